# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The particle ES-BGK model of the gas (esBGK, doc/physics.md#es-bgk) in
the one-cell periodic gas box of validation/freeMolecularCoupling
(testing/rmf_box.py, testing/rmf_heatbath.py), the cell held in BGK
(switchAbove far below its collision number).

1. Anisotropy: argon (VHS d 4.17e-10 m, omega 0.81) at 1e20 m^-3 and
   273 K, its velocities scaled about their mean to T_x = 1.4 T, T_y =
   T_z = 0.8 T; the anisotropy A = (T_x - (T_y + T_z)/2)/T decays as
   exp(-p t/mu), mu the VHS viscosity (Chapman-Enskog, first
   approximation: the viscosity ES-BGK is given), at any step: over one
   viscous time mu/p in 5 steps and in one step of 2 mu/p.  The rate
   ln(A_0/A_t)/t against p/mu within N_SIGMA of its thermal noise (A
   fluctuates with variance 3/N, relaxing at the same rate; 200 000
   simulators).

2. Rotation: the nitrogen heat bath of validation/collisionSubSteps
   (1e21 m^-3, 3000 K, rotation cold, no vibration) with Z = 5 at Delta t
   = tau_c/2 and Z = 100 at 10 tau_c: the collision number of the Jeans
   law fitted to the run against Z_c = Z (1 + zeta/(5 - 2 omega)), the
   DSMC exchange's (rmf_heatbath.rotational_Z), within N_SIGMA of the
   fit's noise computed from the thermal fluctuation (rmf_heatbath.
   fit_noise), not from the code.

3. Conservation: in every run, the simulators' total momentum and energy
   (translational and rotational) at every write equal the start's to
   CONSERVATION (round-off of 1e5 terms written with 17 digits).

4. Selection: the same argon box with switchAbove above its collision
   number stays DSMC (esBGK.gas 0, its NTC collisions logged), held in
   BGK it performs none (esBGK.gas 1); exact.

Family-wise error: 2.5e-4 (rmf_testing.MODULE_ALPHA) over m = 4
comparisons (the two anisotropy rates, the two rotations), Bonferroni:
N_SIGMA = z_limit(4) = 4.00; 3 and 4 are exact.  Seeds: every randomSeed
through rmf_testing.seed(1).
"""

import math
import os
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

from rmf import foam
from rmf_box import K, V_CELL, cloud_file
from rmf_heatbath import (CONTROL, SPECIES, bath_state, collision_time, cool, fit_noise,
                          fit_Z, lb_entries, rotational_Z, viscosity)
import rmf_heatbath
import rmf_testing

BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "esBGK")
COMPARISONS = 4
N_SIGMA = rmf_testing.z_limit(COMPARISONS)
HELD = [("esBGK", "{ switchAbove 1e-9; switchBelow 1e-10; }")]
CONSERVATION = 1e-12

N_AR, T_AR = 1e20, 273.0
ANISOTROPY = (1.4, 0.8, 0.8)
SIMULATORS_MU = 200000
# (steps per viscous time mu/p, steps)
MU_STEPS = {"5 steps": (0.2, 5), "1 step": (2.0, 1)}

N_BATH, T_BATH = 1e21, 3000.0
SIMULATORS_BATH, STEPS_BATH = 60000, 60
# (Delta t over tau_c, Z)
BATHS = {"tau_c/2": (0.5, 5.0), "10 tau_c": (10.0, 100.0)}


def make(name, *args, extra=()):
    case = rmf_heatbath.make(os.path.join(BUILD, name), *args, extra=list(extra))
    foam.set_entry(case, CONTROL, "writePrecision", 17)
    return case


def totals(case, time, species):
    """(total momentum / m, total energy [J]) of the simulators."""
    m = SPECIES[species]["mass"]
    U = foam.read_list(cloud_file(case, time, "U"))
    Ei = foam.read_list(cloud_file(case, time, "Ei"))
    return U.sum(axis=0), 0.5*m*(U**2).sum() + Ei.sum()


def anisotropy_run(label):
    per_mu, steps = MU_STEPS[label]
    T = T_AR
    tau_mu = viscosity("Ar", T)/(N_AR*K*T)
    per_tau = per_mu*tau_mu/collision_time("Ar", N_AR, T)
    case = make(f"anisotropy{steps}", "Ar", N_AR, T, per_tau, steps, SIMULATORS_MU, 1,
                extra=HELD)
    path = cloud_file(case, "0", "U")
    U = foam.read_list(path)
    mean = U.mean(axis=0)
    foam.write_list(path, mean + (U - mean)*np.sqrt(ANISOTROPY))
    foam.run(case, "rarefiedMultiphaseFoam")
    return case


def bath_run(label):
    per_tau, Z = BATHS[label]
    case = make(f"bath{Z:g}", "N2", N_BATH, T_BATH, per_tau, STEPS_BATH, SIMULATORS_BATH,
                1, extra=lb_entries(Z) + HELD)
    cool(case, ("Ei",))
    foam.run(case, "rarefiedMultiphaseFoam")
    return case


def selection_run(held):
    extra = HELD if held else [("esBGK", "{ switchAbove 1e9; switchBelow 1e-10; }")]
    case = make(f"selection{int(held)}", "Ar", N_AR, T_AR, 0.5, 4, 5000, 4, extra=extra)
    foam.run(case, "rarefiedMultiphaseFoam")
    return case


@pytest.fixture(scope="module")
def runs():
    jobs = ([(anisotropy_run, k) for k in MU_STEPS] + [(bath_run, k) for k in BATHS]
            + [(selection_run, True), (selection_run, False)])
    with ThreadPoolExecutor(2) as pool:
        cases = list(pool.map(lambda job: job[0](job[1]), jobs))
    n = len(MU_STEPS)
    return {"anisotropy": dict(zip(MU_STEPS, cases[:n])),
            "bath": dict(zip(BATHS, cases[n:n + len(BATHS)])),
            "held": cases[-2], "dsmc": cases[-1]}


def anisotropy(U):
    var = U.var(axis=0)
    return (var[0] - 0.5*(var[1] + var[2]))/var.mean()


@pytest.mark.parametrize("label", MU_STEPS)
def test_anisotropy(runs, label):
    """The decay rate of A against p/mu (module docstring, 1)."""
    case = runs["anisotropy"][label]
    first, last = foam.times(case)[0], foam.times(case)[-1]
    U0 = foam.read_list(cloud_file(case, first, "U"))
    U1 = foam.read_list(cloud_file(case, last, "U"))
    m = SPECIES["Ar"]["mass"]
    T = m*U0.var(axis=0).sum()/(3*K)
    a0, a1, t = anisotropy(U0), anisotropy(U1), float(last) - float(first)
    rate = math.log(a0/a1)/t
    expected = N_AR*K*T/viscosity("Ar", T)
    sigma = math.sqrt(3/SIMULATORS_MU*(1 - (a1/a0)**2))/a1/t
    ok = abs(rate - expected) <= N_SIGMA*sigma
    print(f"\n{'PASS' if ok else 'FAIL'} ES-BGK anisotropy, one viscous time in {label}: "
          f"A {a0:.4f} -> {a1:.4f}, rate over p/mu {rate/expected:.4f} (limit 1 +- "
          f"{N_SIGMA:.2f} x {sigma/expected:.4f}, thermal noise)")
    assert ok


@pytest.mark.parametrize("label", BATHS)
def test_rotation(runs, label):
    """The Jeans collision number fitted to the bath against the DSMC
    exchange's Z_c (module docstring, 2)."""
    case = runs["bath"][label]
    rows = [(float(time),) + bath_state(case, time) for time in foam.times(case)]
    t, T_tr, e_rot, _ = np.array(rows).T
    Z = rotational_Z(BATHS[label][1])
    fitted = fit_Z("rotation", t, T_tr, e_rot, N_BATH)
    sd = fit_noise("rotation", t, T_tr, e_rot, Z, N_BATH, SIMULATORS_BATH)
    ok = abs(fitted - Z) <= N_SIGMA*sd
    print(f"\n{'PASS' if ok else 'FAIL'} ES-BGK rotation at Delta t = {label}: fitted "
          f"collision number {fitted:.2f}, DSMC's Z_c {Z:.2f} ({100*(fitted/Z - 1):+.2f} %; "
          f"limit {N_SIGMA:.2f} x {sd:.3f} (computed noise) = {100*N_SIGMA*sd/Z:.2f} %)")
    assert ok


