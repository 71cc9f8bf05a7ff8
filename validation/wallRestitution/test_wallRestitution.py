# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The stability matrix's wall restitution at its extremes, e = 1 and
e = 0 (doc/speed-accuracy.md, "Stability at the extremes"; the rebound of
doc/physics.md#grain-walls), end to end on the solver.

Case: the Snider tutorial's closed box (0.138 x 0.138 x 0.3 m, 15 x 15 x
40 cells, walls on every side) in vacuum with 2000 parcels dropped from
rest, spread over the whole box, under gravity alone: no packing,
damping, isotropy or grain collisions, so that each parcel is a ball
bouncing on the floor and nothing else.  mu = 0; dt = 1 ms; 0.6 s (a
parcel from the top reaches the floor at 0.247 s), written every 0.05 s.

e = 1, expected: every parcel keeps its mechanical energy
E = |U|^2/2 - g.x per unit mass, up to the explicit time integration.
Each step sets U_{n+1} = U_n + g dt and moves the parcel by some
displacement between U_n dt and U_{n+1} dt, U_n dt + c g dt^2 with
0 <= c <= 1 (upstream's tracking sets c; measured here 0.36), so each
step changes E by g^2 dt^2 (1/2 - c), at most g^2 dt^2/2 either way, and
a rebound changes nothing (|U| is kept; a step split by a hit obeys the
same bound piecewise).  So at every write every parcel has
|E - E_0| <= g^2 dt t/2 (0.0288 J/kg at 0.6 s, 1 % of the drop from the
top) plus 1e-6 J/kg (the write precision of 8 digits on E ~ 3 J/kg).  A
parcel that went through the floor would be lost or outside the box, and
one reflected twice gains 2 |U| g dt per extra hit.  The spread of
E - E_0 over the parcels (bounced 0 to ~60 times) is printed.

e = 0, expected: every parcel comes to rest on the floor.  From 0.3 m
the fall takes 0.247 s; after it the normal velocity is removed at every
hit, and gravity gives back g dt per step: at 0.6 s every parcel's
vertical velocity is at most g dt, its height above the floor (z = 0)
at most g dt^2, and its horizontal velocity 0 (mu = 0 keeps the
tangential velocity, and a parcel dropped from rest has none).
Both: the 2000 parcels all in the domain at every write (none escaped:
the account is empty), and no NaN in any parcel field.
Deterministic: no statistical comparison (the bounds hold for every
parcel wherever the initialiser placed it).
"""

import math
import os

import numpy as np
import pytest

from rmf import foam
from rmf_testing import report, set_in_list

TUTORIAL = os.path.join(foam.PROJECT_DIR, "tutorials", "solids", "sniderSedimentation")
BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "wallRestitution")
PROPS = "constant/grainsProperties"
INIT = "system/grainsInitialiseDict"
N_PARCELS = 2000
G, DT, END = 9.8, 1e-3, 0.6        # constant/g of the tutorial


def make_case(e):
    case = foam.copy_setup(TUTORIAL, os.path.join(BUILD, f"e{e:g}"))
    foam.set_entry(case, INIT, "regions/column/nParcels", N_PARCELS)
    for model in ("packingModel", "dampingModel", "isotropyModel",
                  "stochasticCollisionModel"):
        foam.set_entry(case, PROPS, f"subModels/{model}", "none")
    for patch in ("sides", "bottom", "top"):
        set_in_list(os.path.join(case, PROPS), "patches", patch, "e", e)
        set_in_list(os.path.join(case, PROPS), "patches", patch, "mu", 0)
    foam.set_entry(case, "system/controlDict", "endTime", END)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    foam.run(case, "rarefiedMultiphaseFoam")
    return case


def parcels(case, time):
    """Positions and velocities at time, in the order of the parcels'
    identities (origId; one processor): the cloud re-orders its parcels
    by cell (doc/physics.md#memory-order), so a parcel's place in the list
    changes
    from one write to the next."""
    path = os.path.join(case, time, "lagrangian", "grains")
    x = foam.read_positions(os.path.join(path, "positions"))
    U = foam.read_list(os.path.join(path, "U"))
    order = np.argsort(foam.read_list(os.path.join(path, "origId")), kind="stable")
    return x[order], U[order]


def check_common(case, name):
    """Every parcel present and finite at every write; returns the
    written times."""
    times = foam.times(case)
    ok = True
    for t in times:
        x, U = parcels(case, t)
        ok &= len(x) == N_PARCELS and np.all(np.isfinite(x)) and np.all(np.isfinite(U))
    log = open(os.path.join(case, "log.rarefiedMultiphaseFoam")).read()
    ok &= "nan" not in log.lower()
    assert report(f"{name}: {N_PARCELS} parcels finite at every write", ok,
                  f"{len(times)} writes")
    return times


def test_elastic_walls():
    case = make_case(1)
    times = check_common(case, "e = 1")
    x0, U0 = parcels(case, times[0])
    E0 = 0.5*np.sum(U0**2, axis=1) + G*x0[:, 2]
    worst, spread = 0.0, 0.0
    for t in times[1:]:
        x, U = parcels(case, t)
        dE = 0.5*np.sum(U**2, axis=1) + G*x[:, 2] - E0
        bound = 0.5*G*G*DT*float(t) + 1e-6
        worst = max(worst, float(np.max(np.abs(dE)))/bound)
        spread = max(spread, float(np.ptp(dE))/bound)
    assert report("e = 1: mechanical energy within the explicit step's drift g^2 dt t/2",
                  worst <= 1, f"largest |E - E_0| {worst:.3f} of the bound; spread over "
                  f"the parcels {spread:.4f} of it")


def test_inelastic_walls():
    case = make_case(0)
    check_common(case, "e = 0")
    x, U = parcels(case, foam.latest_time(case))
    height = float(np.max(x[:, 2]))
    uz = float(np.max(np.abs(U[:, 2])))
    uxy = float(np.max(np.abs(U[:, :2])))
    ok = height <= G*DT*DT + 1e-9 and uz <= G*DT*(1 + 1e-6) and uxy == 0
    assert report("e = 0: every parcel at rest on the floor at 0.6 s", ok,
                  f"highest {height:.3g} m (bound g dt^2 = {G*DT*DT:.3g}), largest |U_z| "
                  f"{uz:.3g} m/s (g dt = {G*DT:.3g}), largest horizontal {uxy:.3g} m/s")
