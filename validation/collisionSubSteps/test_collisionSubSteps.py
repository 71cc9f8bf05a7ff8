# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""NTC collisions with bound majorants, sub-stepped per cell
(collisionSubSteps, doc/physics.md#collision-sub-steps), in the one-cell
periodic gas box of validation/freeMolecularCoupling (testing/rmf_box.py)
at steps of 10 and 50 mean collision times (STEPS_PER_TAU).

1. Collision rate: argon (VHS, omega 0.81) at 1e20 m^-3 and 273 K in
   equilibrium, 5000 simulators, 40 steps: the collisions per step
   against the VHS rate within t_9 standard errors (ten batch means of
   the log's counts).  Measured 2026-12-07: +0.11 % (limit 0.43 %) at 10
   tau_c and +0.02 % (limit 0.22 %) at 50 tau_c.  Upstream's majorant at
   these steps (no collisionSubSteps, the same start): -0.9 % at both,
   its first steps short of collisions (not a comparison here).

2. Relaxation: the nitrogen heat bath of validation/vibrationalRelaxation
   (1e21 m^-3, 3000 K) with rotation and vibration both cold at the
   start, Z_rot = Z_v = 10 Delta t/tau_c so that each relaxes over about
   ten steps at either Delta t; every step written.  Each mode's
   collision number fitted to the run by its relaxation law (Jeans,
   Landau-Teller) integrated with the run's T_tr, against the analytic
   one: Z_v for the vibration, Z_rot (1 + zeta/(5 - 2 omega)) for the
   rotation (rotational_Z; a resolved run, Delta t = tau_c/2, Z = 20
   without sub-steps, fitted 32.7 against 31.4).  Tolerance: N_SIGMA of
   the fit's noise computed from the thermal fluctuation of the mean
   energy (fit_noise), not from the code.

3. The bound: no candidate above its majorant in any sub-stepped run,
   including two argon beams crossing at 4000 m/s (12 c_mp), exact
   (the log's count is 0); the same beams with upstream's majorant are
   printed as the control (3 cell-steps, acceptance up to 4.3, measured
   2026-12-07).

Bad input (collisionSubSteps' keywords, barycentric tracking, a model
without the VHS cross-section) is in validation/gasInputErrors.

Family-wise error: 2.5e-4 (rmf_testing.MODULE_ALPHA) over m = 6
comparisons (the rate at two steps, two modes at two steps), Bonferroni:
N_SIGMA = z_limit(6) = 4.10 and t_limit(9, 6) = 7.39; 3 is exact.
Seeds: every randomSeed through rmf_testing.seed(1).
"""

import math
import os
import re
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

from rmf import foam
from rmf_box import K, V_CELL, cloud_file
from rmf_heatbath import (CONTROL, SPECIES, T_REF, bath_state, cool, fit_noise, fit_Z,
                          lb_entries, rotational_Z)
import rmf_heatbath
import rmf_testing

BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "collisionSubSteps")
SUB_STEPS = [("collisionSubSteps", "{ collisionsPerSubStep 1; maxSubSteps 64; }")]
STEPS_PER_TAU = (10, 50)                # Delta t over the mean collision time
COMPARISONS = 6                         # module docstring
N_SIGMA = rmf_testing.z_limit(COMPARISONS)

# 1. the collision rate: argon at 273 K
N_AR, T_AR = 1e20, 273.0
SIMULATORS_RATE, STEPS_RATE, BATCHES = 5000, 40, 10
# 2. the heat bath: nitrogen at 3000 K, rotation and vibration cold
N_BATH, T_BATH = 1e21, 3000.0
SIMULATORS_BATH, STEPS_BATH = 60000, 60
RELAXATION_STEPS = 10                   # Z tau_c over Delta t (the input Z's)
# 3. the bound: argon beams at +-BEAM along x
BEAM, STEPS_BEAM = 2000.0, 10           # [m/s]: 6 c_mp


def log_lines(case, pattern):
    """The groups of pattern on each matching line of the solver's log."""
    with open(os.path.join(case, "log.rarefiedMultiphaseFoam")) as f:
        return [m.groups() for m in re.finditer(pattern, f.read())]


EXCEEDED = r"\(sigma c_r\)_max was exceeded (\S+), largest acceptance probability (\S+)"
SUB_STEPPED = (r"sub-steps since the last write: (\S+) cell-steps in more than one "
             r"\(largest (\d+)\), capped (\S+); acceptance of the bound (\S+)")


def make(name, *args, sub_steps=True, extra=()):
    """rmf_heatbath.make in BUILD/name, with collisionSubSteps unless
    sub_steps is false."""
    return rmf_heatbath.make(os.path.join(BUILD, name), *args,
                             extra=(SUB_STEPS if sub_steps else []) + list(extra))


def rate_run(per_tau):
    case = make(f"rate{per_tau}", "Ar", N_AR, T_AR, per_tau, STEPS_RATE, SIMULATORS_RATE,
                STEPS_RATE)
    foam.run(case, "rarefiedMultiphaseFoam")
    return case


def bath_run(per_tau):
    case = make(f"bath{per_tau}", "N2", N_BATH, T_BATH, per_tau, STEPS_BATH,
                SIMULATORS_BATH, 1,
                extra=lb_entries(RELAXATION_STEPS*per_tau, vibration=True))
    cool(case, ("vibLevel0", "Ei"))
    foam.run(case, "rarefiedMultiphaseFoam")
    return case


def beam_run(sub_steps):
    case = make(f"beams{int(sub_steps)}", "Ar", N_AR, T_AR, STEPS_PER_TAU[0], STEPS_BEAM,
                SIMULATORS_RATE, 1, sub_steps=sub_steps)
    path = cloud_file(case, "0", "U")
    U = foam.read_list(path)
    U[:, 0] += np.where(np.arange(len(U)) % 2, BEAM, -BEAM)
    foam.write_list(path, U)
    foam.run(case, "rarefiedMultiphaseFoam")
    return case


@pytest.fixture(scope="module")
def runs():
    jobs = ([(rate_run, k) for k in STEPS_PER_TAU] + [(bath_run, k) for k in STEPS_PER_TAU]
            + [(beam_run, True), (beam_run, False)])
    with ThreadPoolExecutor(2) as pool:
        cases = list(pool.map(lambda job: job[0](job[1]), jobs))
    return {"rate": dict(zip(STEPS_PER_TAU, cases[0:2])),
            "bath": dict(zip(STEPS_PER_TAU, cases[2:4])),
            "beams": cases[4], "beamsPlain": cases[5]}


@pytest.mark.parametrize("per_tau", STEPS_PER_TAU)
def test_collision_rate(runs, per_tau):
    """Collisions per step against the VHS rate N (N - 1)/2 W <sigma_T
    c_r> dt/V, <sigma_T c_r> = 4 d^2 (pi k T_ref/m)^(1/2) (T/T_ref)^(1 -
    omega) (Bird 1994 eq. 4.64 over n) at the simulators' T (exactly kept:
    argon has no internal energy); tolerance t_limit standard errors of
    the mean count from BATCHES batch means of the log's counts."""
    case = runs["rate"][per_tau]
    log = os.path.join(case, "log.rarefiedMultiphaseFoam")
    counts = foam.log_values(log, "Collisions")[:, 0]
    n = foam.log_values(log, "Simulators present")[0, 0]
    s = SPECIES["Ar"]
    U = foam.read_list(cloud_file(case, "0", "U"))
    T = s["mass"]*U.var(axis=0).sum()/(3*K)
    dt = float(foam.get_entry(case, CONTROL, "deltaT"))
    W = N_AR*V_CELL/SIMULATORS_RATE
    sigma_cr = 4*s["d"]**2*math.sqrt(math.pi*K*T_REF/s["mass"])*(T/T_REF)**(1 - s["omega"])
    expected = 0.5*n*(n - 1)*W*sigma_cr*dt/V_CELL
    batches = counts.reshape(BATCHES, -1).mean(axis=1)
    se = batches.std(ddof=1)/math.sqrt(BATCHES)
    limit = rmf_testing.t_limit(BATCHES - 1, COMPARISONS)
    steps = log_lines(case, SUB_STEPPED)[-1]
    ok = abs(counts.mean() - expected) <= limit*se
    print(f"\n{'PASS' if ok else 'FAIL'} collision rate at Delta t = {per_tau} tau_c: "
          f"{counts.mean():.1f} per step, VHS {expected:.1f} "
          f"({100*(counts.mean()/expected - 1):+.3f} %; t_{BATCHES - 1} {limit:.2f} se = "
          f"{100*limit*se/expected:.3f} %); sub-steps up to {steps[1]}, acceptance of "
          f"the bound {float(steps[3]):.3f}")
    assert ok


@pytest.mark.parametrize("per_tau", STEPS_PER_TAU)
@pytest.mark.parametrize("mode", ["rotation", "vibration"])
def test_relaxation(runs, mode, per_tau):
    """The mode's collision number fitted to the run (the law integrated
    with its T_tr(t), every step written) against the analytic one:
    rotational_Z(Z) for rotation, Z for vibration (the quantum Larsen-
    Borgnakke exchange of validation/vibrationalRelaxation), within
    N_SIGMA of fit_noise.  Z = RELAXATION_STEPS Delta t/tau_c: the mode
    relaxes over about ten steps at either Delta t."""
    case = runs["bath"][per_tau]
    rows = [(float(time),) + bath_state(case, time) for time in foam.times(case)]
    t, T_tr, e_rot, e_vib = np.array(rows).T
    e = e_rot if mode == "rotation" else e_vib
    Z_in = RELAXATION_STEPS*per_tau
    Z = rotational_Z(Z_in) if mode == "rotation" else Z_in
    fitted = fit_Z(mode, t, T_tr, e, N_BATH)
    sd = fit_noise(mode, t, T_tr, e, Z, N_BATH, SIMULATORS_BATH)
    ok = abs(fitted - Z) <= N_SIGMA*sd
    print(f"\n{'PASS' if ok else 'FAIL'} {mode} at Delta t = {per_tau} tau_c: fitted "
          f"collision number {fitted:.1f}, analytic {Z:.1f} ({100*(fitted/Z - 1):+.2f} %; "
          f"limit {N_SIGMA:.2f} x {sd:.2f} (computed noise) = "
          f"{100*N_SIGMA*sd/Z:.2f} %)")
    assert ok


def test_bound_holds(runs):
    """No candidate above the bound in any sub-stepped run (exact: the
    log's count of cell-steps whose candidates exceeded their majorant
    is 0 at every write), in equilibrium, in the heat baths and with two
    argon beams crossing at 2 BEAM, whose first step upstream's majorant
    (a thermal gas's) cannot hold: that control's count is printed."""
    sub_stepped = (list(runs["rate"].values()) + list(runs["bath"].values())
                   + [runs["beams"]])
    worst = max(float(n) for case in sub_stepped for n, _ in log_lines(case, EXCEEDED))
    plain = log_lines(runs["beamsPlain"], EXCEEDED)
    ok = worst == 0
    print(f"\n{'PASS' if ok else 'FAIL'} bound majorants: cell-steps with a candidate "
          f"above the bound {worst:g} over {len(sub_stepped)} runs; control (upstream's "
          f"majorant, beams): {sum(float(n) for n, _ in plain):g} cell-steps exceeded, "
          f"largest acceptance probability {max(float(p) for _, p in plain):.2f}")
    assert ok
