# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The one-cell periodic gas box of validation/freeMolecularCoupling/box,
shared by the coupling tests (test support: on sys.path through the
top-level conftest.py).

One hexahedral cell (0.1 x 0.08 x 0.08 m), cyclic in every direction: the
gas neither gains nor loses simulators, momentum or energy by itself.
Its gas species (argon and nitrogen) are those of box/constant/
dsmcProperties; the initial fields come from upstream's periodic dsmcFoam
tutorial (same patch names).
"""

import os
import shutil

from rmf import foam
from rmf_testing import seed

BOX = os.path.join(foam.PROJECT_DIR, "validation", "freeMolecularCoupling", "box")
PROPS = "constant/grainsProperties"
GAS = "constant/dsmcProperties"
FILL = "system/dsmcInitialiseDict"
GRAINS = "system/grainsInitialiseDict"
CONTROL = "system/controlDict"

K = 1.380649e-23                            # Boltzmann [J/K]
MASS = {"Ar": 66.3e-27, "N2": 46.5e-27}     # as box/constant/dsmcProperties
ZETA = {"Ar": 0, "N2": 2}                   # internal degrees of freedom
V_CELL = 0.1*0.08*0.08                      # [m^3]


def copy_box(dst, species="Ar", n_gas=1e20, eps=0.0, alpha=1.0, coupling="oneWay"):
    """Fresh set-up of the box in dst (not meshed or filled): one gas
    species at number density n_gas, the grains' specular fraction eps,
    thermal accommodation alpha and interphaseCoupling.  The box's
    randomSeeds (the gas's, the gas's and the grains' fills) are set to
    rmf_testing.seed(1), so that a seed set changes them."""
    case = foam.copy_setup(BOX, dst)
    shutil.rmtree(os.path.join(case, "0"))
    shutil.copytree(os.path.join(foam.dsmc_tutorial("freeSpacePeriodic"), "0"),
                    os.path.join(case, "0"))
    if species != "Ar":
        foam.set_entry(case, GAS, "typeIdList", f"({species})")
        foam.remove_entry(case, FILL, "numberDensities/Ar")
    foam.set_entry(case, FILL, f"numberDensities/{species}", f"{n_gas:g}")
    foam.set_entry(case, PROPS, "constantProperties/specularFraction", eps)
    foam.set_entry(case, PROPS, "constantProperties/thermalAccommodation", alpha)
    foam.set_entry(case, PROPS, "subModels/interphaseCoupling", coupling)
    for path in (GAS, FILL, GRAINS):
        foam.set_entry(case, path, "randomSeed", seed(1))
    return case


def cloud_file(case, time, name):
    """Path of the gas simulators' field name (U, Ei, typeId, vibLevel0,
    ...) at a written time."""
    return os.path.join(case, time, "lagrangian", "dsmc", name)
