# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The gas between two parallel walls (the case validation/esBGK/channel:
lower wall at y = 0, upper at y = L, periodic in x and z): planar Couette
and Fourier flows, set up on their linear profiles and read back as batch
means (each write averages the steps since the previous one).  Used by
validation/esBGK/test_esBGKChannel.py (the ES-BGK model's viscosity and
conductivity) and bench/tradeoff's denseGas scene (the gas models at long
steps)."""

import math
import os

import numpy as np

from rmf import foam
from rmf.kinetic import K_B

CHANNEL = os.path.join(foam.PROJECT_DIR, "validation", "esBGK", "channel")
GAS = "constant/dsmcProperties"
FILL = "system/dsmcInitialiseDict"
CONTROL = "system/controlDict"


def make(case, L, W, cells, n, T0, simulators, seed, dt, write_steps, writes,
         walls, entries=(), remove=()):
    """The channel in case: L wide, W x W in x and z, `cells` cells across,
    the gas (constant/dsmcProperties's typeIdList, one species) at n and
    T0 with `simulators` simulators per cell, every randomSeed `seed`,
    `writes` writes of write_steps steps of dt; walls = {"lower": (T, U_x),
    "upper": (T, U_x)}; entries: (key, value) of dsmcProperties to set,
    remove: its keys to remove (the case holds every cell in esBGK).  The
    simulators start on the linear profile between the walls' velocities
    and temperatures (a velocity added, thermal speeds scaled, per cell).
    Meshed and filled, not run."""
    case = foam.copy_setup(CHANNEL, case)
    mesh = os.path.join(case, "system", "blockMeshDict")
    for key, value in (("L", f"{L:.9g}"), ("W", f"{W:.9g}"), ("ny", cells)):
        foam.substitute(mesh, rf"\n{key}(\s+)[^;]+;", rf"\n{key}\g<1>{value};")
    foam.set_entry(case, GAS, "nEquivalentParticles", f"{n*W*W*L/(cells*simulators):.9g}")
    for key, value in entries:
        foam.set_entry(case, GAS, key, value)
    for key in remove:
        foam.remove_entry(case, GAS, key)
    species = foam.get_entry(case, GAS, "typeIdList").strip("() ")
    foam.set_entry(case, GAS, "randomSeed", seed)
    foam.set_entry(case, FILL, "randomSeed", seed)
    foam.set_entry(case, FILL, "numberDensities", f"{{ {species} {n:g}; }}")
    foam.set_entry(case, FILL, "temperature", T0)
    foam.set_entry(case, CONTROL, "deltaT", f"{dt:.9g}")
    foam.set_entry(case, CONTROL, "writeInterval", write_steps)
    foam.set_entry(case, CONTROL, "endTime", f"{writes*write_steps*dt:.9g}")
    for patch, (T, U) in walls.items():
        foam.set_entry(case, "0/boundaryT", f"boundaryField/{patch}/value", f"uniform {T:g}")
        foam.set_entry(case, "0/boundaryU", f"boundaryField/{patch}/value",
                       f"uniform ({U:g} 0 0)")
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    path = os.path.join(case, "0", "lagrangian", "dsmc", "U")
    _, cell = foam.read_positions(os.path.join(case, "0", "lagrangian", "dsmc", "positions"),
                                  cells=True)
    U = foam.read_list(path)
    share = (cell + 0.5)/cells
    (T_lo, U_lo), (T_hi, U_hi) = walls["lower"], walls["upper"]
    U *= np.sqrt((T_lo + (T_hi - T_lo)*share)/T0)[:, None]
    U[:, 0] += U_lo + (U_hi - U_lo)*share
    foam.write_list(path, U)
    return case


def slowest_time(L, mu, rho):
    """The decay time L^2/(pi^2 mu/rho) of the channel's slowest velocity
    mode [s]: how long a run takes to its steady state, and a batch to be
    independent of the next."""
    return L**2/(math.pi**2*mu/rho)


def centres(L, cells):
    """The cells' centres across the channel [m]."""
    return (np.arange(cells) + 0.5)*L/cells


def batch_fields(case, time):
    """(number density, velocity (cells, 3), translational T) of the batch
    written at time."""
    def field(name):
        return foam.read_field(os.path.join(case, time, name))
    n, rho = field("rhoNMean"), field("rhoMMean")
    U = field("momentumMean")/rho[:, None]
    T = 2*(field("linearKEMean") - 0.5*rho*(U**2).sum(axis=1))/(3*K_B*n)
    return n, U, T


def wall_load(case, time, name, patch):
    """A wall's load of the batch (fDMean: the force per area the gas
    puts on it, a vector; qMean: the heat flux into it), face mean."""
    return foam.read_patch_field(os.path.join(case, time, name), patch).mean(axis=0)
