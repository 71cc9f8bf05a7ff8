# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Loth coupling and the adaptive switch (
doc/physics.md#loth, #adaptive), end to end on the solver.

1. interphaseCoupling Loth with a prescribed uniform gas, no DSMC (no
   constant/dsmcProperties): one light grain released at rest in a
   uniform stream (validation/freeMolecularCoupling/box's mesh, scaled to
   a 1 m periodic cell so that the grain never leaves it, and its
   grainsProperties with a light grain: rho_p = 1000 kg/m^3,
   c_p = 1000 J/kg/K, T_p0 = 200 K; gas: argon-like, T = 300 K,
   R = k/m(Ar) = 208.24 J/kg/K, gamma = 5/3, mu = 2.27e-5 Pa s, Pr by
   Eucken = 2/3).  The parcel's velocity and temperature at every write
   against:
   a) Stokes regime (rho_g = 1 kg/m^3, |U| = 1e-3 m/s, d = 100 um: Re <=
      4.4e-3, Kn = 1.1e-3, Ma ~ 3e-6): the analytic exponential
      v = U (1 - exp(-t/tau)), tau = rho_p d^2/(18 mu).  Loth's C_D
      exceeds 24/Re by the factor (1 + 0.15 Re^0.687) f_Kn, here within
      0.4 % and 0.3 % of 1, so the velocity may differ from the
      exponential by at most ~0.6 %/e ~ 0.25 % of U: tolerance 0.5 % of U.
   b) Both regimes' ODE, integrated independently here (RK4, 50 substeps
      per solver step) with rmf.kinetic's Loth C_D and
      the Nusselt number written out below from dragLaws.H's formulas:
          dv/dt = (3/4) C_D rho_g |U - v| (U - v)/(rho_p d),
          dT/dt = Nu pi d kappa (T_g - T)/(m_p c_p),  kappa = mu c_p,g/Pr,
      for (a) and for a rarefied, compressible case (rho_g = 0.282
      kg/m^3, |U| = 161 m/s (Ma = 0.5), d = 10 um: Re from 20 down, Kn =
      0.04).  The solver freezes C_D and Nu over a step and relaxes
      exactly (LothCoupling.H): a first-order error in dt/tau, with
      dt = tau/100 here; tolerance 0.5 % of |U| and of T_g - T_p0.
2. Bad input: gas not dsmc or prescribed, gamma > 5/3, mu <= 0, and a
   model needing gas (oneWay) in a case without gas: FatalIOError naming
   file, keyword and value.
3. Loth with gas dsmc: the force on a held grain in a drifting argon cell
   equals Loth's at the cell's realized state (test_loth_from_dsmc).
4. adaptive: regime fractions (log and fields) for two grains on either
   side of KnSwitch, and KnSwitch / averagingSteps input checks.
5. Loth with the prescribed gas as a table (prescribedGas): relaxation to
   the state interpolated at the grain's position (inline table, and a
   table file with outOfBounds clamp), a grain outside the table (error),
   and bad tables (unsorted, column count, rho/T/mu <= 0, one row,
   coordinate, outOfBounds, missing file).
