# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""NTC hard-sphere grain collisions: kinetic-theory verification
of the NTCHardSphere stochastic collision model, end to end on the solver.

Case (granularGas/): a fully periodic (cyclic) cube of 0.1 m, 4 x 4 x 4
cells, no gravity, every MPPIC model off; N = 20000 parcels of W = 1 glass
grain (d = 1 mm, m = rho pi d^3/6), placed uniformly, velocities
Maxwellian with per-component variance theta = sigmaU^2 = 1 m^2/s^2
(initialiser's sigmaU).  Real number density n = W N / V = 2e7 m^-3,
alpha = 0.0105; dt = 0.5 ms, so each particle collides with probability
~0.07 per step.  Fixed seeds (initialiser randomSeed 1, collision model
randomSeed 1): every run repeats exactly.

Kinetic theory (equal spheres, sigma = pi (R_p + R_q)^2 = pi d^2; a
Maxwellian of per-component variance theta, whose relative velocity c_r is
Maxwellian of variance 2 theta: <c_r> = 4 sqrt(theta/pi),
<c_r^3> = 32 theta^(3/2)/sqrt(pi))

1. Collision rate (e = 1).  Each particle collides at nu = n sigma <c_r>;
   a collision event involves two parcels, so the events per step in the
   whole box are N nu dt / 2 and the measured rate per parcel is
   2 C / (N t) for C events in time t.  Noise: C is a sum of Bernoulli
   acceptances, variance <= C (Poisson): relative sd 1/sqrt(C), taken with
   C kinetic theory's expected count (N nu t/2), not the code's; tolerance
   Z sd (family-wise error below).  The NTC
   count W N (N-1) .../(2V) equals the kinetic rate for the mean over
   cells because <N (N-1)> = <N>^2 for Poisson occupancy; here the
   occupancy is multinomial (fixed total), which lowers <N (N-1)> by
   <N>/64 of <N>^2 ~ 1e5: 3e-5, negligible.

2. Homogeneous cooling (Haff's law) for THIS model.  A collision keeps the
   centre-of-mass velocity and scales the relative speed by e in an
   isotropic direction, so it removes (1 - e^2) mu c_r^2/2 =
   (1 - e^2)(m/4) c_r^2 (equal masses, mu = m/2) whatever the geometry.
   Collisions per volume and time at relative speed c_r: n^2 sigma c_r
   f(c_r)/2.  With E = (3/2) n m theta per volume:

       dE/dt = -(n^2 sigma/2) (1 - e^2) (m/4) <c_r^3>
             = -4 (1 - e^2) n^2 sigma m theta^(3/2) / sqrt(pi)
       dtheta/dt = -(8/(3 sqrt(pi))) (1 - e^2) n sigma theta^(3/2)

   whose solution is theta(t) = theta_0/(1 + t/tau)^2 with

       tau = 3 sqrt(pi) / (4 (1 - e^2) n sigma sqrt(theta_0)).

   (Classical inelastic hard spheres lose only the normal part,
   (1 - e^2)(m/4)(c_r.k)^2, whose collision-weighted mean over impact
   geometry is half as large: their tau is twice this one.)  The
   velocity distribution is assumed to stay Maxwellian (the homogeneous
   cooling state's small departure is not modelled).  theta(t) is read
   every step from the log (kinetic energy, momentum, mass of the cloud:
   theta = (2 KE/M - |P/M|^2)/3); 1/sqrt(theta) = (1 + t/tau)/sqrt(theta_0)
   is fitted by least squares through the exact 1/sqrt(theta_0) of the
   initial parcels, giving tau.  Noise (haff_sd), from kinetic theory
   alone: y = 1/sqrt(theta) grows at the constant rate s = 1/(tau
   sqrt(theta_0)) whatever theta is, in steps, one per collision, each
   removing ~c_r^2 drawn with weight c_r; so y(t) is s t plus a random
   walk with independent increments, whose variance grows at
   q(t) = 1.5 s^2/Gamma(t) (1.5 = <c_r^5><c_r>/<c_r^3>^2; Gamma(t) =
   Gamma_0/(1 + t/tau) the box's collisions per second, Gamma_0 = N n
   sigma <c_r>/2 at theta_0), i.e. Var y(t) = 1.5 s^2 (t + t^2/(2 tau))
   /Gamma_0.  The least-squares slope sum t y/sum t^2 over the steps
   then has the relative variance 1.5/Gamma_0 sum_ij t_i t_j (m_ij +
   m_ij^2/(2 tau))/(sum t^2)^2, m_ij = min(t_i, t_j): 0.31 % at e = 0.9
   (400 steps), 0.47 % at e = 0.7 (200 steps), a little above sqrt(1.5/C)
   for the C collisions kinetic theory expects (0.30 and 0.46 %).  (Until
   2026-12-06 a floor of 0.45 %, the scatter of five seeds of the code
   itself, stood beside sqrt(1.5/C).)
   The velocity distribution does not stay Maxwellian: within a few
   collisions it relaxes to the homogeneous cooling state, whose fourth
   cumulant a2 speeds the cooling by the factor 1 + 3 a2/16.  For this
   collision rule a2 follows from the first Sonine approximation
   (closure_bias: the fourth moment's collisional change balancing the
   cooling, its collision integrals over Maxwellian pairs): a2 = -0.020 at
   e = 0.9, +0.072 at e = 0.7, so tau errs by b = +0.38 % and -1.35 %.
   The run starts Maxwellian, so the fitted tau's expected error lies
   between 0 and b: the check is that err lies in [min(0, b), max(0, b)]
   widened by Z sd each side (family-wise error below).  Measured
   2026-12-06 on seeds outside the test's (101 to 108): e = 0.7 -0.92 %
   mean over 8 seeds (standard error 0.17 %; -0.78 +- 0.08 % at half the
   step, so not the step), their sd 0.47 % against haff_sd's 0.47 %;
   e = 0.9 +0.34 +- 0.06 % over 6 seeds, sd 0.14 % against 0.31 %.

3. Energy bookkeeping: with equal weights every collision turns exactly
   the kinetic energy it removes into heat of the two grains, so
   KE(0) - KE(t) = sum W m c_p (T(t) - T(0)) to round-off (parcel data
   written with 17 digits).  Momentum: each collision conserves the
   pair's, and without forces nothing else changes U: the total is
   conserved to round-off.

4. Relaxation to a Maxwellian (e = 1): two opposing streams U0 = (+-1 0 0)
   m/s, each with a small Maxwellian spread sigmaU = 0.3 m/s, start with
   x-velocity kurtosis ~1.3 (two peaks) and unequal component variances;
   after ~15 collisions per particle every component has kurtosis 3
   (Gaussian) and the variances are equal.  Noise of a sample kurtosis of
   N Gaussian values: sd sqrt(24/N) = 0.035; of a variance ratio:
   sqrt(4/N) = 0.014.  Tolerances Z sd.

5. Polydisperse (e = 1): 10000 grains of 1 mm and 2500 of 2 mm (W = 1,
   m_2 = 8 m_1), started in equipartition (sigmaU_2 = sigmaU_1/sqrt(8):
   m theta equal, so the state is stationary).  Events per volume and
   time: sum over species pairs i <= j of n_i n_j sigma_ij <c_r,ij>
   (halved for i = j), sigma_ij = pi ((d_i + d_j)/2)^2, <c_r,ij> =
   sqrt(8 (theta_i + theta_j)/pi); tolerance Z/sqrt(C) as in 1 (C the
   expected count: that rate times volume and time).  Momentum
   and kinetic energy conserved to round-off (equal weights, unequal
   masses).

6. Unequal weights: the same grains, half of them in parcels of W = 2
   (10000 parcels of W = 1 and 5000 of W = 2, equal real densities):
   physically the same gas, so Haff's tau is the same (as in 2., its sd
   times sqrt(2): the W = 2 parcels halve the independent samples of
   half the grains), and both weight classes cool alike (sample variances
   of 3 N_c values: ratio sd sqrt(2/(3 N_1) + 2/(3 N_2)) = 0.014,
   tolerance Z sd).  A collision updates only one of its parcels with
   probability up to 1/2, so energy and momentum are conserved on average
   only: of some C/2 one-sided updates each misplaces at most ~m theta_0
   of energy and ~m sqrt(theta_0) of each momentum component, a random
   walk of sd sqrt(C/2) times that; tolerances Z sd, against the initial
   kinetic energy (3/2) n V m theta_0 for the energy.  C is kinetic theory's
   expected number of events, not the code's count: the 20000 real
   grains' collisions in the cooling gas, (N nu_0/2) tau ln(1 + t/tau),
   times W_max N_p^2/N^2 = 1.125 (NTCHardSphere.H: candidates between
   any two of the N_p = 15000 parcels are drawn at the largest weight's
   rate).

7. Hybrid and validity monitor (one step): with alphaSwitch set inside
   the range of the cells' alpha, cells above it have no candidate and no
   collision, the log's NTC parcel fraction is that of the cells below,
   and the write-time report counts the cells above alphaValid.  A restart
   reads sigmaCrMax back (and it never decreases).

Family-wise error: 2.5e-4 (rmf_testing.MODULE_ALPHA) over the m = 23
comparisons against noise (STATISTICAL: the collision rates of 1., the
stale majorant, 5. and the step guard's three runs, 6; the relaxation's
three kurtoses and three variance ratios, 6; Haff's tau at e = 0.9 and
0.7, 2; 6.'s tau, temperature ratio, energy and three momentum
components, 6; the step guard's largest cell estimate, 3), Bonferroni,
Z = rmf_testing.z_limit(23) = 4.4 sd each.  The checks to round-off are
deterministic.  Seeds: the initialiser's and the collision model's
randomSeed (1 in the case files) are set to rmf_testing.seed(1).
"""

import os
import re

import numpy as np
import pytest

from rmf import foam
from rmf_testing import report, seed, z_limit

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, "granularGas")
BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "grainCollisions")
PROPS = "constant/grainsProperties"
INIT = "system/grainsInitialiseDict"
COEFFS = "subModels/NTCHardSphereCoeffs/"

N = 20000                   # parcels
W = 1.0                     # particles per parcel
D = 1e-3                    # grain diameter [m]
RHO = 2500.0                # grain density [kg/m^3]
CP = 840.0                  # specific heat [J/kg/K]
VBOX = 0.1**3               # box volume [m^3]
DT = 5e-4                   # time step [s]
MASS = RHO*np.pi*D**3/6     # one grain [kg]
NREAL = W*N/VBOX            # real number density [1/m^3]
SIGMA = np.pi*D**2          # cross-section of two equal grains [m^2]
STATISTICAL = 23            # comparisons against noise (module docstring)
Z = z_limit(STATISTICAL)


def run_case(name, steps, entries=(), init_entries=(), before_solver=None):
    """Run a copy of the granular gas for steps steps, written at the start
    and the end (before_solver(case): a change to the initialised case),
    its seeds those of the seed set (module docstring); returns the case."""
    case = foam.copy_setup(CASE, os.path.join(BUILD, name))
    seeded(case)
    for entry, value in entries:
        foam.set_entry(case, PROPS, entry, value)
    for entry, value in init_entries:
        foam.set_entry(case, INIT, entry, value)
    foam.set_entry(case, "system/controlDict", "endTime", f"{steps*DT:.6g}")
    foam.set_entry(case, "system/controlDict", "writeInterval", steps)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    if before_solver:
        before_solver(case)
    foam.run(case, "rarefiedMultiphaseFoam")
    return case


def seeded(case):
    """The initialiser's and the collision model's seeds: seed(1)."""
    foam.set_entry(case, INIT, "randomSeed", seed(1))
    foam.set_entry(case, PROPS, COEFFS + "randomSeed", seed(1))


def haff_sd(t, tau, theta0, grains=N):
    """Relative sd of Haff's tau fitted at the times t (module docstring,
    2.): kinetic theory's collisions of the grains at theta0 and its tau."""
    gamma0 = grains*NREAL*SIGMA*4*np.sqrt(theta0/np.pi)/2
    m = np.minimum.outer(t, t)
    return float(np.sqrt(1.5/gamma0*(t @ (m + m*m/(2*tau)) @ t))/np.sum(t*t))


def closure_bias(e, n=2000000):
    """b: the relative error of the Maxwellian closure's tau in the
    homogeneous cooling state of this collision rule (module docstring,
    2.), first Sonine approximation.  Per pair of velocities v1, v2 (per-
    component variance 1, x = v^2/2, S2(x) = x^2/2 - 5 x/2 + 15/8), the
    rule keeps V = (v1 + v2)/2 and turns g = v1 - v2 into e |g| n, n
    isotropic: sum v^2 changes by (e^2 - 1) g^2/2, sum v^4 by
    2 (V^2 + e^2 g^2/4)^2 + 2 e^2 g^2 V^2/3 - 2 (V^2 + g^2/4)^2 - 2 (V.g)^2
    (n averaged).  Their collision-rate (|g|) weighted means over
    Maxwellian pairs, A_k, and over the Sonine term's weight S2(x1) +
    S2(x2), B_k, give the state's <v^4>/<v^2>^2 = (5/3)(1 + a2) stationary:
    a2 = (A_4 - 10 A_2)/(10 B_2 + 10 A_2 - B_4), the cooling faster by
    1 + a2 B_2/A_2 (B_2/A_2 = 3/16).  The means are integrated by Monte
    Carlo over n pairs of a fixed generator (numerical quadrature, not a
    seed of the test: b scatters by 0.02 % between generators)."""
    rng = np.random.default_rng(0)
    v1, v2 = rng.standard_normal((n, 3)), rng.standard_normal((n, 3))
    V, g = (v1 + v2)/2, v1 - v2
    g2, V2, Vg = (g*g).sum(axis=1), (V*V).sum(axis=1), (V*g).sum(axis=1)
    rate = np.sqrt(g2)
    d2 = rate*(e*e - 1)*g2/2
    d4 = rate*(2*(V2 + e*e*g2/4)**2 + 2*e*e*g2*V2/3 - 2*(V2 + g2/4)**2 - 2*Vg**2)
    x1, x2 = (v1*v1).sum(axis=1)/2, (v2*v2).sum(axis=1)/2
    s2 = x1*x1/2 - 5*x1/2 + x2*x2/2 - 5*x2/2 + 15/4
    A2, B2, A4, B4 = d2.mean(), (d2*s2).mean(), d4.mean(), (d4*s2).mean()
    a2 = (A4 - 10*A2)/(10*B2 + 10*A2 - B4)
    return float(1/(1 + a2*B2/A2) - 1)


def haff_ok(name, e, err, sd):
    """report() of Haff's tau: err within [min(0, b), max(0, b)] +- Z sd."""
    b = closure_bias(e)
    lo, hi = min(0, b) - Z*sd, max(0, b) + Z*sd
    return report(name, lo < err < hi,
                  f"error {100*err:+.2f} % in [{100*lo:+.2f}, {100*hi:+.2f}] %: the closure's"
                  f" {100*b:+.2f} % (homogeneous cooling state) or none, +- {Z:.1f} x"
                  f" {100*sd:.3f} %, kinetic theory's sd")


def parcels(case, t, name):
    return foam.read_list(os.path.join(case, t, "lagrangian", "grains", name))


def theta_of(U):
    """Granular temperature: mean per-component variance [m^2/s^2]."""
    return float(np.mean(U.var(axis=0)))


def kurtosis(x):
    x = x - x.mean()
    return float(np.mean(x**4)/np.mean(x**2)**2)


def log_series(case):
    """Per step: time, collisions, kinetic energy, momentum, mass."""
    log = os.path.join(case, "log.rarefiedMultiphaseFoam")
    collisions = foam.log_values(log, "NTC collisions")[:, 0]
    ke = foam.log_values(log, "Linear kinetic energy")[:, 0]
    p = foam.log_values(log, "Linear momentum")
    m = foam.log_values(log, "Current mass in system")[:, 0]
    t = DT*np.arange(1, len(ke) + 1)
    return t, collisions, ke, p, m


# ---------------------------------------------------------------------------
# e = 1: collision rate, conservation


@pytest.fixture(scope="module")
def elastic():
    case = run_case("elastic", 200)
    return case


def collision_rate(case):
    """Collisions per parcel and second over the run, kinetic theory's
    n sigma <c_r> of the initial parcels, the relative error, its
    tolerance (Z sd of a Poisson count of kinetic theory's expected
    number, N nu t/2) and the measured count C."""
    t, collisions, _, _, _ = log_series(case)
    theta = theta_of(parcels(case, "0", "U"))
    C = collisions.sum()
    measured = 2*C/(N*t[-1])
    theory = NREAL*SIGMA*4*np.sqrt(theta/np.pi)
    expected = theory*N*t[-1]/2
    return measured, theory, measured/theory - 1, Z/np.sqrt(expected), C


def test_collision_rate(elastic):
    measured, theory, err, tol, C = collision_rate(elastic)
    assert report(
        "collision rate (e = 1)", abs(err) < tol,
        f"{measured:.2f}/s per parcel vs n sigma <c_r> = {theory:.2f}/s, "
        f"error {100*err:+.2f} % (tolerance {100*tol:.2f} %: {Z:.1f}/sqrt(expected count), "
        f"C = {C:.0f} collisions)")


def test_stale_majorant():
    """A majorant far below the cell's pairs does not stall the cell: every
    cell starts with (sigma c_r)_max = 1e-30 m^3/s, read as a restart's
    sigmaCrMax, and the model raises it to the bound of the step's pairs
    (doc/physics.md#ntc), so the collision rate over 50 steps is the
    kinetic theory's, tolerance Z/sqrt(C) as above.  Raised by candidates
    alone (the model before 2026-12-02), the cells drew 1e-28 candidates
    per step and never collided."""
    def stale(case):
        with open(os.path.join(case, "0", "sigmaCrMax.grains"), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class volScalarField;"
                    " object sigmaCrMax.grains; }\n"
                    "dimensions [0 3 -1 0 0 0 0];\ninternalField uniform 1e-30;\n"
                    "boundaryField { \".*\" { type cyclic; } }\n")
    case = run_case("staleMajorant", 50, before_solver=stale)
    with open(os.path.join(case, "log.rarefiedMultiphaseFoam")) as f:
        read = "read sigmaCrMax.grains" in f.read()
    measured, theory, err, tol, C = collision_rate(case)
    assert report(
        "stale majorant raised", read and abs(err) < tol,
        f"read the planted sigmaCrMax: {read}; {measured:.2f}/s per parcel vs"
        f" {theory:.2f}/s, error {100*err:+.2f} % (tolerance {100*tol:.2f} %,"
        f" C = {C:.0f})")


def test_elastic_conservation(elastic):
    t_end = foam.latest_time(elastic)
    U0, U1 = parcels(elastic, "0", "U"), parcels(elastic, t_end, "U")
    mw = W*MASS
    p0, p1 = mw*U0.sum(axis=0), mw*U1.sum(axis=0)
    scale = mw*np.abs(U0).sum()
    dp = np.abs(p1 - p0).max()/scale
    ke0, ke1 = 0.5*mw*(U0**2).sum(), 0.5*mw*(U1**2).sum()
    dke = abs(ke1/ke0 - 1)
    T1 = parcels(elastic, t_end, "T")
    ok = report("momentum (e = 1)", dp < 1e-12,
                f"|dP|/sum(m|U|) = {dp:.1e} (tolerance 1e-12, round-off)")
    ok &= report("kinetic energy (e = 1)", dke < 1e-12,
                 f"|dKE|/KE = {dke:.1e} (tolerance 1e-12, round-off)")
    ok &= report("no heating (e = 1)", np.all(np.abs(T1 - 300) < 1e-10),
                 f"max |T - 300 K| = {np.abs(T1 - 300).max():.1e} K")
    assert ok


# ---------------------------------------------------------------------------
# Relaxation of a two-peaked distribution


def test_relaxation_to_maxwellian():
    streams = ("{ plus { type box; min (0 0 0); max (0.1 0.1 0.1); d 1e-3;"
               " nParcels 10000; nParticle 1; U0 (1 0 0); sigmaU 0.3; }"
               " minus { type box; min (0 0 0); max (0.1 0.1 0.1); d 1e-3;"
               " nParcels 10000; nParticle 1; U0 (-1 0 0); sigmaU 0.3; } }")
    case = run_case("twoStreams", 300, init_entries=[("regions", streams)])
    U0 = parcels(case, "0", "U")
    U1 = parcels(case, foam.latest_time(case), "U")
    k0 = [kurtosis(U0[:, i]) for i in range(3)]
    k1 = [kurtosis(U1[:, i]) for i in range(3)]
    var1 = U1.var(axis=0)
    tol_k = Z*np.sqrt(24/N)
    tol_v = Z*np.sqrt(4/N)
    ok = report("two peaks at start", k0[0] < 1.5,
                f"x kurtosis {k0[0]:.3f} (two streams: < 1.5)")
    for i, c in enumerate("xyz"):
        ok &= report(f"kurtosis {c}", abs(k1[i] - 3) < tol_k,
                     f"{k0[i]:.3f} -> {k1[i]:.3f} (Gaussian 3, tolerance "
                     f"{tol_k:.3f}: {Z:.1f} sqrt(24/N))")
    ratio = var1.max()/var1.min() - 1
    ok &= report("isotropy", ratio < tol_v,
                 f"variances {var1.round(4)} (start {U0.var(axis=0).round(4)}),"
                 f" max/min - 1 = {ratio:.4f} (tolerance {tol_v:.3f}: "
                 f"{Z:.1f} sqrt(4/N))")
    assert ok


# ---------------------------------------------------------------------------
# Haff's law, energy bookkeeping


HAFF = [(0.9, 400), (0.7, 200)]      # (e, steps): to theta/theta_0 ~ 0.1


@pytest.mark.parametrize("e, steps", HAFF, ids=[f"e{e}" for e, _ in HAFF])
def test_haff_cooling(e, steps):
    case = run_case(f"haff{e}", steps, entries=[(COEFFS + "e", e)])
    t, collisions, ke, p, m = log_series(case)
    theta = (2*ke/m - (p**2).sum(axis=1)/m**2)/3
    U0 = parcels(case, "0", "U")
    theta0 = theta_of(U0)

    # Least squares of 1/sqrt(theta) - 1/sqrt(theta0) = t/(tau sqrt(theta0))
    a0 = 1/np.sqrt(theta0)
    slope = np.sum(t*(1/np.sqrt(theta) - a0))/np.sum(t*t)
    tau = a0/slope
    tau_theory = 3*np.sqrt(np.pi)/(4*(1 - e*e)*NREAL*SIGMA*np.sqrt(theta0))
    err = tau/tau_theory - 1
    C = collisions.sum()
    print(f"\n    e = {e}: fitted {tau*1e3:.2f} ms vs theory {tau_theory*1e3:.2f} ms, "
          f"C = {C:.0f}; theta fell to {theta[-1]/theta0:.3f} theta_0")
    ok = haff_ok(f"Haff tau (e = {e})", e, err, haff_sd(t, tau_theory, theta0))

    # Energy: kinetic lost = heat gained (equal weights: exact)
    t_end = foam.latest_time(case)
    U1 = parcels(case, t_end, "U")
    mw = W*MASS
    lost = 0.5*mw*((U0**2).sum() - (U1**2).sum())
    heat = mw*CP*(parcels(case, t_end, "T") - parcels(case, "0", "T")).sum()
    rel = abs(heat/lost - 1)
    ok &= report(f"energy bookkeeping (e = {e})", rel < 1e-9,
                 f"kinetic energy lost {lost:.10e} J, heat gained "
                 f"{heat:.10e} J, relative difference {rel:.1e} (tolerance "
                 f"1e-9: round-off of T ~ 300 K at 17 digits)")

    scale = mw*np.abs(U0).sum()
    dp = np.abs(mw*(U1.sum(axis=0) - U0.sum(axis=0))).max()/scale
    ok &= report(f"momentum (e = {e})", dp < 1e-12,
                 f"|dP|/sum(m|U|) = {dp:.1e} (tolerance 1e-12, round-off)")
    assert ok


def test_totally_inelastic():
    """Stability at the extreme e = 0 (doc/speed-accuracy.md): every accepted
    pair leaves with its centre-of-mass velocity.  Expected: the model
    stays stable (no NaN, theta falls at every step and stays positive),
    kinetic energy lost equals heat gained and momentum is conserved to
    round-off, as at e = 0.9 and 0.7.  Haff's tau is printed, not
    checked: the Maxwellian closure behind it fails at e = 0, where the
    homogeneous cooling state carries a fourth cumulant of order 0.2
    (first Sonine estimate for classical inelastic spheres, 16/81 at
    e = 0), which speeds the cooling by several per cent; measured
    -5.3 % (0.65 % noise) on this case (2026-12-06), against +0.29 % and
    -0.71 % at e = 0.9 and 0.7.  (This collision rule's own first Sonine
    estimate, closure_bias, gives a2 = 1.0 and -15 % at e = 0: the
    approximation fails there, and the run spends much of its time in
    the transient from the Maxwellian start.)"""
    e, steps = 0.0, 100
    case = run_case("inelastic0", steps, entries=[(COEFFS + "e", e)])
    t, collisions, ke, p, m = log_series(case)
    theta = (2*ke/m - (p**2).sum(axis=1)/m**2)/3
    U0 = parcels(case, "0", "U")
    theta0 = theta_of(U0)
    a0 = 1/np.sqrt(theta0)
    tau = a0/(np.sum(t*(1/np.sqrt(theta) - a0))/np.sum(t*t))
    tau_theory = 3*np.sqrt(np.pi)/(4*NREAL*SIGMA*np.sqrt(theta0))
    print(f"\n    e = 0: Haff tau {tau*1e3:.2f} ms against the Maxwellian closure's "
          f"{tau_theory*1e3:.2f} ms ({100*(tau/tau_theory - 1):+.2f} %); "
          f"theta fell to {theta[-1]/theta0:.3f} theta_0 in {collisions.sum():.0f} collisions")

    ok = report("finite and cooling (e = 0)",
                bool(np.all(np.isfinite(theta)) and np.all(theta > 0)
                     and np.all(np.diff(theta) < 0)),
                f"theta finite, positive and falling at each of {len(theta)} steps")
    t_end = foam.latest_time(case)
    U1 = parcels(case, t_end, "U")
    T1 = parcels(case, t_end, "T")
    mw = W*MASS
    lost = 0.5*mw*((U0**2).sum() - (U1**2).sum())
    heat = mw*CP*(T1 - parcels(case, "0", "T")).sum()
    rel = abs(heat/lost - 1)
    ok &= report("energy bookkeeping (e = 0)",
                 rel < 1e-9 and bool(np.all(np.isfinite(U1))) and bool(np.all(np.isfinite(T1))),
                 f"kinetic energy lost {lost:.10e} J, heat gained {heat:.10e} J, "
                 f"relative difference {rel:.1e} (tolerance 1e-9)")
    dp = np.abs(mw*(U1.sum(axis=0) - U0.sum(axis=0))).max()/(mw*np.abs(U0).sum())
    ok &= report("momentum (e = 0)", dp < 1e-12,
                 f"|dP|/sum(m|U|) = {dp:.1e} (tolerance 1e-12, round-off)")
    assert ok


def test_polydisperse():
    mixed = ("{ small { type box; min (0 0 0); max (0.1 0.1 0.1); d 1e-3;"
             " nParcels 10000; nParticle 1; U0 (0 0 0); sigmaU 1; }"
             " large { type box; min (0 0 0); max (0.1 0.1 0.1); d 2e-3;"
             " nParcels 2500; nParticle 1; U0 (0 0 0);"
             f" sigmaU {1/np.sqrt(8):.15g}; }} }}")
    case = run_case("polydisperse", 200, init_entries=[("regions", mixed)])
    t, collisions, _, _, _ = log_series(case)
    C = collisions.sum()
    U0, d0 = parcels(case, "0", "U"), parcels(case, "0", "d")
    sizes = (1e-3, 2e-3)
    n = [np.sum(np.isclose(d0, d))/VBOX for d in sizes]
    theta = [theta_of(U0[np.isclose(d0, d)]) for d in sizes]
    rate = 0
    for i in range(2):
        for j in range(i, 2):
            sigma = np.pi*((sizes[i] + sizes[j])/2)**2
            cr = np.sqrt(8*(theta[i] + theta[j])/np.pi)
            rate += n[i]*n[j]*sigma*cr*(0.5 if i == j else 1)
    measured = C/(VBOX*t[-1])
    err = measured/rate - 1
    tol = Z/np.sqrt(rate*VBOX*t[-1])    # kinetic theory's expected count
    ok = report(
        "polydisperse collision rate (e = 1)", abs(err) < tol,
        f"{measured:.4g} vs {rate:.4g} events/(m^3 s), error {100*err:+.2f} "
        f"% (tolerance {100*tol:.2f} %: {Z:.1f}/sqrt(expected count), C = {C:.0f})")

    t_end = foam.latest_time(case)
    U1, d1 = parcels(case, t_end, "U"), parcels(case, t_end, "d")
    m0 = RHO*np.pi*d0**3/6
    m1 = RHO*np.pi*d1**3/6
    dp = np.abs((m1[:, None]*U1).sum(axis=0)
                - (m0[:, None]*U0).sum(axis=0)).max()/(m0[:, None]*np.abs(U0)).sum()
    dke = abs((m1*(U1**2).sum(axis=1)).sum()/(m0*(U0**2).sum(axis=1)).sum() - 1)
    ok &= report("momentum (polydisperse)", dp < 1e-12,
                 f"|dP|/sum(m|U|) = {dp:.1e} (tolerance 1e-12, round-off)")
    ok &= report("kinetic energy (polydisperse, e = 1)", dke < 1e-12,
                 f"|dKE|/KE = {dke:.1e} (tolerance 1e-12, round-off)")
    assert ok


def test_unequal_weights():
    e = 0.7
    mixed = ("{ single { type box; min (0 0 0); max (0.1 0.1 0.1); d 1e-3;"
             " nParcels 10000; nParticle 1; U0 (0 0 0); sigmaU 1; }"
             " double { type box; min (0 0 0); max (0.1 0.1 0.1); d 1e-3;"
             " nParcels 5000; nParticle 2; U0 (0 0 0); sigmaU 1; } }")
    case = run_case("unequalWeights", 200, entries=[(COEFFS + "e", e)],
                       init_entries=[("regions", mixed)])
    t, collisions, ke, p, m = log_series(case)
    theta = (2*ke/m - (p**2).sum(axis=1)/m**2)/3
    t_end = foam.latest_time(case)
    U0, U1 = parcels(case, "0", "U"), parcels(case, t_end, "U")
    W0, W1 = parcels(case, "0", "nParticle"), parcels(case, t_end, "nParticle")
    mean0 = np.average(U0, axis=0, weights=W0)
    theta0 = float(np.average(((U0 - mean0)**2).sum(axis=1), weights=W0)/3)
    C = collisions.sum()

    a0 = 1/np.sqrt(theta0)
    tau = a0/(np.sum(t*(1/np.sqrt(theta) - a0))/np.sum(t*t))
    tau_theory = 3*np.sqrt(np.pi)/(4*(1 - e*e)*NREAL*SIGMA*np.sqrt(theta0))
    err = tau/tau_theory - 1
    print(f"\n    unequal weights: fitted {tau*1e3:.2f} ms vs theory {tau_theory*1e3:.2f} ms,"
          f" C = {C:.0f}")
    ok = haff_ok("Haff tau, unequal weights", e, err, np.sqrt(2)*haff_sd(t, tau_theory, theta0))

    th = [theta_of(U1[W1 == w]) for w in (1, 2)]
    n1, n2 = (W1 == 1).sum(), (W1 == 2).sum()
    tol_th = Z*np.sqrt(2/(3*n1) + 2/(3*n2))
    ok &= report("weight classes cool alike", abs(th[1]/th[0] - 1) < tol_th,
                 f"theta(W = 1) = {th[0]:.4f}, theta(W = 2) = {th[1]:.4f} "
                 f"m^2/s^2 (tolerance {100*tol_th:.1f} %: {Z:.1f} sd of the ratio)")

    mass = MASS
    ke0 = 0.5*mass*(W0*(U0**2).sum(axis=1)).sum()
    ke1 = 0.5*mass*(W1*(U1**2).sum(axis=1)).sum()
    heat = mass*CP*((W1*parcels(case, t_end, "T")).sum()
                    - (W0*parcels(case, "0", "T")).sum())
    rel = (heat - (ke0 - ke1))/ke0
    nu0 = NREAL*SIGMA*4*np.sqrt(theta0/np.pi)
    scheme = W0.max()*len(W0)**2/W0.sum()**2          # 1.125
    C_bound = scheme*N*nu0/2*tau_theory*np.log(1 + t[-1]/tau_theory)   # N = 20000 grains
    print(f"    events counted {C:.0f}, expected from kinetic theory {C_bound:.0f}")
    tol_e = Z*np.sqrt(C_bound/2)*mass*theta0/ke0
    ok &= report("energy on average, unequal weights", abs(rel) < tol_e,
                 f"heat gained - kinetic energy lost = {100*rel:+.3f} % of "
                 f"KE(0) (tolerance {100*tol_e:.2f} %: {Z:.1f} sqrt(C/2) m theta_0)")
    dp = np.abs(mass*((W1[:, None]*U1).sum(axis=0)
                      - (W0[:, None]*U0).sum(axis=0))).max()
    tol_p = Z*np.sqrt(C_bound/2)*mass*np.sqrt(theta0)
    ok &= report("momentum on average, unequal weights", dp < tol_p,
                 f"max |dP_i| = {dp:.2e} kg m/s (tolerance {tol_p:.2e}: "
                 f"{Z:.1f} sqrt(C/2) m sqrt(theta_0))")
    assert ok


# ---------------------------------------------------------------------------
# Hybrid regime split, validity monitor, restart of sigmaCrMax


def cell_field(case, t, name):
    return foam.read_field(os.path.join(case, t, f"{name}.grains"), 64)


def test_hybrid_and_monitor():
    # Mean alpha 0.0105 with ~2 % scatter between cells: thresholds at the
    # mean split the cells
    alpha_mean = N*W*np.pi*D**3/6/VBOX
    case = run_case("hybrid", 1, entries=[
        (COEFFS + "alphaSwitch", f"{alpha_mean:.6g}"),
        (COEFFS + "alphaValid", f"{alpha_mean:.6g}"),
    ])
    t1 = foam.latest_time(case)
    nParcels = cell_field(case, t1, "nParcels")
    alpha = nParcels*W*np.pi*D**3/6/(VBOX/64)
    cand = cell_field(case, t1, "nCandidates")
    coll = cell_field(case, t1, "nCollisions")
    dense = alpha >= alpha_mean
    with open(os.path.join(case, "log.rarefiedMultiphaseFoam")) as f:
        log = f.read()
    frac = foam.log_values(os.path.join(case, "log.rarefiedMultiphaseFoam"),
                           "Parcel fraction NTC / MPPIC only")[-1]
    m = re.search(r"NTCHardSphere: (\d+) of 64 cells above alphaValid", log)

    ok = report("dense cells present", 0 < dense.sum() < 64,
                f"{dense.sum()} of 64 cells at alpha >= {alpha_mean:.4g}")
    ok &= report("no collisions in dense cells",
                 cand[dense].sum() == 0 and coll[dense].sum() == 0,
                 f"candidates {cand[dense].sum():.0f}, collisions "
                 f"{coll[dense].sum():.0f} there; {coll[~dense].sum():.0f} "
                 f"collisions in the dilute cells")
    ok &= report("colliding elsewhere", coll[~dense].sum() > 0,
                 f"{coll[~dense].sum():.0f} collisions in dilute cells")
    expected = nParcels[~dense].sum()/N
    ok &= report("regime split in the log",
                 abs(frac[0] - expected) < 1e-6 and abs(frac.sum() - 1) < 1e-6,
                 f"NTC / MPPIC only = {frac[0]:.4f} / {frac[1]:.4f}, "
                 f"parcels in dilute cells {expected:.4f}")
    ok &= report("validity monitor", m is not None
                 and int(m.group(1)) == int((alpha > alpha_mean).sum()),
                 f"reported {m.group(1) if m else None} cells above "
                 f"alphaValid, counted {(alpha > alpha_mean).sum()}")

    # Restart: one more step reads sigmaCrMax back
    foam.set_entry(case, "system/controlDict", "endTime", f"{2*DT:.6g}")
    foam.set_entry(case, "system/controlDict", "startFrom", "latestTime")
    foam.run(case, "rarefiedMultiphaseFoam", log="log.restart")
    with open(os.path.join(case, "log.restart")) as f:
        restart = f.read()
    t2 = foam.latest_time(case)
    s1, s2 = cell_field(case, t1, "sigmaCrMax"), cell_field(case, t2, "sigmaCrMax")
    ok &= report("sigmaCrMax restart",
                 "read sigmaCrMax.grains" in restart and t2 != t1
                 and np.all(s2 >= s1) and np.all(s1[~dense] > 0),
                 f"read back: {'read sigmaCrMax.grains' in restart}, "
                 f"never lowered: {bool(np.all(s2 >= s1))}")
    assert ok


# ---------------------------------------------------------------------------
# The step guard at 0.5, 2 and 10 times the grains' mean collision time

GUARD = re.compile(r"NTCHardSphere: collisions per parcel per step since the last write"
                   r" largest (\S+) \((\d+) cells above 1\); candidates with acceptance"
                   r" probability above 1 (\S+) \(largest (\S+)\)")


@pytest.mark.parametrize("factor", [0.5, 2, 10])
def test_step_guard(factor):
    """Stability at the extremes (doc/speed-accuracy.md: deltaT at 1x, 2x and
    10x the model's limit).  The limit of NTC grains is their mean time
    between collisions, 1/nu with nu = n sigma <c_r> (7.05 ms here);
    deltaT = factor/nu.  The guard logs at every write the largest
    collisions per parcel per step of a cell, 2 N_coll/(parcels x steps):
    nominal nu deltaT = factor.  It is the largest of 64 cells'
    estimates, each with the noise of its collision count (1/sqrt(C_cell):
    2.5 % at 0.5x, 1560 collisions) and of its occupancy (the rate of a
    parcel goes as the cell's N - 1: 1/sqrt(312 parcels x the independent
    occupancies of 20 steps, about 4.5 at 0.5x, where a parcel moves 5.6 mm
    of a 25 mm cell per step): 3.7 % at 0.5x, less at 2x and 10x.  The
    largest of 64 lies about 2.4 sd above the nominal, at most about 4 sd
    (15 %): band [1, 1.2) of the nominal.
    Expected: no warning at 0.5x, the warning at 2x and 10x (every cell
    above 1); no candidate above the majorant at 0.5x and 2x (it is never
    below the bound of the step's pairs at the step's start); at 10x a few
    (each parcel collides about 10 times in the step, and a collision can
    send a parcel beyond that bound: v_p* - <v> = (v_m - <v>) +
    |v_p - v_m| n), fewer than 1e-5 of the candidates, with probabilities
    below 2; and the collision rate per second and the
    conservation of momentum and energy as at the tutorial's step: in a
    homogeneous elastic gas NTC's rate does not depend on deltaT (each
    step draws nu deltaT collisions per parcel from the state it starts
    with, and collisions do not change the state's distribution), so a
    long step loses nothing this case can see: what it loses is the
    motion between a parcel's collisions in a gradient."""
    nu = NREAL*SIGMA*4*np.sqrt(1/np.pi)     # theta_0 = 1 m^2/s^2
    dt = factor/nu
    steps = 20
    case = foam.copy_setup(CASE, os.path.join(BUILD, f"stepGuard{factor:g}"))
    seeded(case)
    foam.set_entry(case, "system/controlDict", "deltaT", f"{dt:.6g}")
    foam.set_entry(case, "system/controlDict", "endTime", f"{steps*dt:.6g}")
    foam.set_entry(case, "system/controlDict", "writeInterval", steps)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    log = foam.run(case, "rarefiedMultiphaseFoam")
    with open(log) as f:
        text = f.read()
    rows = GUARD.findall(text)
    collisions = foam.log_values(log, "NTC collisions")[:, 0]
    C = collisions.sum()
    t_end = foam.latest_time(case)
    U0, U1 = parcels(case, "0", "U"), parcels(case, t_end, "U")
    rate = 2*C/(N*steps*dt)
    theory = NREAL*SIGMA*4*np.sqrt(theta_of(U0)/np.pi)
    err, tol = rate/theory - 1, Z/np.sqrt(theory*N*steps*dt/2)  # expected count
    dp = np.abs(U1.sum(axis=0) - U0.sum(axis=0)).max()/np.abs(U0).sum()
    dke = abs((U1**2).sum()/(U0**2).sum() - 1)
    warned = "too long for the grain collisions" in text

    ok = report(f"guard logged ({factor}x)", len(rows) == 1, f"{len(rows)} report(s)")
    largest, above, n_over, p_over = rows[0] if rows else (0, 0, -1, 0)
    largest, above, n_over = float(largest), int(above), float(n_over)
    ok &= report(f"collisions per parcel per step ({factor}x)",
                 1 <= largest/factor < 1.2,
                 f"largest {largest:.4g} against nominal {factor} (band [1, 1.2)),"
                 f" {above} of 64 cells above 1")
    ok &= report(f"warning ({factor}x)",
                 warned == (factor > 1) and above == (64 if factor > 1 else 0),
                 f"warned {warned}, {above} cells above 1 (expected {factor > 1})")
    candidates = foam.log_values(log, "NTC candidate pairs")[:, 0].sum()
    ok &= report(f"acceptance above 1 ({factor}x)",
                 n_over == 0 if factor < 10 else
                 n_over < 1e-5*candidates and float(p_over) < 2,
                 f"{n_over:g} of {candidates:.0f} candidates (largest probability {p_over};"
                 f" expected {'none' if factor < 10 else 'below 1e-5 of them, below 2'})")
    ok &= report(f"collision rate ({factor}x)", abs(err) < tol,
                 f"{rate:.2f}/s per parcel vs {theory:.2f}/s ({100*err:+.2f} %,"
                 f" tolerance {100*tol:.2f} %: {Z:.1f}/sqrt(expected count), C = {C:.0f})")
    ok &= report(f"conservation ({factor}x)",
                 dp < 1e-12 and dke < 1e-12 and bool(np.all(np.isfinite(U1))),
                 f"|dP|/sum(m|U|) {dp:.1e}, |dKE|/KE {dke:.1e} (round-off: 1e-12)")
    assert ok
