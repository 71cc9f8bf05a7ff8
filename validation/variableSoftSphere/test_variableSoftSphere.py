# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The variable soft sphere (VSS, doc/physics.md#vss) in the one-cell
periodic gas box of validation/freeMolecularCoupling (testing/rmf_box.py),
argon at 1e20 m^-3 and 273 K (Koura and Matsumoto's VSS data: d =
4.11e-10 m at 273 K, omega 0.81, alpha 1.40; the VHS control: Bird's
d = 4.17e-10 m, the same omega).  Steps of 2 us, a 17th of the mean
collision time.

1. Equilibrium collision rate.  The VSS keeps the VHS total cross-section,
   so the collisions per step in the cell are
       C = N (N - 1)/2 W <sigma_T c_r> dt/V,
       <sigma_T c_r> = 4 d^2 (pi k T_ref/m)^(1/2) (T/T_ref)^(1 - omega)
   (the VHS collision rate per molecule over n), N simulators of weight W
   in the cell of volume V.  400 steps of 20 000 simulators; tolerance
   t_9 standard errors of the mean count (batch means of the log's
   counts: ten batches of 40 steps, 2.3 mean collision times, nine degrees
   of freedom; t_9 = 9.53 at the module's per-comparison error).
   Measured -0.06 % (5 se 0.9 %).

2. Viscosity.  The fill's velocities are scaled about their mean to T_x =
   1.4 T, T_y = T_z = 0.8 T; the anisotropy A = (T_x - (T_y + T_z)/2)/T
   then decays as exp(-p t/mu).  The viscosity runs use omega = 1 (OMEGA_MU;
   the same d): sigma_T c_r is then independent of c_r (pseudo-Maxwell
   molecules, for the VHS's isotropic and the VSS's scattering alike), so
   the second moments of the velocity distribution obey closed linear
   equations and the decay of A is exactly exponential at the rate p/mu
   for any amplitude, with mu the Chapman-Enskog first approximation,
   exact for these molecules (Truesdell and Muncaster 1980, ch. XVII;
   Chapman and Cowling 1970, 10.31):
       mu_VHS = 15 (m k T_ref/pi)^(1/2)/(2 (5 - 2 omega)(7 - 2 omega) d^2),
       mu_VSS = mu_VHS(d) (alpha + 1)(alpha + 2)/(6 alpha).
   The method then has no error of its own (at omega = 0.81 it had one, of
   a few %, measured only by the code: METHOD_MU, removed).  mu = p t/
   ln(A_0/A_t) over one relaxation time (28 steps), 200 000 simulators,
   seeds 1..3, against the formula within z sigma, sigma the thermal noise
   of the estimate computed from the fluctuation of A (variance 3/N,
   relaxing at the same rate), independent of the code.  Measured
   2026-12-06: VHS 1.018, VSS 1.020 of their formulas (sigma 0.92 %; the
   two models start from the same states, so their errors are alike).
   The viscosity of the VSS differs from the VHS's of the same d by 3 % at most (alpha in
   [1, 2]): this check cannot tell the scattering laws apart; the next one
   can.

3. Momentum transfer.  Two halves of the gas under two names (Ar and ArB,
   the same molecule) start with drifts +100 and -100 m/s along x; the
   drift between them decays at a rate proportional to the momentum-
   transfer cross-section sigma_T <1 - cos chi>: 2 sigma_T/(alpha + 1)
   for the VSS, sigma_T for the VHS.  The ratio of the decay rates,
   seed-paired (the same initial state), against 2/(alpha + 1)
   (d_VSS/d_VHS)^2 = 0.8095, within z sigma (thermal noise of the drift,
   variance 4 kT/(m N), computed).  Isotropic scattering would give
   0.9714, 17 sigma away.  40 steps, 200 000 simulators, seeds 1..3.
   Measured 0.8128 (sigma 0.0093).  Only Ar-ArB collisions move momentum
   between the streams, so a third variant gives the pair its own alpha
   (alphaPairs, 1.80): expected 0.6939, measured 0.6965 (sigma 0.0079).