"""

import math
import os
import shutil
import subprocess

import numpy as np
import pytest

from rmf import foam
from rmf.kinetic import loth_cd, loth_cl, nusselt
from rmf_testing import run_failing

HERE = os.path.dirname(os.path.abspath(__file__))
BOX = os.path.join(foam.PROJECT_DIR, "validation", "freeMolecularCoupling", "box")
BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "lothCoupling")
PROPS = "constant/grainsProperties"
CONTROL = "system/controlDict"

K = 1.380649e-23
R_AR = K/66.3e-27
GAMMA = 5/3
T_G = 300.0
MU = 2.27e-5
PR = 4*GAMMA/(9*GAMMA - 5)
RHO_P, CP_P, T_P0 = 1000.0, 1000.0, 200.0
TOL = 0.005


def make_case(name, rho_g, U, d, dt, steps, write_every, coupling="Loth", edit=None):
    """The box without gas, one grain of diameter d at rest, Loth with a
    prescribed uniform gas (U along x); edit(case), if given, changes the
    set-up before meshing and initialising."""
    case = foam.copy_setup(BOX, os.path.join(BUILD, name))
    os.remove(os.path.join(case, "constant", "dsmcProperties"))
    os.remove(os.path.join(case, "system", "dsmcInitialiseDict"))
    foam.set_entry(case, "system/blockMeshDict", "scale", 0.1)
    foam.set_entry(case, "system/grainsInitialiseDict", "regions/grain/d", d)
    foam.set_entry(case, PROPS, "constantProperties/rho0", RHO_P)
    foam.set_entry(case, PROPS, "constantProperties/Cp0", CP_P)
    foam.set_entry(case, PROPS, "constantProperties/T0", T_P0)
    foam.set_entry(case, PROPS, "subModels/interphaseCoupling", coupling)
    coeffs = "subModels/LothCoeffs/"
    foam.set_entry(case, PROPS, "subModels/LothCoeffs", "{}")
    foam.set_entry(case, PROPS, coeffs + "gas", "prescribed")
    foam.set_entry(case, PROPS, coeffs + "prescribed", "{}")
    for key, value in (("rho", rho_g), ("U", f"({U:.9g} 0 0)"), ("T", T_G),
                       ("mu", MU), ("gamma", f"{GAMMA:.12g}"), ("R", f"{R_AR:.9g}")):
        foam.set_entry(case, PROPS, coeffs + "prescribed/" + key, value)
    foam.set_entry(case, CONTROL, "deltaT", f"{dt:.9g}")
    foam.set_entry(case, CONTROL, "endTime", f"{steps*dt:.9g}")
    foam.set_entry(case, CONTROL, "writeInterval", write_every)
    if edit:
        edit(case)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case


def single(path):
    """The value of a one-parcel field file, which OpenFOAM writes inline:
    1(value) or 1((x y z))."""
    values = foam.read_list(path)
    assert len(values) == 1, path
    return [float(x) for x in values.ravel()]


def trajectory(case):
    """(t, v_x, T_p) of the single parcel at every write time > 0."""
    rows = []
    for t in foam.times(case):
        if float(t) > 0:
            base = os.path.join(case, t, "lagrangian", "grains")
            U = single(os.path.join(base, "U"))
            T = single(os.path.join(base, "T"))
            rows.append((float(t), U[0], T[0]))
    return np.array(rows)


def integrate(rho_g, U, d, t_end, n, T_g=T_G, mu=MU):
    """RK4 of (v, T_p) from (0, T_P0) to t_end in n steps, gas (rho_g, U
    along x, T_g, mu); returns a function of t by linear interpolation on
    the fine grid."""
    mp = RHO_P*math.pi*d**3/6
    kappa = mu*GAMMA*R_AR/((GAMMA - 1)*PR)
    kn = mu/(rho_g*d)*math.sqrt(math.pi/(2*R_AR*T_g))

    def rhs(y):
        v, T = y
        v0 = U - v
        re = rho_g*abs(v0)*d/mu
        ma = abs(v0)/math.sqrt(GAMMA*R_AR*T_g)
        dv = 0.75*loth_cd(re, ma, GAMMA, T/T_g)*rho_g*abs(v0)*v0/(RHO_P*d) if re > 0 else 0
        dT = nusselt(re, kn, GAMMA, PR)*math.pi*d*kappa*(T_g - T)/(mp*CP_P)
        return np.array([dv, dT])

    h = t_end/n
    ts = np.linspace(0, t_end, n + 1)
    ys = np.empty((n + 1, 2))
    y = np.array([0.0, T_P0])
    ys[0] = y
    for i in range(n):
        k1 = rhs(y)
        k2 = rhs(y + 0.5*h*k1)
        k3 = rhs(y + 0.5*h*k2)
        k4 = rhs(y + h*k3)
        y = y + h/6*(k1 + 2*k2 + 2*k3 + k4)
        ys[i + 1] = y
    return lambda t: (np.interp(t, ts, ys[:, 0]), np.interp(t, ts, ys[:, 1]))


CASES = {
    # name: rho_g, |U|, d, deltaT, steps, write every
    "stokes": (1.0, 1e-3, 1e-4, 2.5e-4, 500, 25),
    "rarefiedCompressible": (0.282, 0.5*math.sqrt(GAMMA*R_AR*T_G), 1e-5, 1.2e-6, 600, 20),
}


def check_against_ode(case, what, rho_g, U, d, dt, steps, every, T_g=T_G, mu=MU):
    """Run case; its parcel's trajectory against integrate() for the gas
    (rho_g, U, T_g, mu): largest differences below TOL of U and of
    T_g - T_p0.  Returns (t, v) of the run."""
    foam.run(case, "rarefiedMultiphaseFoam")
    traj = trajectory(case)
    assert len(traj) == steps//every, len(traj)
    t, v, T = traj.T

    ode = integrate(rho_g, U, d, steps*dt, 50*steps, T_g=T_g, mu=mu)
    v_ode, T_ode = ode(t)
    err_v = np.abs(v - v_ode).max()/U
    err_T = np.abs(T - T_ode).max()/(T_g - T_P0)
    ok = err_v < TOL and err_T < TOL
    print(f"\n{'PASS' if ok else 'FAIL'} {what}: v/U at the end "
          f"{v[-1]/U:.5f} (ODE {v_ode[-1]/U:.5f}), T_p {T[-1]:.3f} K (ODE "
          f"{T_ode[-1]:.3f} K); largest difference {100*err_v:.3f} % of U, "
          f"{100*err_T:.3f} % of T_g - T_p0 (tolerance {100*TOL:g} %)")
    assert err_v < TOL, err_v
    assert err_T < TOL, err_T
    return t, v


@pytest.mark.parametrize("name", list(CASES))
def test_relaxation(name):
    rho_g, U, d, dt, steps, every = CASES[name]
    case = make_case(name, rho_g, U, d, dt, steps, every)
    t, v = check_against_ode(case, f"Loth relaxation, {name}", rho_g, U, d, dt, steps, every)

    if name == "stokes":
        tau = RHO_P*d**2/(18*MU)
        v_exact = U*(1 - np.exp(-t/tau))
        err = np.abs(v - v_exact).max()/U
        ok = err < TOL
        print(f"{'PASS' if ok else 'FAIL'} Stokes exponential (tau = {tau:.5g} s): largest "
              f"difference {100*err:.3f} % of U (tolerance {100*TOL:g} %)")
        assert err < TOL, err


# ---------------------------------------------------------------------------
# Prescribed gas as a table (prescribedGas)

# Rows (y rho Ux Uy Uz T mu) around the grain, which sits at y = 0.2 in the
# one cell (centre y = 0): the state there is half-way between the last two
# rows, far from the cell centre's (second row), so evaluating at the cell
# centre instead of the parcel would fail by ~15 %.
TABLE = [(-0.4, 0.10, 100.0, 0, 0, 250.0, 2.0e-5),
         (0.0, 0.20, 150.0, 0, 0, 280.0, 2.2e-5),
         (0.4, 0.40, 200.0, 0, 0, 340.0, 2.5e-5)]
Y_GRAIN = 0.2


def table_text(rows):
    return "(" + " ".join("(" + " ".join(f"{v:.9g}" for v in r) + ")" for r in rows) + ")"


def use_table(case, rows, coordinate="y", inline=True, extra=()):
    """Replace the uniform prescribed state of case by a table (mu a 7th
    column when the rows have 7 entries), the grain placed at y = 0.2."""
    pre = "subModels/LothCoeffs/prescribed/"
    for key in ("rho", "U", "T") + (("mu",) if len(rows[0]) == 7 else ()):
        subprocess.run(["foamDictionary", "-entry", pre + key, "-remove", PROPS],
                       cwd=case, check=True, stdout=subprocess.DEVNULL)
    foam.set_entry(case, PROPS, pre + "coordinate", coordinate)
    if inline:
        foam.set_entry(case, PROPS, pre + "table", table_text(rows))
    else:
        with open(os.path.join(case, "constant", "gasTable"), "w") as f:
            f.write("// y rho Ux Uy Uz T mu\n" + table_text(rows).replace(") (", ")\n(") + "\n")
        foam.set_entry(case, PROPS, pre + "file", '"$FOAM_CASE/constant/gasTable"')
    for key, value in extra:
        foam.set_entry(case, PROPS, pre + key, value)


def place_grain(case, y):
    init = "system/grainsInitialiseDict"
    foam.set_entry(case, init, "regions/grain/min", f"(-1e-5 {y - 1e-5:.9g} -1e-5)")
    foam.set_entry(case, init, "regions/grain/max", f"(1e-5 {y + 1e-5:.9g} 1e-5)")


def table_case(name, rows, inline=True, extra=()):
    """rarefiedCompressible's set-up (d = 10 um, dt = 1.2e-6 s, 600 steps)
    with the grain at y = 0.2 and the gas from a table in y."""
    _, _, d, dt, steps, every = CASES["rarefiedCompressible"]

    def edit(case):
        place_grain(case, Y_GRAIN)
        use_table(case, rows, inline=inline, extra=extra)

    return make_case(name, 1.0, 1.0, d, dt, steps, every, edit=edit)


@pytest.mark.parametrize("variant", ["inline", "file_clamped"])
def test_prescribed_table(variant):
    """A grain released at rest at y = 0.2 in a gas tabulated in y (rho, U
    along x, T and mu all varying) moves along x only, so it relaxes to
    the state interpolated at y = 0.2: the solver's trajectory against the
    RK4 of the same ODEs as test_relaxation at that state, interpolated
    here with numpy.interp (independent of OpenFOAM's interpolationTable).
    file_clamped: the same rows from a file, but only those with y <= 0
    and outOfBounds clamp, so the grain (above the table) sees the last
    row.  Tolerance 0.5 % as test_relaxation (same step/tau)."""
    _, _, d, dt, steps, every = CASES["rarefiedCompressible"]
    if variant == "inline":
        rows, extra = TABLE, ()
        y = Y_GRAIN
    else:
        rows, extra = TABLE[:2], (("outOfBounds", "clamp"),)
        y = TABLE[1][0]
    case = table_case("table_" + variant, rows, inline=(variant == "inline"), extra=extra)
    col = np.array(rows).T
    rho_g, U, T_g, mu = (float(np.interp(y, col[0], col[i])) for i in (1, 2, 5, 6))
    check_against_ode(case, f"Loth, prescribed table ({variant}), gas at y = {y:g}: rho "
                      f"{rho_g:.4g}, U {U:.4g}, T {T_g:.4g}, mu {mu:.4g}",
                      rho_g, U, d, dt, steps, every, T_g=T_g, mu=mu)


@pytest.mark.parametrize("shear", [5e4, -5e4])
def test_lift(shear):
    """Loth's shear lift (LothCoeffs lift true) in a prescribed simple
    shear U_x = 175 + G (y - 0.2) (at the grain's initial y, read back),
    rho, T, mu uniform (0.3 kg/m^3, 310 K,
    2.35e-5 Pa s): one step from rest at y = 0.2, where v0 = (175, 0, 0),
    |curl U| = |G|, omega* = |G| d/|v0|.  The lift impulse is
    v_y = sign(G) C_L(Re, omega*) (pi d^2/8) rho |v0|^2 dt/m_p (towards the
    faster gas), C_L from rmf.kinetic (independent
    of dragLaws); tolerance 1e-6 relative (10 written digits).  v_z stays
    0, and v_x is the drag's alone (the lift is perpendicular)."""
    _, _, d, dt, _, _ = CASES["rarefiedCompressible"]
    rho, U, T, mu = 0.3, 175.0, 310.0, 2.35e-5
    rows = [(y, rho, U + shear*(y - Y_GRAIN), 0, 0, T, mu) for y in (0.1, 0.3)]

    def edit(case):
        place_grain(case, Y_GRAIN)
        use_table(case, rows)
        foam.set_entry(case, PROPS, "subModels/LothCoeffs/lift", "true")

    case = make_case(f"lift_{'up' if shear > 0 else 'down'}", 1.0, 1.0, d, dt, 1, 1,
                     edit=edit)
    foam.run(case, "rarefiedMultiphaseFoam")
    v = single(os.path.join(case, foam.latest_time(case), "lagrangian", "grains", "U"))

    # The grain's y (placed within 1e-5 of Y_GRAIN) sets the gas it sees
    y = float(foam.read_positions(os.path.join(case, "0", "lagrangian", "grains",
                                               "positions"))[0, 1])
    U = U + shear*(y - Y_GRAIN)
    mp = RHO_P*math.pi*d**3/6
    reynolds = rho*U*d/mu
    omega = abs(shear)*d/U
    cl = loth_cl(reynolds, omega)
    expected = math.copysign(cl*math.pi*d**2/8*rho*U**2*dt/mp, shear)
    print(f"\nlift, G = {shear:g} 1/s: Re {reynolds:.3f}, omega* {omega:.4g}, C_L "
          f"{cl:.5g}; v_y {v[1]:.6g} m/s, expected {expected:.6g}")
    assert abs(v[1]/expected - 1) < 1e-6, (v[1], expected)
    assert v[2] == 0
    assert v[0] > 0


def test_prescribed_table_outside():
    """outOfBounds error (default): a parcel above the table stops the run
    with a FatalError naming the table's dictionary, the parcel's
    coordinate and the table's range."""
    case = table_case("table_outside", TABLE[:2])
    out = run_failing(case, "rarefiedMultiphaseFoam")
    for text in ("FOAM FATAL ERROR", "outside the prescribed gas table",
                 "grainsProperties", "coordinate: 0.1999", "table range: [-0.4, 0]"):
        assert text in out, (text, out[-2000:])


BAD_TABLES = {
    # name: rows or text, extra entries, texts the message must hold
    "unsorted": ([TABLE[0], TABLE[2], TABLE[1]], (),
                 ("table", "row 2: position 0 after 0.4", "strictly increasing")),
    "columns": ([TABLE[0], TABLE[1][:5]], (),
                ("table", "row 1: 5 columns", "6 (s rho Ux Uy Uz T) or 7")),
    "rho": ([TABLE[0], (0.0, -1.0) + TABLE[1][2:]], (),
            ("table", "row 1: rho = -1", "rho in (0, inf)")),
    "T": ([TABLE[0], TABLE[1][:5] + (0.0, 2.2e-5)], (),
          ("table", "row 1: T = 0", "T in (0, inf)")),
    "mu": ([TABLE[0], TABLE[1][:6] + (-2e-5,)], (),
           ("table", "row 1: mu = -2e-05", "mu in (0, inf)")),
    "oneRow": ([TABLE[0]], (), ("table", "1 rows", "at least 2 rows")),
    "coordinate": (TABLE, (("coordinate", "theta"),), ("coordinate", "theta", "x", "r")),
    "outOfBounds": (TABLE, (("outOfBounds", "wrap"),), ("outOfBounds", "wrap", "clamp")),
}


@pytest.mark.parametrize("name", list(BAD_TABLES))
def test_prescribed_table_bad_input(vacuum, name):
    """Bad tables: FatalIOError naming the file
    (grainsProperties), the keyword, the bad value and the valid range."""
    rows, extra, texts = BAD_TABLES[name]
    case = foam.copy_case(vacuum, os.path.join(BUILD, "badTable_" + name))
    use_table(case, rows, extra=extra)
    out = run_failing(case, "rarefiedMultiphaseFoam")
    for text in ("FOAM FATAL IO ERROR", "grainsProperties") + texts:
        assert text in out, (text, out[-2000:])


def test_prescribed_table_bad_file(vacuum):
    """A table file that does not exist: FatalIOError naming the keyword
    file and the path."""
    case = foam.copy_case(vacuum, os.path.join(BUILD, "badTable_file"))
    use_table(case, TABLE, inline=False)
    os.remove(os.path.join(case, "constant", "gasTable"))
    out = run_failing(case, "rarefiedMultiphaseFoam")
    for text in ("FOAM FATAL IO ERROR", "grainsProperties", "'file'",
                 "constant/gasTable", "a readable file"):
        assert text in out, (text, out[-2000:])


# ---------------------------------------------------------------------------
# Bad input

@pytest.fixture(scope="module")
def vacuum():
    return make_case("vacuum", 1.0, 1e-3, 1e-4, 2.5e-4, 2, 1)


@pytest.mark.parametrize("entry,value,texts", [
    ("subModels/LothCoeffs/gas", "frozen", ("gas", "frozen", "dsmc", "prescribed")),
    ("subModels/LothCoeffs/prescribed/gamma", 2, ("gamma", "2", "(1, 5/3]")),
    ("subModels/LothCoeffs/prescribed/mu", 0, ("mu", "0", "(0, inf)")),
    ("subModels/interphaseCoupling", "oneWay", ("oneWay", "needs a gas phase")),
])
def test_bad_input(vacuum, entry, value, texts):
    case = foam.copy_case(vacuum, os.path.join(BUILD, "bad_" + entry.split("/")[-1]))
    foam.set_entry(case, PROPS, entry, value)
    out = run_failing(case, "rarefiedMultiphaseFoam")
    for text in ("FOAM FATAL IO ERROR", "grainsProperties") + texts:
        assert text in out, (text, out[-2000:])


# ---------------------------------------------------------------------------
# With DSMC gas: Loth from the averaged cell state

M_AR = 66.3e-27
D_AR, OMEGA_AR, T_REF = 4.17e-10, 0.81, 273.0   # box/constant/dsmcProperties
V_CELL = 0.1*0.08*0.08


def make_gas_case(name, coupling, velocity=(0, 0, 0)):
    """freeMolecularCoupling's periodic argon cell (n = 1e20 m^-3, 300 K,
    lambda = 1.33 cm) with its held grain (d = 10 um), 200 steps written
    every 100."""
    case = foam.copy_setup(BOX, os.path.join(BUILD, name))
    shutil.rmtree(os.path.join(case, "0"))
    shutil.copytree(os.path.join(foam.dsmc_tutorial("freeSpacePeriodic"), "0"),
                    os.path.join(case, "0"))
    foam.set_entry(case, "system/dsmcInitialiseDict", "velocity",
                   "({:.6g} {:.6g} {:.6g})".format(*velocity))
    foam.set_entry(case, PROPS, "subModels/interphaseCoupling", coupling)
    foam.set_entry(case, CONTROL, "endTime", "2e-3")
    foam.set_entry(case, CONTROL, "writeInterval", 100)
    return case


def prepare(case):
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case


def test_loth_from_dsmc():
    """Loth, gas dsmc, the held grain in argon drifting at s = 1: the
    periodic cell conserves the gas's mass, momentum and energy exactly,
    so the averaged cell state is the realized one (rho.gas, U.gas,
    T.gas), and the force per grain, couplingForce V, must be Loth's
    C_D (rmf.kinetic) at that state, with mu from the VHS law (Bird
    1994 eq. 4.62, as gasCarrierFields): tolerance 1e-6 (the files' 10
    digits; the grain's velocity change is ~1e-20 of |U|, so freezing C_D
    over a step costs nothing)."""
    U = math.sqrt(2*K*T_G/M_AR)
    case = make_gas_case("lothDsmc", "Loth", (U, 0, 0))
    foam.set_entry(case, PROPS, "subModels/LothCoeffs", "{}")
    foam.set_entry(case, PROPS, "subModels/LothCoeffs/gas", "dsmc")
    foam.set_entry(case, PROPS, "subModels/LothCoeffs/averagingSteps", 50)
    prepare(case)
    foam.run(case, "rarefiedMultiphaseFoam")

    t = foam.latest_time(case)
    rho = foam.read_field(os.path.join(case, t, "rho.gas"), 1)[0]
    Ug = foam.read_field(os.path.join(case, t, "U.gas"), 1)[0]
    Tg = foam.read_field(os.path.join(case, t, "T.gas"), 1)[0]
    F = foam.read_field(os.path.join(case, t, "couplingForce.grains"), 1)[0]*V_CELL
    mu_ref = (15*math.sqrt(M_AR*K*T_REF/math.pi)
              / (2*(5 - 2*OMEGA_AR)*(7 - 2*OMEGA_AR)*D_AR**2))
    mu = mu_ref*(Tg/T_REF)**OMEGA_AR
    d = 1e-5
    v0 = np.linalg.norm(Ug)
    re = rho*v0*d/mu
    ma = v0/math.sqrt(GAMMA*K/M_AR*Tg)
    cd = loth_cd(re, ma, GAMMA, T_G/Tg)
    expected = cd*math.pi*d**2/8*rho*v0**2
    err = (F @ Ug/v0)/expected - 1
    ok = abs(err) < 1e-6
    print(f"\n{'PASS' if ok else 'FAIL'} Loth from the DSMC cell (Re {re:.4g}, Ma {ma:.4g}, "
          f"C_D {cd:.5g}): force {F @ Ug/v0:.6g} N, expected {expected:.6g} N, "
          f"error {err:+.2e} (tolerance 1e-6)")
    assert abs(err) < 1e-6, err


def test_loth_bad_averaging_steps():
    """averagingSteps (gas dsmc) below 1: FatalIOError with the range."""
    case = make_gas_case("bad_averagingSteps", "Loth")
    foam.set_entry(case, PROPS, "subModels/LothCoeffs", "{}")
    foam.set_entry(case, PROPS, "subModels/LothCoeffs/gas", "dsmc")
    foam.set_entry(case, PROPS, "subModels/LothCoeffs/averagingSteps", 0)
    prepare(case)
    out = run_failing(case, "rarefiedMultiphaseFoam")
    for text in ("FOAM FATAL IO ERROR", "grainsProperties", "averagingSteps", "[1, "):
        assert text in out, (text, out[-2000:])


# ---------------------------------------------------------------------------
# adaptive (doc/physics.md#adaptive)

@pytest.mark.parametrize("KnSwitch,fm", [(None, 0.5), (1e5, 0.0), (1.0, 1.0)])
def test_adaptive_fractions(KnSwitch, fm):
    """adaptive in the argon cell (lambda = 1.33 cm) with two grains:
    d = 10 um (Kn_p = 1333) and d = 5 mm (Kn_p = 2.67).  Default KnSwitch
    10: one in each regime, so 50 % / 50 % in the log and the fields;
    KnSwitch 1e5: both Loth; KnSwitch 1: both free-molecular.  Exact."""
    case = make_gas_case(f"adaptive_{KnSwitch}", "adaptive")
    init = "system/grainsInitialiseDict"
    foam.set_entry(case, init, "regions/big", "{}")
    for key, value in (("type", "box"), ("min", "(0.01 -0.001 -0.001)"),
                       ("max", "(0.012 0.001 0.001)"), ("d", 5e-3), ("nParcels", 1),
                       ("nParticle", 1), ("U0", "(0 0 0)")):
        foam.set_entry(case, init, "regions/big/" + key, value)
    if KnSwitch is not None:
        foam.set_entry(case, PROPS, "subModels/adaptiveCoeffs", "{}")
        foam.set_entry(case, PROPS, "subModels/adaptiveCoeffs/KnSwitch", KnSwitch)
    prepare(case)
    log = foam.run(case, "rarefiedMultiphaseFoam")

    with open(os.path.join(case, "log.rarefiedMultiphaseFoam")) as f:
        lines = [line for line in f if line.startswith("adaptive: parcel-steps")]
    assert len(lines) == 2, lines
    t = foam.latest_time(case)
    f_fm = foam.read_field(os.path.join(case, t, "freeMolecularFraction.grains"), 1)[0]
    f_l = foam.read_field(os.path.join(case, t, "LothFraction.grains"), 1)[0]
    knp = foam.read_field(os.path.join(case, t, "Knp.grains"), 1)[0]
    ok = abs(f_fm - fm) < 1e-12 and abs(f_l - (1 - fm)) < 1e-12
    print(f"\n{'PASS' if ok else 'FAIL'} adaptive, KnSwitch {KnSwitch}: free-molecular "
          f"fraction {f_fm}, Loth {f_l} (expected {fm}, {1 - fm}); Knp (smallest d) "
          f"{knp:.5g}; log: {lines[-1].strip()}")
    assert ok
    assert f"free-molecular {100*fm:g} %" in lines[-1], lines[-1]


@pytest.mark.parametrize("entry,value,texts", [
    ("subModels/adaptiveCoeffs/KnSwitch", 0, ("KnSwitch", "0", "(0, inf)")),
    ("subModels/adaptiveCoeffs/KnSwitch", -5, ("KnSwitch", "-5", "(0, inf)")),
    ("subModels/adaptiveCoeffs/averagingSteps", 0, ("averagingSteps", "0")),
])
def test_adaptive_bad_input(entry, value, texts):
    case = make_gas_case("bad_" + entry.split("/")[-1], "adaptive")
    foam.set_entry(case, PROPS, "subModels/adaptiveCoeffs", "{}")
    foam.set_entry(case, PROPS, entry, value)
    prepare(case)
    out = run_failing(case, "rarefiedMultiphaseFoam")
    for text in ("FOAM FATAL IO ERROR", "grainsProperties") + texts:
        assert text in out, (text, out[-2000:])


@pytest.mark.parametrize("KnSwitch,same_as", [(1.0, "oneWay"), (1e5, "Loth")])
def test_adaptive_branches(KnSwitch, same_as):
    """adaptive with every parcel in one regime gives exactly (to the
    files' 10 digits) the exchange of the model of that regime on the same
    two grains in argon drifting at s = 1 (same seeds, same averaging
    window of 200 steps): the branches are oneWay's and Loth's own."""
    U = math.sqrt(2*K*T_G/M_AR)
    fields = {}
    for model in ("adaptive", same_as):
        case = make_gas_case(f"branch_{same_as}_{model}", model, (U, 0, 0))
        init = "system/grainsInitialiseDict"
        foam.set_entry(case, init, "regions/big", "{}")
        for key, value in (("type", "box"), ("min", "(0.01 -0.001 -0.001)"),
                           ("max", "(0.012 0.001 0.001)"), ("d", 5e-3),
                           ("nParcels", 1), ("nParticle", 1), ("U0", "(0 0 0)")):
            foam.set_entry(case, init, "regions/big/" + key, value)
        if model == "adaptive":
            foam.set_entry(case, PROPS, "subModels/adaptiveCoeffs", "{}")
            foam.set_entry(case, PROPS, "subModels/adaptiveCoeffs/KnSwitch", KnSwitch)
        if model == "Loth":
            foam.set_entry(case, PROPS, "subModels/LothCoeffs", "{}")
            foam.set_entry(case, PROPS, "subModels/LothCoeffs/gas", "dsmc")
        prepare(case)
        foam.run(case, "rarefiedMultiphaseFoam")
        t = foam.latest_time(case)
        fields[model] = np.concatenate([
            np.ravel(foam.read_field(os.path.join(case, t, name + ".grains"), 1))
            for name in ("couplingForce", "couplingHeat")])
    a, b = fields["adaptive"], fields[same_as]
    ok = np.allclose(a, b, rtol=1e-9, atol=0) and np.any(a != 0)
    print(f"\n{'PASS' if ok else 'FAIL'} adaptive (KnSwitch {KnSwitch}) = {same_as}: "
          f"force/heat fields {a} vs {b}")
    assert ok
