# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Gas relaxation in the one-cell periodic box (testing/rmf_box.py), shared
by the tests of the gas's collision models at long steps
(validation/collisionSubSteps, validation/esBGK): the box set up at a
number density, temperature and step in mean collision times; the VHS
mean collision time and viscosity; the relaxation laws of rotation
(Jeans) and vibration (Landau-Teller) integrated with a run's T_tr(t),
the collision number fitted to a run and the fit's noise computed from
the thermal fluctuation alone (test support: on sys.path through the
top-level conftest.py)."""

import math
import os

import numpy as np
from scipy import integrate, optimize

from rmf import foam
from rmf.kinetic import vhs_collision_time, vhs_viscosity
from rmf_box import FILL, GAS, K, MASS, V_CELL, cloud_file, copy_box
from rmf_testing import seed

CONTROL = "system/controlDict"
T_REF = 273.0
SPECIES = {"Ar": dict(mass=MASS["Ar"], d=4.17e-10, omega=0.81, zeta=0),
           "N2": dict(mass=MASS["N2"], d=4.17e-10, omega=0.74, zeta=2,
                      theta=3371.0)}
LB_MODEL = "LarsenBorgnakkeVariableSoftSphere"


def viscosity(species, T):
    """VHS viscosity at T, Chapman-Enskog first approximation (Bird 1994
    eq. 4.62)."""
    s = SPECIES[species]
    return vhs_viscosity(T, s["mass"], s["d"], s["omega"], T_REF)


def lb_entries(Z, vibration=False):
    """constant/dsmcProperties entries: Larsen-Borgnakke (VSS of alpha 1)
    for nitrogen with relaxation collision number Z (and its vibration at
    Z_v = Z)."""
    entries = [("BinaryCollisionModel", LB_MODEL),
               (f"{LB_MODEL}Coeffs", f"{{ Tref {T_REF:g}; alpha {{ N2 1; }}"
                                     f" relaxationCollisionNumber {Z:g}; }}")]
    if vibration:
        entries += [("moleculeProperties/N2/vibrationalModes",
                     f"{{ stretch {{ temperature {SPECIES['N2']['theta']:g}; }} }}"),
                    ("moleculeProperties/N2/vibrationalRelaxationCollisionNumber", Z)]
    return entries


def cool(case, names):
    """Set the simulators' fields names (Ei, vibLevel0) to 0 at time 0."""
    for name in names:
        path = cloud_file(case, "0", name)
        foam.write_list(path, np.zeros_like(foam.read_list(path)))


def collision_time(species, n, T):
    """VHS mean collision time at n and T (Bird 1994 eq. 4.64) [s]."""
    s = SPECIES[species]
    return vhs_collision_time(n, T, s["mass"], s["d"], s["omega"], T_REF)


def make(path, species, n, T0, steps_per_tau, steps, simulators, write, extra=(),
         seed_k=1, cells_x=1):
    """The box in path with one species at n and T0, Delta t =
    steps_per_tau mean collision times (at T0), `steps` steps writing
    every `write`; extra: more entries of constant/dsmcProperties; cells_x
    cells along x (one by default)."""
    case = copy_box(path, species, n)
    mesh = os.path.join(case, "system", "blockMeshDict")
    with open(mesh) as f:
        text = f.read()
    with open(mesh, "w") as f:
        f.write(text.replace("(0 1 2 3 4 5 6 7) (1 1 1)", f"(0 1 2 3 4 5 6 7) ({cells_x} 1 1)"))
    for path in ("constant/grainsProperties", "system/grainsInitialiseDict"):
        os.remove(os.path.join(case, path))
    dt = steps_per_tau*collision_time(species, n, T0)
    entries = [("nEquivalentParticles", f"{n*V_CELL/simulators:.17g}"),
               ("randomSeed", seed(seed_k))]
    for entry, value in entries + list(extra):
        foam.set_entry(case, GAS, entry, value)
    foam.set_entry(case, FILL, "randomSeed", seed(seed_k))
    foam.set_entry(case, FILL, "temperature", T0)
    foam.set_entry(case, CONTROL, "deltaT", f"{dt:.9g}")
    foam.set_entry(case, CONTROL, "endTime", f"{steps*dt:.9g}")
    foam.set_entry(case, CONTROL, "writeInterval", write)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case


