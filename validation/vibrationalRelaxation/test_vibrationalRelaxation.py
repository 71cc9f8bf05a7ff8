# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Vibrational energy (doc/physics.md#vibration) in the one-cell periodic gas
box of validation/freeMolecularCoupling (testing/rmf_box.py), with the quantum
Larsen-Borgnakke exchange of LarsenBorgnakkeVariableSoftSphere (alpha 1:
VHS scattering).

1. Heat bath of nitrogen (one mode, theta 3371 K; d 4.17e-10 m, omega
   0.74, zeta_rot 2) at 1e21 m^-3, filled at 3000 K with every simulator
   moved to the vibrational ground level.  Z_v = 20, Z_rot = 5.  The
   vibrational energy per molecule E_v relaxes by the Landau-Teller law
       dE_v/dt = (E_v*(T_tr) - E_v)/(Z_v tau_c(T_tr)),
       E_v*(T) = k theta/(exp(theta/T) - 1),
       tau_c(T) = 1/(4 n d^2 (pi k T_ref/m)^(1/2) (T/T_ref)^(1 - omega))
   (tau_c: the VHS mean collision time, Bird 1994 eq. 4.64) with the
   translational temperature the run measures.  Z_v is fitted to the run's
   E_v(t) (least squares of the integrated law), per seed, and compared
   with the input 20: the mean over 4 seeds within t_limit standard errors
   (Student t of NOISE_TRIALS - 1 degrees of freedom: the error is
   estimated from NOISE_TRIALS synthetic fits), the
   error of one fit computed from the thermal noise of the mean level
   (fit_noise: synthetic runs of the law with the fluctuation of N
   geometric levels, relaxing at the law's rate), not from the code.
   Then, at the end (the last 2 of 7 relaxation times), the gas is at
   equipartition:
   T_rot and T_vib (from the mean level, theta/ln(1 + 1/a)) equal T_tr, and
   T_tr equals the temperature that shares the fill's energy between
   translation, rotation and a harmonic oscillator, 3/2 k T + k T +
   E_v*(T) = 3/2 k T_0 + k T_0, within N_SIGMA of their thermal noise
   (computed from the chi-square noise of the sums, not from the run).
   The sampled fields carry the vibration: internalE and iDof equal the
   parcels' sums with the vibrational energy and degrees of freedom
   (2 a ln(1 + 1/a) per molecule), so dsmcFields' overall temperature
   ends at the energy-sharing temperature, and vibrationalT.gas agrees
   with the levels.

2. Water vapour at 3000 K (three modes, 2294, 5261 and 5432 K; d 4.5e-10
   m, omega 0.75, zeta_rot 3; Z_v = 5, Z_rot = 5), 1e21 m^-3: filled at
   equilibrium, the exchange must keep each mode's level populations on
   the Boltzmann (geometric) distribution P(i) = (1 - q) q^i, q =
   exp(-theta/T): chi-square of the final levels against it (levels pooled
   so that every class expects at least 20) with a p-value above the
   comparison's share of the budget for each mode, after about 15
   exchanges per oscillator (checked: the
   fraction of levels that differ from the start is at least 0.9 of
   2q/(1 + q), that of independent draws).  A wrong exponent of the level
   draw would move the populations off it.

3. Bad input: a characteristic temperature <= 0, a degeneracy below 1, a
   missing relaxation number, a relaxation number below 1 or without
   modes, a collision model that does not exchange vibration:
   FatalIOError naming the file, keyword, value and valid range.

Statistics: the comparisons are the fitted Z_v (1), T_tr, T_rot and T_vib
at the end of each of the 4 baths (12), the fields' overall T and
vibrationalT.gas (2), the chi-square and the changed fraction of each of
the 3 water modes (6) and the two oscillators' levels after a new mode
(2): m = COMPARISONS = 23, each at MODULE_ALPHA/23 = 1.1e-5 two-sided
(N_SIGMA = z_limit(23) = 4.40 standard errors; Z_v at t_limit(39, 23) =
5.04; the chi-square's p-value above 1.1e-5; the changed fractions lie
more than 10 of their binomial sd above their bound).  internalE and iDof
against the parcels' sums are exact (FIELD_TOLERANCE).
Family-wise error: 2.5e-4 (rmf_testing.MODULE_ALPHA) over m = 23
comparisons, Bonferroni.  Seeds: the baths rmf_testing.seed(1..4), the
water vapour, the new mode and fit_noise's synthetic runs seed(1).
"""

import math
import os
import re

import numpy as np
import pytest
from scipy import integrate, optimize, stats

from rmf import foam
from rmf_box import FILL, GAS, K, V_CELL, cloud_file, copy_box
import rmf_testing
from rmf_testing import run_failing, seed

BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "vibrationalRelaxation")
CONTROL = "system/controlDict"
MODEL = "LarsenBorgnakkeVariableSoftSphere"
COMPARISONS = 23                        # module docstring
N_SIGMA = rmf_testing.z_limit(COMPARISONS)
P_MIN = rmf_testing.MODULE_ALPHA/COMPARISONS
T_REF = 273.0
N_GAS = 1e21                            # [1/m^3]

SPECIES = {
    "N2": dict(mass=46.5e-27, d=4.17e-10, omega=0.74, zeta=2,
               modes={"stretch": 3371.0}, Zv=20.0),
    "H2O": dict(mass=2.99e-26, d=4.5e-10, omega=0.75, zeta=3,
                modes={"bend": 2294.0, "symmetric": 5261.0, "asymmetric": 5432.0},
                Zv=5.0),
}
Z_ROT = 5.0
T0 = 3000.0                             # fill temperature [K]
DT = 2e-7                               # [s]
SIMULATORS_BATH, STEPS_BATH, WRITE_BATH = 50000, 1100, 20   # 7 Z_v tau_c
K_SEEDS = 4
FINAL_WRITES = 15                       # the last 60 us: equipartition
NOISE_TRIALS = 40
# internalE and iDof against the sums of the parcels: v1912's k is CODATA
# 2014's 1.38064852e-23 J/K, K here 2019's 1.380649e-23 (3.5e-7 apart)
FIELD_TOLERANCE = 1e-6
SIMULATORS_EQ, STEPS_EQ = 50000, 300


def make(name, species, seed, simulators, steps, write, extra=()):
    """The box with one species, its modes and the Larsen-Borgnakke model,
    filled at T0, writing every `write` steps."""
    s = SPECIES[species]
    case = copy_box(os.path.join(BUILD, name), "N2", N_GAS)
    for path in ("constant/grainsProperties", "system/grainsInitialiseDict"):
        os.remove(os.path.join(case, path))
    if species != "N2":
        foam.set_entry(case, GAS, f"moleculeProperties/{species}",
                       foam.get_entry(case, GAS, "moleculeProperties/N2"))
        foam.set_entry(case, GAS, "typeIdList", f"({species})")
        foam.remove_entry(case, FILL, "numberDensities/N2")
    modes = " ".join(f"{m} {{ temperature {t:g}; }}" for m, t in s["modes"].items())
    props = f"moleculeProperties/{species}"
    entries = (("BinaryCollisionModel", MODEL),
                         (f"{MODEL}Coeffs", f"{{ Tref {T_REF:g}; alpha {{ {species} 1; }}"
                                            f" relaxationCollisionNumber {Z_ROT:g}; }}"),
                         ("nEquivalentParticles", f"{N_GAS*V_CELL/simulators:.17g}"),
                         ("randomSeed", seed),
                         (f"{props}/mass", s["mass"]), (f"{props}/diameter", s["d"]),
                         (f"{props}/omega", s["omega"]),
                         (f"{props}/internalDegreesOfFreedom", s["zeta"]),
                         (f"{props}/vibrationalModes", f"{{ {modes} }}"),
                         (f"{props}/vibrationalRelaxationCollisionNumber", s["Zv"]))
    for entry, value in entries + tuple(extra):
        foam.set_entry(case, GAS, entry, value)
    foam.set_entry(case, FILL, f"numberDensities/{species}", f"{N_GAS:g}")
    foam.set_entry(case, FILL, "randomSeed", seed)
    foam.set_entry(case, FILL, "temperature", T0)
    foam.set_entry(case, CONTROL, "deltaT", DT)
    foam.set_entry(case, CONTROL, "endTime", f"{steps*DT:.6g}")
    foam.set_entry(case, CONTROL, "writeInterval", write)
    foam.set_entry(case, CONTROL, "functions",
                   "{ vibrationalT { type gasVibrationalT; writeControl writeTime; } }")
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case



def state(case, time, species):
    """(T_tr, mean rotational energy over k, mean level of each oscillator)
    of the simulators at a written time."""
    s = SPECIES[species]
    U = foam.read_list(cloud_file(case, time, "U"))
    Ei = foam.read_list(cloud_file(case, time, "Ei"))
    levels = np.array([foam.read_list(cloud_file(case, time, f"vibLevel{k}"))
                       for k in range(len(s["modes"]))])
    T_tr = s["mass"]*U.var(axis=0).sum()/(3*K)
    return T_tr, Ei.mean()/K, levels


def equilibrium_level(theta, T):
    """Mean level of a harmonic oscillator at T."""
    return 1/math.expm1(theta/T)


def collision_time(species, T):
    """VHS mean collision time at T (Bird 1994 eq. 4.64) [s]."""
    s = SPECIES[species]
    return 1/(4*N_GAS*s["d"]**2*math.sqrt(math.pi*K*T_REF/s["mass"])
              * (T/T_REF)**(1 - s["omega"]))


def landau_teller(t, T_tr, start, theta, Zv):
    """Mean level at times t by the Landau-Teller law with T_tr(t)."""
    def rate(time, a):
        T = np.interp(time, t, T_tr)
        return [(equilibrium_level(theta, T) - a[0])/(Zv*collision_time("N2", T))]
    sol = integrate.solve_ivp(rate, (t[0], t[-1]), [start], t_eval=t,
                              rtol=1e-8, atol=1e-12)
    return sol.y[0]


def fit_Zv(t, T_tr, level, theta):
    """Z_v of the Landau-Teller law integrated with the run's T_tr(t),
    least squares against its mean level(t) (level(0) as the start)."""
    res = optimize.minimize_scalar(
        lambda z: ((landau_teller(t, T_tr, level[0], theta, z) - level)**2).sum(),
        bounds=(1, 200), method="bounded", options={"xatol": 1e-4})
    return res.x


def fit_noise(t, T_tr, theta, Zv, n, trials, rng):
    """Standard deviation of fit_Zv from the thermal noise of the mean
    level alone, independent of the code: synthetic runs of the law plus
    a fluctuation of the variance of N geometric levels, a (1 + a)/N (0 at
    the start, where every level is 0), relaxing at the law's own rate
    (an Ornstein-Uhlenbeck process, Onsager's regression), each fitted as
    the run is."""
    a = landau_teller(t, T_tr, 0.0, theta, Zv)
    var = a*(1 + a)/n
    tau = Zv*np.array([collision_time("N2", T) for T in T_tr])
    fits = []
    for _ in range(trials):
        x = np.zeros_like(a)
        for i in range(1, len(t)):
            rho = math.exp(-(t[i] - t[i - 1])/tau[i])
            x[i] = rho*x[i - 1] + math.sqrt(max(var[i] - rho**2*var[i - 1], 0))*rng.normal()
        fits.append(fit_Zv(t, T_tr, a + x, theta))
    return float(np.std(fits, ddof=1))


def heat_bath(k):
    """Run k of the nitrogen heat bath (seed(k)): (times, T_tr, T_rot,
    mean level) at every write."""
    case = make(f"bath{k}", "N2", seed(k), SIMULATORS_BATH, STEPS_BATH, WRITE_BATH)
    path = cloud_file(case, "0", "vibLevel0")
    foam.write_list(path, np.zeros_like(foam.read_list(path)))
    foam.run(case, "rarefiedMultiphaseFoam")
    out = []
    for time in foam.times(case):
        T_tr, e_rot, levels = state(case, time, "N2")
        out.append((float(time), T_tr, e_rot, levels[0].mean()))
    return np.array(out).T


@pytest.fixture(scope="module")
def baths():
    from concurrent.futures import ThreadPoolExecutor
    with ThreadPoolExecutor(2) as pool:
        return list(pool.map(heat_bath, range(1, K_SEEDS + 1)))


def test_relaxation_time(baths):
    """Fitted Z_v of the Landau-Teller law against the input: the mean over
    the seeds within t_limit(NOISE_TRIALS - 1) standard errors, the error
    of one fit from fit_noise (NOISE_TRIALS synthetic runs, seed(1))."""
    theta = SPECIES["N2"]["modes"]["stretch"]
    Z = SPECIES["N2"]["Zv"]
    Zv = np.array([fit_Zv(t, T_tr, level, theta) for t, T_tr, _, level in baths])
    t, T_tr = baths[0][0], baths[0][1]
    sd = fit_noise(t, T_tr, theta, Z, SIMULATORS_BATH, NOISE_TRIALS,
                   np.random.default_rng(seed(1)))
    se = sd/math.sqrt(len(Zv))
    limit = rmf_testing.t_limit(NOISE_TRIALS - 1, COMPARISONS)
    ok = abs(Zv.mean() - Z) <= limit*se
    print(f"\n{'PASS' if ok else 'FAIL'} N2 heat bath: fitted Z_v {Zv.mean():.3f} "
          f"(seeds {np.round(Zv, 3)}, their sd {Zv.std(ddof=1):.3f}), input {Z:g}: "
          f"{100*(Zv.mean()/Z - 1):+.2f} %; one fit's noise (computed) {sd:.3f}, "
          f"limit {limit:.2f} se = {100*limit*se/Z:.2f} %")
    assert ok


def final_temperature(T_tr0, T_rot0, theta):
    """The temperature that shares the start's energy (translation,
    rotation, vibration at level 0) at equipartition."""
    e = 1.5*T_tr0 + T_rot0
    return optimize.brentq(lambda T: 2.5*T + theta*equilibrium_level(theta, T) - e,
                           100, e)


def test_equipartition(baths):
    """At the end T_tr, T_rot and T_vib equal the temperature that shares
    the energy, each within N_SIGMA of its thermal noise: T sqrt(2/(3N)),
    T sqrt(2/(zeta N)) and sqrt(a(1 + a)/N) dT_v/da (the level's variance
    at equilibrium), for one snapshot (an average over the last writes is
    no noisier)."""
    theta = SPECIES["N2"]["modes"]["stretch"]
    N = SIMULATORS_BATH
    ok = True
    for k, (t, T_tr, e_rot, level) in enumerate(baths, 1):
        Tf = final_temperature(T_tr[0], e_rot[0], theta)
        a = level[-FINAL_WRITES:].mean()
        T_v = theta/math.log1p(1/a)
        dTda = theta/math.log1p(1/a)**2/(a*(1 + a))
        values = {"T_tr": (T_tr[-FINAL_WRITES:].mean(), Tf*math.sqrt(2/(3*N))),
                  "T_rot": (e_rot[-FINAL_WRITES:].mean(), Tf*math.sqrt(1/N)),
                  "T_vib": (T_v, math.sqrt(a*(1 + a)/N)*dTda)}
        dev = {k: (v - Tf)/sigma for k, (v, sigma) in values.items()}
        good = all(abs(d) <= N_SIGMA for d in dev.values())
        print(f"\n{'PASS' if good else 'FAIL'} N2 heat bath {k}: equipartition "
              f"at {Tf:.1f} K: " + ", ".join(
                  f"{k} {values[k][0]:.1f} ({dev[k]:+.2f} sigma)" for k in values))
        ok &= good
    assert ok


def test_fields_include_vibration(baths):
    """The sampled fields of seed 1's bath at every write: internalE is
    W/V sum (E_rot + k theta i) and iDof W/V sum (zeta_rot + 2 a
    ln(1 + 1/a)), a the cell's mean level (to FIELD_TOLERANCE: the same
    sums, with the code's Boltzmann constant); the overall temperature dsmcFields
    makes of them, 2 (E_thermal + internalE)/(k (3 rhoN + iDof)), is at the
    energy-sharing temperature at the end (the mean of the last writes
    within N_SIGMA sigma, sigma = T sqrt(2/(3N)) the translational noise of one
    write; while the vibration is cold it is higher: zeta_v is near 0); and
    vibrationalT.gas (the mean since the previous write) agrees with T_vib
    of the mean level over the last writes within N_SIGMA of the level's
    noise."""
    s = SPECIES["N2"]
    theta = s["modes"]["stretch"]
    case = os.path.join(BUILD, "bath1")
    W, N = N_GAS*V_CELL/SIMULATORS_BATH, SIMULATORS_BATH
    t, T_tr, e_rot, level = baths[0]
    Tf = final_temperature(T_tr[0], e_rot[0], theta)
    worst, overall = 0.0, []
    for time in foam.times(case)[1:]:
        def field(name):
            return foam.read_field(os.path.join(case, time, name), 1)[0]
        Ei = foam.read_list(cloud_file(case, time, "Ei"))
        lv = foam.read_list(cloud_file(case, time, "vibLevel0"))
        a = lv.mean()
        internal = W/V_CELL*(Ei.sum() + K*theta*lv.sum())
        dof = W/V_CELL*len(lv)*(s["zeta"] + (2*a*math.log1p(1/a) if a > 0 else 0))
        worst = max(worst, abs(field("internalE")/internal - 1), abs(field("iDof")/dof - 1))
        rhoN, rhoM = field("rhoN"), field("rhoM")
        thermal = field("linearKE") - 0.5*(np.asarray(field("momentum"))**2).sum()/rhoM
        overall.append(2*(thermal + field("internalE"))/(K*(3*rhoN + field("iDof"))))
    overall = np.array(overall)
    sigma = Tf*math.sqrt(2/(3*N))
    dev_overall = (overall - Tf)/sigma
    a_end = level[-FINAL_WRITES:].mean()
    T_written = foam.read_field(os.path.join(case, foam.times(case)[-1], "vibrationalT.gas"), 1)[0]
    T_levels = theta/math.log1p(1/a_end)
    sigma_v = math.sqrt(a_end*(1 + a_end)/N)*theta/math.log1p(1/a_end)**2/(a_end*(1 + a_end))
    ok = (worst < FIELD_TOLERANCE and abs(dev_overall[-FINAL_WRITES:].mean()) <= N_SIGMA
          and abs(T_written - T_levels) <= N_SIGMA*sigma_v)
    print(f"\n{'PASS' if ok else 'FAIL'} N2 heat bath fields: internalE and iDof with the "
          f"vibration to {worst:.1e}; overall T from {overall[0]:.1f} K to "
          f"{overall[-FINAL_WRITES:].mean():.1f} K at the end against {Tf:.1f} K "
          f"({dev_overall[-FINAL_WRITES:].mean():+.2f} sigma); vibrationalT.gas "
          f"{T_written:.1f} K against {T_levels:.1f} K from the levels (sigma {sigma_v:.1f})")
    assert ok


def test_equilibrium_populations():
    """Water vapour at 3000 K: each mode's final level populations on the
    Boltzmann distribution (chi-square p-value above P_MIN), after most
    levels have changed."""
    s = SPECIES["H2O"]
    case = make("equilibrium", "H2O", seed(1), SIMULATORS_EQ, STEPS_EQ, STEPS_EQ)
    foam.run(case, "rarefiedMultiphaseFoam")
    start, end = foam.times(case)[0], foam.times(case)[-1]
    T_tr, _, levels = state(case, end, "H2O")
    _, _, levels0 = state(case, start, "H2O")
    ok = True
    for k, (mode, theta) in enumerate(s["modes"].items()):
        q = math.exp(-theta/T0)
        counts = np.bincount(levels[k].astype(int))
        n = len(levels[k])
        expected = n*(1 - q)*q**np.arange(len(counts) + 50)
        # Classes: levels 0.. while each expects >= 20, the rest pooled
        top = int(np.argmax(expected < 20))
        observed = np.append(counts[:top], counts[top:].sum())
        expect = np.append(expected[:top], n - expected[:top].sum())
        chi2 = ((observed - expect)**2/expect).sum()
        p = stats.chi2.sf(chi2, len(observed) - 1)
        changed = (levels[k] != levels0[k]).mean()
        decorrelated = 2*q/(1 + q)      # 1 - sum P(i)^2: a fresh draw differs
        T_v = theta/math.log1p(1/levels[k].mean())
        good = p > P_MIN and changed > 0.9*decorrelated
        print(f"\n{'PASS' if good else 'FAIL'} H2O {mode} ({theta:g} K) at {T0:g} K: "
              f"chi2 {chi2:.2f} for {len(observed) - 1} dof (p {p:.3f}), "
              f"T_vib {T_v:.0f} K, levels changed {100*changed:.1f} % (independent draws "
              f"{100*decorrelated:.1f} %)")
        ok &= good
    print(f"  T_tr at the end {T_tr:.1f} K")
    assert ok


def test_levels_drawn_for_a_new_mode():
    """A case filled with nitrogen's one mode, then given a second
    (theta 1000 K) before the solver starts: the simulators are read
    without all their levels, so every level is drawn again at the cell's
    translational temperature (logged).  After one step the new
    oscillator's mean level is its equilibrium at T0 within N_SIGMA,
    sigma = sqrt(a (1 + a)/N) (the mean of N geometric levels), and the
    first keeps its equilibrium too."""
    case = make("newMode", "N2", seed(1), SIMULATORS_EQ, 1, 1)
    n = foam.list_size(cloud_file(case, "0", "U"))     # the fill's count
    foam.set_entry(case, GAS, "moleculeProperties/N2/vibrationalModes",
                   "{ stretch { temperature 3371; } second { temperature 1000; } }")
    log = foam.run(case, "rarefiedMultiphaseFoam")
    with open(log) as f:
        drawn = re.search(r"temperature for (\d+) simulators read without them", f.read())
    end = foam.times(case)[-1]
    ok = drawn is not None and int(drawn.group(1)) == n
    texts = []
    for k, theta in enumerate((3371.0, 1000.0)):
        levels = foam.read_list(cloud_file(case, end, f"vibLevel{k}"))
        a, expected = levels.mean(), equilibrium_level(theta, T0)
        sigma = math.sqrt(expected*(1 + expected)/len(levels))
        ok &= len(levels) == n and abs(a - expected) <= N_SIGMA*sigma
        texts.append(f"oscillator {k} ({theta:g} K) mean level {a:.4f} against "
                     f"{expected:.4f} ({N_SIGMA:.2f} sigma {N_SIGMA*sigma:.4f})")
    print(f"\n{'PASS' if ok else 'FAIL'} levels drawn for "
          f"{drawn.group(1) if drawn else 'no'} of {n} simulators read without them; "
          + "; ".join(texts))
    assert ok


# Bad input: FatalIOError naming the file, keyword, value and valid range

PROPS = "moleculeProperties/N2"
BAD = [
    ("thetaZero", f"{PROPS}/vibrationalModes/stretch/temperature", "0",
     ("temperature", "0", "(0, inf)")),
    ("thetaNegative", f"{PROPS}/vibrationalModes/stretch/temperature", "-3371",
     ("temperature", "-3371", "(0, inf)")),
    ("degeneracy", f"{PROPS}/vibrationalModes/stretch/degeneracy", "0",
     ("degeneracy", "0", "[1, 10]")),
    ("degeneracyFraction", f"{PROPS}/vibrationalModes/stretch/degeneracy", "1.5",
     ("degeneracy", "1.5")),
    ("modeNotDict", f"{PROPS}/vibrationalModes/stretch", "3371",
     ("stretch", "3371", "temperature")),
    ("noModes", f"{PROPS}/vibrationalModes", "{ }", ("vibrationalModes", "one or more")),
    ("zvLow", f"{PROPS}/vibrationalRelaxationCollisionNumber", "0.5",
     ("vibrationalRelaxationCollisionNumber", "0.5", "[1, inf)")),
    ("model", "BinaryCollisionModel", "VariableHardSphere",
     ("BinaryCollisionModel", "VariableHardSphere", "vibrationalModes",
      "LarsenBorgnakkeVariableSoftSphere")),
]


@pytest.fixture(scope="module")
def meshed():
    return make("meshed", "N2", 1, 1000, 1, 1)


@pytest.mark.parametrize("name, entry, value, texts", BAD, ids=[b[0] for b in BAD])
def test_bad_input(meshed, name, entry, value, texts):
    case = foam.copy_case(meshed, os.path.join(BUILD, name))
    foam.set_entry(case, GAS, entry, value)
    if name == "model":
        foam.set_entry(case, GAS, "VariableHardSphereCoeffs", "{ Tref 273; }")
    out = run_failing(case, "rarefiedMultiphaseFoam")
    for text in ("FOAM FATAL IO ERROR", "constant/dsmcProperties") + texts:
        assert text in out, (text, out[-1500:])


@pytest.mark.parametrize("name", ["missingZv", "zvAlone"])
def test_bad_relaxation_number(meshed, name):
    """The relaxation number is required with modes, refused without."""
    case = foam.copy_case(meshed, os.path.join(BUILD, name))
    if name == "missingZv":
        foam.remove_entry(case, GAS, f"{PROPS}/vibrationalRelaxationCollisionNumber")
        texts = ("vibrationalRelaxationCollisionNumber", "missing")
    else:
        foam.remove_entry(case, GAS, f"{PROPS}/vibrationalModes")
        texts = ("vibrationalRelaxationCollisionNumber", "20", "vibrationalModes")
    out = run_failing(case, "rarefiedMultiphaseFoam")
    for text in ("FOAM FATAL IO ERROR", "constant/dsmcProperties") + texts:
        assert text in out, (text, out[-1500:])
