# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""With gas present, the grains' carrier fields come from the gas: tutorials/gas/impingingStream with a cloud of resting grains (no
forces, every MPPIC model off), 5 steps.  Expected:
- the gas mass the grains see is the gas's own: sum(rho.gas V) equals
  nEquivalentParticles x simulators x m(N2) of the written dsmc cloud
  (same step; tolerance 1e-6 relative: the files' 8 significant digits),
- mu.gas follows the VHS law, mu = mu_ref (T/Tref)^omega with T = T.gas,
  and mu_ref(273 K) = 1.656e-5 Pa s, Bird's (1994, table A.1) viscosity of
  N2 for d = 4.17e-10 m, omega = 0.74 (tolerance 0.5%: the table's
  rounding of d),
- rho.gas, T.gas and mu.gas finite in every cell, T.gas > 0 in more than
  90 % of the cells (the law is checked there), and mu.gas zero where
  T.gas is zero (a cell with fewer than two simulators, whose velocities
  have no spread: one cell of 3200 here).  No cell is empty at the 5th
  step, so zero fields of empty cells are not checked here (the sparse
  gas of validation/sparseGas has them)."""

import os
import shutil

import numpy as np

from rmf import foam

GAS = os.path.join(foam.PROJECT_DIR, "tutorials", "gas", "impingingStream")
SNIDER = os.path.join(foam.PROJECT_DIR, "tutorials", "solids", "sniderSedimentation")
BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "gasCarrier")
PROPS = "constant/grainsProperties"
M_N2, W, TREF, OMEGA = 46.5e-27, 6e11, 273.0, 0.74
MU_REF_BIRD = 1.656e-5


def test_carrier_fields_from_gas():
    case = foam.copy_setup(GAS, BUILD)
    shutil.copy(os.path.join(SNIDER, PROPS), os.path.join(case, PROPS))
    shutil.copy(os.path.join(SNIDER, "constant", "g"), os.path.join(case, "constant"))
    init = os.path.join(case, "system", "grainsInitialiseDict")
    shutil.copy(os.path.join(SNIDER, "system", "grainsInitialiseDict"), init)
    foam.set_entry(case, "system/grainsInitialiseDict", "regions/column/min", "(-0.1 0.05 0)")
    foam.set_entry(case, "system/grainsInitialiseDict", "regions/column/max",
                   "(0.1 0.1 0.005)")
    foam.set_entry(case, "system/grainsInitialiseDict", "regions/column/nParcels", 100)
    for model in ("packingModel", "dampingModel", "isotropyModel"):
        foam.set_entry(case, PROPS, "subModels/" + model, "none")
    foam.set_entry(case, PROPS, "subModels/patchInteractionModel", "none")
    # Required with gas present; none keeps the grains at rest
    foam.set_entry(case, PROPS, "subModels/interphaseCoupling", "none")
    foam.set_steps(case, 5)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    foam.run(case, "rarefiedMultiphaseFoam")

    t = foam.latest_time(case)
    rho = foam.read_field(os.path.join(case, t, "rho.gas"))
    T = foam.read_field(os.path.join(case, t, "T.gas"))
    mu = foam.read_field(os.path.join(case, t, "mu.gas"))
    assert np.isfinite(rho).all() and np.isfinite(T).all() and np.isfinite(mu).all()

    V = 0.4*0.2*0.005/len(rho)                  # uniform 80 x 40 mesh
    n_sim = len(foam.read_list(os.path.join(case, t, "lagrangian", "dsmc", "typeId")))
    gas_mass = W*n_sim*M_N2
    assert abs(rho.sum()*V/gas_mass - 1) < 1e-6, (rho.sum()*V, gas_mass)

    hot = T > 0
    assert hot.sum() > 0.9*len(T)
    mu_ref = mu[hot]/(T[hot]/TREF)**OMEGA
    assert np.allclose(mu_ref, mu_ref.mean(), rtol=1e-6)
    assert abs(mu_ref.mean()/MU_REF_BIRD - 1) < 5e-3, mu_ref.mean()
    assert np.all(mu[~hot] == 0)