def equilibrium(mode, T):
    """Mean energy over k of the mode at T: rotation (zeta 2) T, the
    vibration's harmonic oscillator theta/(exp(theta/T) - 1)."""
    if mode == "rotation":
        return T
    theta = SPECIES["N2"]["theta"]
    return theta/math.expm1(theta/T)


def relaxation(mode, t, T_tr, start, Z, n):
    """The mode's mean energy over k at times t by the relaxation law
        dE/dt = (E*(T_tr) - E)/(Z tau_c(T_tr))
    (Jeans for rotation, Landau-Teller for vibration) with the run's
    T_tr(t) (linear between writes)."""
    def rate(time, e):
        T = np.interp(time, t, T_tr)
        return [(equilibrium(mode, T) - e[0])/(Z*collision_time("N2", n, T))]
    sol = integrate.solve_ivp(rate, (t[0], t[-1]), [start], t_eval=t,
                              rtol=1e-8, atol=1e-10)
    return sol.y[0]


def fit_Z(mode, t, T_tr, e, n):
    """Z of the law integrated with the run's T_tr(t), least squares
    against its mean energy e(t) (e(0) the start)."""
    res = optimize.minimize_scalar(
        lambda z: ((relaxation(mode, t, T_tr, e[0], z, n) - e)**2).sum(),
        bounds=(1, 5000), method="bounded", options={"xatol": 1e-4})
    return res.x


def bath_state(case, time):
    """(T_tr, E_rot/k, E_vib/k) per molecule of the nitrogen simulators at
    a written time (E_vib 0 without vibrational levels)."""
    s = SPECIES["N2"]
    U = foam.read_list(cloud_file(case, time, "U"))
    Ei = foam.read_list(cloud_file(case, time, "Ei"))
    levels = cloud_file(case, time, "vibLevel0")
    e_vib = s["theta"]*foam.read_list(levels).mean() if os.path.exists(levels) else 0.0
    return s["mass"]*U.var(axis=0).sum()/(3*K), Ei.mean()/K, e_vib


def rotational_Z(Z):
    """The rotational collision number of the Jeans law for Larsen-
    Borgnakke's exchange with probability 1/Z per simulator and collision
    (doc/physics.md#collision-sub-steps): a relaxed simulator draws its
    energy from the collision's, so it keeps part of its own and moves
    1/(1 + zeta/(5 - 2 omega)) of the way to equilibrium."""
    s = SPECIES["N2"]
    return Z*(1 + s["zeta"]/(5 - 2*s["omega"]))


def fit_noise(mode, t, T_tr, e, Z, n, simulators):
    """Standard deviation of fit_Z from the thermal noise of the mean
    energy alone, independent of the code: the fit linearised about Z
    (J = de/dZ) under the noise's covariance C, var = J'CJ/(J'J)^2.  The
    mean energy of N simulators fluctuates with variance e^2/N (rotation,
    zeta 2: an exponential energy) or theta^2 a (1 + a)/N (vibration, mean
    level a), relaxing at the law's rate (Onsager's regression: an
    Ornstein-Uhlenbeck process, as the vibration heat bath's synthetic
    runs)."""
    theta = SPECIES["N2"]["theta"]
    law = relaxation(mode, t, T_tr, e[0], Z, n)
    J = (relaxation(mode, t, T_tr, e[0], Z*1.001, n) - law)/(0.001*Z)
    if mode == "rotation":
        var = law**2/simulators
    else:
        a = law/theta
        var = theta**2*a*(1 + a)/simulators
    rho = np.exp(-np.diff(t)/(Z*np.array([collision_time("N2", n, T) for T in T_tr[1:]])))
    m = len(t)
    C = np.zeros((m, m))
    for i in range(m):
        C[i, i] = var[i]
        for j in range(i + 1, m):
            C[i, j] = C[j, i] = C[j - 1, i]*rho[j - 1]
    return math.sqrt(J @ C @ J)/(J @ J)