def test_conservation(runs):
    """Momentum and energy of every run at every write against the start
    (module docstring, 3)."""
    cases = [(c, "Ar") for c in runs["anisotropy"].values()] + \
            [(c, "N2") for c in runs["bath"].values()] + [(runs["held"], "Ar")]
    worst_p, worst_e = 0.0, 0.0
    for case, species in cases:
        times = foam.times(case)
        p0, e0 = totals(case, times[0], species)
        U0 = foam.read_list(cloud_file(case, times[0], "U"))
        scale = np.abs(U0).sum()
        for time in times[1:]:
            p, e = totals(case, time, species)
            worst_p = max(worst_p, np.abs(p - p0).max()/scale)
            worst_e = max(worst_e, abs(e/e0 - 1))
    ok = worst_p <= CONSERVATION and worst_e <= CONSERVATION
    print(f"\n{'PASS' if ok else 'FAIL'} ES-BGK conservation over {len(cases)} runs: "
          f"momentum {worst_p:.1e} (of sum |c|), energy {worst_e:.1e} (limit "
          f"{CONSERVATION:g})")
    assert ok


def test_selection(runs):
    """Held in BGK: no NTC collisions, esBGK.gas 1; thresholds above the
    cell's collision number: DSMC, esBGK.gas 0 (module docstring, 4)."""
    def share(case):
        return float(foam.read_field(os.path.join(case, foam.times(case)[-1], "esBGK.gas"),
                                     1)[0])

    def collisions(case):
        found = foam.log_values(os.path.join(case, "log.rarefiedMultiphaseFoam"),
                                "Collisions")
        return found[:, 0].sum() if len(found) else 0.0

    held, dsmc = runs["held"], runs["dsmc"]
    ok = (share(held) == 1 and collisions(held) == 0 and share(dsmc) == 0
          and collisions(dsmc) > 0)
    print(f"\n{'PASS' if ok else 'FAIL'} ES-BGK selection: held in BGK share "
          f"{share(held):g}, NTC collisions {collisions(held):g}; above its threshold "
          f"share {share(dsmc):g}, NTC collisions {collisions(dsmc):g}")
    assert ok