4. Rotational exchange (LarsenBorgnakkeVariableSoftSphere, ours, against
   upstream's LarsenBorgnakkeVariableHardSphere of the same d and Z = 5):
   nitrogen (zeta = 2; and 3, as water, for the other branch of the
   energy draw) starts with its rotation cold and relaxes over 400 steps
   of 4 us (9 relaxation times), 50 000 simulators, the same initial
   state for both models.  Rotational temperatures at every write within
   z sigma of each other (sigma = T sqrt(2/(zeta N)) per run, the
   chi-square noise of zeta N/2 degrees, times sqrt 2); at the end
   T_rot = T_tr within z sigma; 3 T_tr + zeta T_rot kept to 1e-9.
   Measured: largest deviation 1.41 (zeta 2) and 1.67 sigma (zeta 3); at
   the end T_rot - T_tr = -0.6 and -1.3 sigma; energy kept to 2e-10.

5. Bad input: alpha outside [1, 2], a species without alpha, an unknown
   species in alpha or alphaPairs, Tref <= 0, Z < 1: FatalIOError naming
   the file, keyword, value and valid range or choices.

Family-wise error: 2.5e-4 (rmf_testing.MODULE_ALPHA) over m = 47
comparisons (COMPARISONS: the collision rate 1, the viscosity of the two
models 2, the two momentum-transfer ratios 2, and per zeta the 20 writes'
T_rot and the final equipartition, 42), Bonferroni: z = 4.55 (N_SIGMA =
rmf_testing.z_limit(47)) each, and t_9 = 9.53 for the batch means of 1.
Seeds: every randomSeed (the gas's and the fill's) through
rmf_testing.seed.
"""

import math
import os

import numpy as np
import pytest

from rmf import foam
from rmf_box import FILL, GAS, K, MASS, V_CELL, cloud_file, copy_box
import rmf_testing
from rmf_testing import run_failing

BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "variableSoftSphere")
CONTROL = "system/controlDict"
MODELS = ("VariableHardSphere", "VariableSoftSphere")

M = MASS["Ar"]
T0 = T_REF = 273.0                  # fill and reference temperature [K]
OMEGA, ALPHA = 0.81, 1.40
OMEGA_MU = 1.0                      # the viscosity runs': pseudo-Maxwell molecules
DIAMETER = {"VariableHardSphere": 4.17e-10, "VariableSoftSphere": 4.11e-10}
N_GAS = 1e20                        # [1/m^3]: mean collision time 35 us
DT = 2e-6                           # [s]: a 28th of mu/p

SIMULATORS_RATE, STEPS_RATE, BATCH = 20000, 400, 40
ANISOTROPY = (1.4, 0.8, 0.8)        # T_x, T_y, T_z over T at the start
SIMULATORS_MU, STEPS_MU = 200000, 28    # 28 steps: one relaxation time
DRIFT = 100.0                       # [m/s] +x for Ar, -x for ArB at the start
ALPHA_PAIR = 1.80                   # the Ar-ArB pair's own alpha (alphaPairs)
SIMULATORS_D, STEPS_D = 200000, 40
K_SEEDS = 3
Z_ROT = 5.0                         # rotational relaxation collision number
SIMULATORS_LB, STEPS_LB, WRITE_LB, DT_LB = 50000, 400, 20, 4e-6
# The module's comparisons (header, "Family-wise error")
COMPARISONS = 1 + 2 + 2 + 2*(STEPS_LB//WRITE_LB + 1)
N_SIGMA = rmf_testing.z_limit(COMPARISONS)


def mu_formula(model, temperature=T0, omega=OMEGA):
    """Chapman-Enskog viscosity, first approximation, of the model."""
    d = DIAMETER[model]
    mu = (15*math.sqrt(M*K*T_REF/math.pi)
          / (2*(5 - 2*omega)*(7 - 2*omega)*d*d)*(temperature/T_REF)**omega)
    if model == "VariableSoftSphere":
        mu *= (ALPHA + 1)*(ALPHA + 2)/(6*ALPHA)
    return mu


def sigma_cr(model, temperature=T0):
    """<sigma_T c_r> at equilibrium: the VHS collision rate over n."""
    d = DIAMETER[model]
    return 4*d*d*math.sqrt(math.pi*K*T_REF/M)*(temperature/T_REF)**(1 - OMEGA)


def make(name, model, seed, simulators, steps, species=("Ar",), diameter=None,
         write=None, extra=(), omega=OMEGA):
    """The box with argon (and ArB, the same molecule under another name,
    or the box's nitrogen) and the model, filled at T0, writing at the
    start and the end (or every `write` steps); extra: more entries of
    constant/dsmcProperties; seed k goes through rmf_testing.seed."""
    case = copy_box(os.path.join(BUILD, name), species[0], N_GAS/len(species))
    for path in ("constant/grainsProperties", "system/grainsInitialiseDict"):
        os.remove(os.path.join(case, path))
    alpha = " ".join(f"{s} {ALPHA:g};" for s in species)
    coeffs = f"Tref {T_REF:g};"
    if "SoftSphere" in model:
        coeffs += f" alpha {{ {alpha} }}"
    if model.startswith("LarsenBorgnakke"):
        coeffs += f" relaxationCollisionNumber {Z_ROT:g};"
    coeffs = f"{{ {coeffs} }}"
    ar = foam.get_entry(case, GAS, "moleculeProperties/Ar")
    for entry, value in (("BinaryCollisionModel", model), (f"{model}Coeffs", coeffs),
                         ("moleculeProperties/ArB", ar),
                         ("typeIdList", f"({' '.join(species)})"),
                         ("nEquivalentParticles", f"{N_GAS*V_CELL/simulators:.17g}"),
                         ("randomSeed", rmf_testing.seed(seed))) + tuple(extra):
        foam.set_entry(case, GAS, entry, value)
    for s in species:
        for key, value in (("diameter", diameter or DIAMETER[model]), ("omega", omega)):
            foam.set_entry(case, GAS, f"moleculeProperties/{s}/{key}", value)
        foam.set_entry(case, FILL, f"numberDensities/{s}", f"{N_GAS/len(species):g}")
    foam.set_entry(case, FILL, "randomSeed", rmf_testing.seed(seed))
    foam.set_entry(case, FILL, "temperature", T0)
    foam.set_entry(case, CONTROL, "deltaT", DT)
    foam.set_entry(case, CONTROL, "endTime", f"{steps*DT:.6g}")
    foam.set_entry(case, CONTROL, "writeInterval", write or steps)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case



def start_anisotropic(case):
    """Scale the fill's velocities about their mean: T_i -> ANISOTROPY_i T."""
    U = foam.read_list(cloud_file(case, "0", "U"))
    mean = U.mean(axis=0)
    foam.write_list(cloud_file(case, "0", "U"), mean + (U - mean)*np.sqrt(ANISOTROPY))


def start_drifting(case):
    """Ar drifts at +DRIFT along x, ArB at -DRIFT."""
    U = foam.read_list(cloud_file(case, "0", "U"))
    species = foam.read_list(cloud_file(case, "0", "typeId")).astype(int)
    U[:, 0] += np.where(species == 0, DRIFT, -DRIFT)
    foam.write_list(cloud_file(case, "0", "U"), U)


def decay(case, observable):
    """The observable of the velocities (and species) at the first and last
    written time, and the time between."""
    first, last = foam.times(case)[0], foam.times(case)[-1]
    values = [observable(foam.read_list(cloud_file(case, t, "U")),
                         foam.read_list(cloud_file(case, t, "typeId")).astype(int))
              for t in (first, last)]
    return values[0], values[1], float(last) - float(first)


def anisotropy(U, species):
    """(T_x - (T_y + T_z)/2)/T."""
    var = U.var(axis=0)
    return (var[0] - 0.5*(var[1] + var[2]))/var.mean()


def drift(U, species):
    """Mean x velocity of Ar less that of ArB."""
    return U[species == 0, 0].mean() - U[species == 1, 0].mean()


def rate_noise(x0, x1, t, variance):
    """Standard deviation of ln(x0/x1)/t from the thermal fluctuation of x
    (stationary variance `variance`, relaxing at the same rate): at the
    end the fluctuation has grown to variance (1 - (x1/x0)^2)."""
    return math.sqrt(variance*(1 - (x1/x0)**2))/x1/t


def seeds(name, prepare, start, observable, simulators, steps, variance,
          variants=None):
    """Per variant (label: model and extra entries of constant/
    dsmcProperties; default the two models as they are) and seed
    (seed-paired: the same initial state): (decay rates of the observable,
    their noise), run two at a time."""
    from concurrent.futures import ThreadPoolExecutor
    variants = variants or {m: (m, ()) for m in MODELS}

    def run(job):
        label, seed = job
        model, extra = variants[label]
        case = prepare(f"{name}_{label}{seed}", model, seed, simulators, steps,
                       extra=extra)
        start(case)
        foam.run(case, "rarefiedMultiphaseFoam")
        x0, x1, t = decay(case, observable)
        return math.log(x0/x1)/t, rate_noise(x0, x1, t, variance)

    jobs = [(v, seed) for seed in range(1, K_SEEDS + 1) for v in variants]
    with ThreadPoolExecutor(2) as pool:
        out = list(pool.map(run, jobs))
    n = len(variants)
    return {v: tuple(np.array(out[i::n]).T) for i, v in enumerate(variants)}


@pytest.fixture(scope="module")
def viscosity():
    """The anisotropy's decay rates of pseudo-Maxwell molecules (OMEGA_MU)."""
    def prepare(*args, extra=()):
        return make(*args, extra=extra, omega=OMEGA_MU)
    return seeds("mu", prepare, start_anisotropic, anisotropy, SIMULATORS_MU, STEPS_MU,
                 3/SIMULATORS_MU)


@pytest.fixture(scope="module")
def diffusion():
    """The drift's decay rates: VHS, VSS, and the VSS with the pair's own
    alpha (alphaPairs Ar { ArB ALPHA_PAIR; }: only Ar-ArB collisions
    transfer momentum between the streams)."""
    def prepare(*args, extra=()):
        return make(*args, species=("Ar", "ArB"), extra=extra)
    pair = (("VariableSoftSphereCoeffs/alphaPairs", f"{{ Ar {{ ArB {ALPHA_PAIR:g}; }} }}"),)
    variants = {"VariableHardSphere": ("VariableHardSphere", ()),
                "VariableSoftSphere": ("VariableSoftSphere", ()),
                "pairAlpha": ("VariableSoftSphere", pair)}
    return seeds("D", prepare, start_drifting, drift, SIMULATORS_D, STEPS_D,
                 K*T0/M*4/SIMULATORS_D, variants)


def test_collision_rate():
    """Collisions per step against N (N - 1)/2 W <sigma_T c_r> dt/V."""
    case = make("rate", "VariableSoftSphere", 1, SIMULATORS_RATE, STEPS_RATE)
    foam.run(case, "rarefiedMultiphaseFoam")
    log = os.path.join(case, "log.rarefiedMultiphaseFoam")
    counts = foam.log_values(log, "Collisions")[:, 0]
    n = foam.log_values(log, "Simulators present")[0, 0]
    W = N_GAS*V_CELL/SIMULATORS_RATE
    expected = 0.5*n*(n - 1)*W*sigma_cr("VariableSoftSphere")*DT/V_CELL
    batches = counts[:len(counts)//BATCH*BATCH].reshape(-1, BATCH).mean(axis=1)
    se = batches.std(ddof=1)/math.sqrt(len(batches))
    t = rmf_testing.t_limit(len(batches) - 1, COMPARISONS)
    ok = abs(counts.mean() - expected) <= t*se
    print(f"\n{'PASS' if ok else 'FAIL'} VSS equilibrium collision rate: "
          f"{counts.mean():.2f} per step, expected "
          f"{expected:.2f} ({100*(counts.mean()/expected - 1):+.3f} %; "
          f"t_{len(batches) - 1} {t:.2f} se = {t*se:.2f})")
    assert ok


def test_viscosity(viscosity):
    """Each model's mu = p/(decay rate of A) against its formula (omega =
    OMEGA_MU, where it is exact), the mean over K_SEEDS seeds within
    N_SIGMA noise."""
    p = N_GAS*K*T0
    ok = True
    for model, (rates, noise) in viscosity.items():
        mu = p/rates/mu_formula(model, omega=OMEGA_MU)
        sigma = math.sqrt((noise**2).sum())/rates.sum()
        good = abs(mu.mean() - 1) <= N_SIGMA*sigma
        print(f"\n{'PASS' if good else 'FAIL'} {model}: mu measured over formula "
              f"{mu.mean():.4f} (seeds "
              f"{np.round(mu, 4)}), limit 1 +- {N_SIGMA:.2f} x {sigma:.4f}")
        ok &= good
    assert ok


@pytest.mark.parametrize("label, alpha", [("VariableSoftSphere", ALPHA),
                                          ("pairAlpha", ALPHA_PAIR)])
def test_momentum_transfer(diffusion, label, alpha):
    """The drift between Ar and ArB decays at a rate proportional to the
    momentum-transfer cross-section of the Ar-ArB pair, sigma_T <1 - cos
    chi>: 2 sigma_T/(alpha + 1) for the VSS, sigma_T for the VHS.  The
    seed-paired ratio of the decay rates against 2/(alpha + 1)
    (d_VSS/d_VHS)^2 (the total cross-sections' ratio; the same omega),
    within N_SIGMA noise; isotropic scattering would give (d_VSS/d_VHS)^2
    alone.  alpha: the species' (1.40), or the pair's own (alphaPairs,
    1.80)."""
    (vhs, n_vhs), (vss, n_vss) = diffusion["VariableHardSphere"], diffusion[label]
    ratio = vss/vhs
    sigma = math.sqrt(((ratio*np.hypot(n_vss/vss, n_vhs/vhs))**2).sum())/len(ratio)
    d2 = (DIAMETER["VariableSoftSphere"]/DIAMETER["VariableHardSphere"])**2
    expected = 2/(alpha + 1)*d2
    ok = abs(ratio.mean() - expected) <= N_SIGMA*sigma
    print(f"\n{'PASS' if ok else 'FAIL'} VSS momentum transfer, pair alpha {alpha:g}: "
          f"drift decay rate over the "
          f"VHS's {ratio.mean():.4f} (seeds {np.round(ratio, 4)}), expected "
          f"{expected:.4f} +- {N_SIGMA:.2f} x {sigma:.4f}; isotropic scattering: {d2:.4f}")
    assert ok


def rotational_history(case, zeta):
    """Per written time after the start (whose fields are the initial
    zeros): (translational T, rotational T) of the cell."""
    out = []
    for t in foam.times(case)[1:]:
        def field(name):
            return float(foam.read_field(os.path.join(case, t, name), 1)[0])
        n = field("rhoN")
        out.append((2*field("linearKE")/(3*K*n), 2*field("internalE")/(zeta*K*n)))
    return np.array(out).T


@pytest.mark.parametrize("zeta", [2, 3])
def test_rotational_exchange(zeta):
    """LarsenBorgnakkeVariableSoftSphere against upstream's
    LarsenBorgnakkeVariableHardSphere: nitrogen (with zeta = 2, and 3 as
    water's) starts with its rotation cold; both models, of the same d and
    Z = 5 and the same initial state, relax it alike: T_rot at every write
    within N_SIGMA of each other, sigma = T sqrt(2/(zeta N)) (the chi-square
    noise of a temperature of zeta N/2 degrees, each run) times sqrt 2;
    each ends at equipartition (T_rot = T_tr within N_SIGMA), and the
    energy 3 T_tr + zeta T_rot is kept (to 1e-9: elastic)."""
    models = ("LarsenBorgnakkeVariableHardSphere", "LarsenBorgnakkeVariableSoftSphere")
    from concurrent.futures import ThreadPoolExecutor

    def run(model):
        case = make(f"rotation{zeta}_{model}", model, 1, SIMULATORS_LB, STEPS_LB,
                    species=("N2",), diameter=DIAMETER["VariableHardSphere"],
                    write=WRITE_LB,
                    extra=(("moleculeProperties/N2/internalDegreesOfFreedom", zeta),))
        foam.set_entry(case, CONTROL, "deltaT", DT_LB)
        foam.set_entry(case, CONTROL, "endTime", f"{STEPS_LB*DT_LB:.6g}")
        Ei = foam.read_list(cloud_file(case, "0", "Ei"))
        foam.write_list(cloud_file(case, "0", "Ei"), np.zeros_like(Ei))
        foam.run(case, "rarefiedMultiphaseFoam")
        return rotational_history(case, zeta)

    with ThreadPoolExecutor(2) as pool:
        (tr_h, rot_h), (tr_s, rot_s) = pool.map(run, models)
    T_eq = T0*3/(3 + zeta)
    sigma = T_eq*math.sqrt(2/(zeta*SIMULATORS_LB))
    dev = (rot_s - rot_h)/(sigma*math.sqrt(2))
    energy = (3*tr_s + zeta*rot_s)/(3 + zeta)
    final = (rot_s[-1] - tr_s[-1])/(sigma*math.sqrt(1 + zeta/3))
    ok = (abs(dev).max() <= N_SIGMA and abs(final) <= N_SIGMA
          and abs(energy/energy[0] - 1).max() < 1e-9)
    print(f"\n{'PASS' if ok else 'FAIL'} rotational exchange, zeta {zeta}: T_rot VSS "
          f"{np.round(rot_s, 1)}\n"
          f"          T_rot VHS {np.round(rot_h, 1)}\n"
          f"  largest |dev| {abs(dev).max():.2f} sigma (sigma {sigma:.2f} K); at the end "
          f"T_rot - T_tr = {rot_s[-1] - tr_s[-1]:+.2f} K ({final:+.2f} sigma), "
          f"equilibrium {T_eq:.2f} K; energy kept to "
          f"{abs(energy/energy[0] - 1).max():.1e}")
    assert ok


# Bad input: FatalIOError naming the file, keyword, value and valid range

BAD = [
    ("alphaLow", "VariableSoftSphereCoeffs/alpha/Ar", "0.8", ("Ar", "0.8", "[1, 2]")),
    ("alphaHigh", "VariableSoftSphereCoeffs/alpha/Ar", "2.5", ("Ar", "2.5", "[1, 2]")),
    ("alphaMissing", "VariableSoftSphereCoeffs/alpha", "{ }", ("Ar", "missing")),
    ("alphaUnknown", "VariableSoftSphereCoeffs/alpha", "{ Ar 1.4; Xe 1.4; }",
     ("alpha", "Xe", "Ar")),
    ("pairUnknown", "VariableSoftSphereCoeffs/alphaPairs", "{ Ar { Kr 1.3; } }",
     ("Kr", "Ar")),
    ("pairHigh", "VariableSoftSphereCoeffs/alphaPairs", "{ Ar { Ar 3; } }",
     ("Ar", "3", "[1, 2]")),
    ("tref", "VariableSoftSphereCoeffs/Tref", "-273", ("Tref", "-273", "(0, inf)")),
]


@pytest.fixture(scope="module")
def meshed():
    return make("meshed", "VariableSoftSphere", 1, 1000, 1)


@pytest.mark.parametrize("name, entry, value, texts", BAD, ids=[b[0] for b in BAD])
def test_bad_input(meshed, name, entry, value, texts):
    case = foam.copy_case(meshed, os.path.join(BUILD, name))
    foam.set_entry(case, GAS, entry, value)
    out = run_failing(case, "rarefiedMultiphaseFoam")
    for text in ("FOAM FATAL IO ERROR", "constant/dsmcProperties") + texts:
        assert text in out, (text, out[-1500:])


def test_bad_relaxation_number(meshed):
    """The Larsen-Borgnakke form needs Z >= 1."""
    case = foam.copy_case(meshed, os.path.join(BUILD, "relaxation"))
    foam.set_entry(case, GAS, "BinaryCollisionModel", "LarsenBorgnakkeVariableSoftSphere")
    foam.set_entry(case, GAS, "LarsenBorgnakkeVariableSoftSphereCoeffs",
                   "{ Tref 273; alpha { Ar 1.4; } relaxationCollisionNumber 0.5; }")
    out = run_failing(case, "rarefiedMultiphaseFoam")
    for text in ("FOAM FATAL IO ERROR", "constant/dsmcProperties",
                 "relaxationCollisionNumber", "0.5", "[1, inf)"):
        assert text in out, (text, out[-1500:])
