# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Our restartableStochastic isotropy against upstream's stochastic
(doc/physics.md#mppic): the same model, Gaussians drawn differently.

The periodic granular box of validation/grainCollisions (20 000 parcels of
1 mm, alpha 0.0105, basic averaging) with two opposing streams,
U0 = (+-1 0 0) and sigmaU 0.1, so that nearly all the fluctuation energy
is in x; only the isotropy model acts (no collisions, packing or
damping; isotropic time scale, alpha_cp 0.6, e 0.85).  The isotropy
redraws a fraction 1 - exp(-dt/tau_c) of the parcels per step in every
direction alike: the x share of the fluctuation energy,

    f_x = sum (v_x - <v_x>)^2 / sum |v - <v>|^2,

falls from about 1 towards 1/3 over a few tau_c (about 20 ms here).
Run with each model for 60 steps of 1 ms, written every 10 steps.
Checks:
1. at every written time after the start (10 to 60 ms) the two models'
   f_x agree within Z standard errors of their difference.  The standard
   error of each f_x is estimated from the parcels themselves (the spread
   of the per-parcel terms v_x'^2 - f_x |v'|^2 over the N parcels,
   independent of the model code); the runs draw from different numbers,
   so the errors add in quadrature (conservative: both runs start from the
   same parcels, which correlates their f_x).  The start itself is not
   compared: both runs begin from the initialiser's identical parcels
   (same seed, no model acted yet), so their f_x agree there by
   construction;
2. both relax: f_x falls at every write (from 0.98 at the start; 0.53 at
   60 ms measured), and the total fluctuation energy is kept within 1 %
   (the model's second step restores the cells' mean square; 1 %: the
   averaging's interpolation to the parcels does not conserve it
   exactly).  The rate is not compared with a closed form: tau_c comes
   from the averaged collision frequency, which changes as the
   distribution does (from the initial state one estimates about 22 ms;
   the fall of f_x - 1/3 measured corresponds to about 50 ms).

Family-wise error: 2.5e-4 (rmf_testing.MODULE_ALPHA) over the m = 6
comparisons of 1. (Bonferroni, Z = rmf_testing.z_limit(6) = 4.1 each);
the checks of 2. are bounds of the model, not of noise (f_x falls by at
least 0.04 per write, 12 times its standard error of 0.0033; measured
2026-12-06: differences within 0.9 standard errors).  Seeds:
initialiser rmf_testing.seed(1), cloud (both models' draws) seed(0).
"""

import os

import numpy as np
import pytest

from rmf import foam
from rmf_testing import seed, z_limit

ROOT = foam.PROJECT_DIR
BOX = os.path.join(ROOT, "validation", "grainCollisions", "granularGas")
BUILD = os.path.join(ROOT, "build", "validation", "isotropyModels")
PROPS = "constant/grainsProperties"
DT, STEPS, EVERY = 1e-3, 60, 10
WRITES = STEPS//EVERY             # compared: every write after the start
N_SIGMA = z_limit(WRITES)
TIME_SCALE = "{ timeScaleModel { type isotropic; alphaPacked 0.6; e 0.85; } }"
STREAMS = ("{ plus { type box; min (0 0 0); max (0.1 0.1 0.1); d 1e-3;"
           " nParcels 10000; nParticle 1; U0 (1 0 0); sigmaU 0.1; }"
           " minus { type box; min (0 0 0); max (0.1 0.1 0.1); d 1e-3;"
           " nParcels 10000; nParticle 1; U0 (-1 0 0); sigmaU 0.1; } }")


def run(model):
    case = foam.copy_setup(BOX, os.path.join(BUILD, model))
    for entry, value in [("subModels/stochasticCollisionModel", "none"),
                         ("subModels/isotropyModel", model),
                         (f"subModels/{model}Coeffs", TIME_SCALE),
                         ("randomSeed", seed(0))]:
        foam.set_entry(case, PROPS, entry, value)
    foam.set_entry(case, "system/grainsInitialiseDict", "regions", STREAMS)
    foam.set_entry(case, "system/grainsInitialiseDict", "randomSeed", seed(1))
    foam.set_entry(case, "system/controlDict", "deltaT", DT)
    foam.set_entry(case, "system/controlDict", "endTime", f"{STEPS*DT:.6g}")
    foam.set_entry(case, "system/controlDict", "writeControl", "timeStep")
    foam.set_entry(case, "system/controlDict", "writeInterval", EVERY)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    foam.run(case, "rarefiedMultiphaseFoam")
    return case


def share(case, t):
    """(f_x, its standard error, total fluctuation energy per parcel)."""
    U = foam.read_list(os.path.join(case, t, "lagrangian", "grains", "U"))
    u = U - U.mean(axis=0)
    e = (u**2).sum(axis=1)
    f = (u[:, 0]**2).sum()/e.sum()
    terms = u[:, 0]**2 - f*e
    se = terms.std(ddof=1)/np.sqrt(len(e))/e.mean()
    return f, se, e.mean()


@pytest.fixture(scope="module")
def runs():
    return {model: run(model) for model in ("stochastic", "restartableStochastic")}


def test_same_relaxation(runs):
    ours, theirs = runs["restartableStochastic"], runs["stochastic"]
    ok = True
    print()
    times = foam.times(ours)[1:]
    assert len(times) == WRITES, times
    for t in times:
        fo, so, _ = share(ours, t)
        fu, su, _ = share(theirs, t)
        z = (fo - fu)/max(np.hypot(so, su), 1e-12)
        good = abs(z) < N_SIGMA
        ok = ok and good
        print(f"{'PASS' if good else 'FAIL'} t = {t}: f_x ours {fo:.4f} +- {so:.4f},"
              f" upstream {fu:.4f} +- {su:.4f}, difference {z:+.2f} sigma (tol {N_SIGMA:.2f})")
    assert ok


def test_relaxes_and_keeps_energy(runs):
    ok = True
    for model, case in runs.items():
        f = [share(case, t)[0] for t in foam.times(case)]
        _, _, e0 = share(case, "0")
        _, _, e1 = share(case, foam.latest_time(case))
        good = f[0] > 0.95 and all(b < a for a, b in zip(f, f[1:])) \
            and abs(e1/e0 - 1) < 0.01
        ok = ok and good
        print(f"{'PASS' if good else 'FAIL'} {model}: f_x "
              + " ".join(f"{x:.3f}" for x in f)
              + f" (falling), fluctuation energy ratio {e1/e0:.4f} (tol 1 %)")
    assert ok
