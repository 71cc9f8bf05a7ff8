# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Plume-surface interaction observables (rmf.psi) on a
synthetic case with known answers.

Case: a 5 degree wedge about the x axis, x in [0, 20] mm (nozzle at 0,
surface at X_s = 20 mm), r in [0, 30] mm, 40 x 30 cells (0.5 mm x 1 mm),
made by blockMesh; fields and parcels written here (no solver run).
observablesDict: layerTop 18 mm (H = 2 mm), layerRadius 16 mm,
nozzleRadius 8.1 mm, crossingRadius 13 mm.
Times: 0 (the layer, no gas fields), 1e-05 and 2e-05 (a crater, gas,
alpha, Kn_p), 3e-05 (gas and alpha, no parcels: the cloud is empty).

- Layer: a lattice of parcels, 0.02 mm in x and 0.1 mm in r, each standing
  for nParticle proportional to r real grains (uniform real-grain density
  in the wedge).  Crater at t: parcels with x < layerTop + D(r) removed,
  D(r) = D0 (1 - r^2/Rc^2) for r < Rc (D0, Rc = 1.2, 6 mm at 1e-05; 1.6,
  8 mm at 2e-05).  At 2e-05 the layer has twice the parcels, each half
  as heavy (as after cloning).  At 1e-05 a resting dilute dust cloud (a
  fifth of the layer's density) fills x in [10, 17] mm above the layer.
  Expected depth of an annulus: the area-weighted mean of D over it
  (quadrature here).  Tolerance 0.03 mm: a lattice column keeps whole
  parcels, so its height is H - D(r) rounded to the lattice step (0.02,
  0.01 mm); the r lattice (0.1 mm) against the continuous annulus average
  adds under 0.005 mm; where D varies by more than a slab (0.2 mm) over an
  annulus the scan may stop one partly filled slab early (measured: worst
  annulus 0.004 mm).  Counting parcels instead of real grains doubles the
  2e-05 thickness; counting the dilute cloud adds 1.4 mm; stopping before
  the partly filled slab loses up to a slab (0.2 mm): each fails.
- Shock: rhoN on the axis = jet 1e21 (1 + x/4 mm)^-2 upstream of x_sh, 6
  times the jet's value at x_sh downstream, rising by half to the wall;
  5 % Gaussian noise per cell (seed rmf_testing.seed(7)).  x_sh = 15.2 mm
  at 1e-05, 16.1 mm at 2e-05 (standoff 4.8 and 3.9 mm); tolerance one cell
  (0.5 mm): the density is known at cell centres only.  At 3e-05 the jet
  alone: no shock, said in a note.
- Ejecta at 1e-05 (above layerTop, U_x < 0): 60 parcels at 30 degrees,
  50 m/s, d = 0.28 um, nParticle 100; 40 parcels at 60 degrees, 100 m/s,
  d = 0.56 um, nParticle 50; random azimuths of the in-plane velocity.
  Mass-weighted mean angle (6000 x 30 + 16000 x 60)/22000 = 51.818 deg,
  median 60 deg; ejecta mean speed (real grains) 62.5 m/s, max 100 m/s.
  Distractors that must not count: 20 parcels above the layer falling
  onto it (U_x > 0, 200 m/s), 20 parcels in the layer lifting off (U_x <
  0, 150 m/s).  Exact construction: tolerance 1e-9 relative.
- Crossing r_c = 13 mm (shell 0.5 mm): 30 parcels with v_r = -20 m/s
  (nParticle 10), 10 with v_r = +10 m/s (nParticle 20), each with an
  azimuthal velocity of 5 m/s and off the y axis; parcels at r = 12 and
  14 mm with v_r = +50 m/s (outside the shell) and the resting layer must
  not count.  Flux-weighted toward the axis 6000/(6000 + 2000) = 0.75;
  real grains 300/500 = 0.6.  Exact: 1e-9.
- alpha.grains: 0.01 in the layer cells, one cell 0.3 (1e-05), 0.45
  (2e-05), 0.2 (3e-05): max exact.
- Kn_p: at 1e-05 Knp.grains = 10 where x > 17 mm, 0.5 in one cell in the
  stagnation region, 0.1 in one cell outside it (r = 25.5 mm): min 0.5.
  At 2e-05 no Knp.grains: lambda.gas = 1e-4 (1 + 10 (X_s - x)/m) m and the
  parcels' d = 0.28 um: min over the region is lambda of the wall row /d.
- T_p: layer 200 K, ejecta 250 and 300 K, others 220-230 K: min 200, max
  300, real-grain mean from the group sums.

- Also: shocks of finite thickness before a cold-wall layer (standoff
  within half a cell, see the test); a zero or flat axis density and an
  empty positions file give a note, not a number; --radial-weight
  multiplies nParticle by 1 + (W - 1) r/R; the CLI writes every PNG and a
  summary.md whose crater depth and ejecta speed are the known ones and
  which holds no NaN; --compare at the common times; a case without
  observablesDict stops with a message.

Statistics.  The checks above on the written case are exact for any draw
of its random parts, but for the shock.  The checks on random draws (the
case's shock; noisy axis profiles like the demo's; random demo-like
layers of 5000 parcels for the crater) are count tests: a scenario is
drawn N_DRAWS = 100 (axis profiles) or N_LAYERS = 100 (layers) times, seeds
rmf_testing.seed(1..100), and each of its checks may miss in at most
miss_limit draws, the count whose excess has probability MODULE_ALPHA/m
(binomial) at the check's calibrated miss rate.  The rates come from
calibration draws with other seeds (CAL_SEED + i, outside every seed
set; 20000 profiles and 5000 layers per scenario, sizes fixed before any
result was seen; calibrate(), the counts in CALIBRATION), taken at their
99.9 % Clopper-Pearson upper bound: a tolerance is no longer judged by
the seeds it is tested on.  A check that breaks misses in most draws
(the old shock criterion, the old crater definition), far above its
limit; a count limit at or above the draws (a vacuous check) fails.  The
case's shock (test_shock_standoff) is one draw: its calibrated error
(20000 noises, none missing) must leave the tolerance z_limit(m) of its
sd.
Family-wise error: 2.5e-4 (rmf_testing.MODULE_ALPHA) over m = 26
comparisons (COMPARISONS: every check of every scenario, and the spread
of drop/sigma of the untouched layers), Bonferroni, 9.6e-6 each.

About 40 s (blockMesh, postProcess, analyses and plots of the CLI runs,
400 random layers, 900 axis profiles).
"""

import math
import os
import re
import shutil
import subprocess
import sys

import numpy as np
import pytest
from scipy import stats

import rmf_testing
from rmf import foam, psi
from rmf_testing import report, seed

BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "psiObservables")

X_S, TOP, R_LAYER, R_NOZZLE, R_C = 0.020, 0.018, 0.016, 0.0081, 0.013
H = X_S - TOP
DX_CELL, DR_CELL = 0.5e-3, 1e-3
LATTICE_X, LATTICE_R = 0.02e-3, 0.1e-3
D_P = 2.8e-7
CRATERS = {"1e-05": (1.2e-3, 6e-3), "2e-05": (1.6e-3, 8e-3)}
SHOCKS = {"1e-05": 0.0152, "2e-05": 0.0161}
ALPHA_MAX = {"1e-05": 0.3, "2e-05": 0.45, "3e-05": 0.2}
CRATER_TOL = 0.03e-3
SHOCK_TOL = DX_CELL
EXACT = 1e-9
THICK_WIDTHS = (0.2e-3, 0.5e-3, 1e-3)

# Count tests (module docstring): draws tested and calibration draws, the
# sizes fixed before any result was seen
N_DRAWS, N_LAYERS = 100, 100                        # tested, seeds seed(1..n)
CAL_DRAWS, CAL_LAYERS = 20000, 5000
CAL_SEED = 10**6                                    # calibration seeds CAL_SEED + i
#: Misses of each check in the calibration draws (calibrate()):
#: {scenario: (draws, {check: misses})}
CALIBRATION = {
    "case shock 1e-05": (20000, {"standoff within a cell": 0}),
    "case shock 2e-05": (20000, {"standoff within a cell": 0}),
    "flat jet, noise 20 %": (20000, {"standoff within 0.4 mm": 38}),
    "flat jet, noise 5 %": (20000, {"standoff within 0.25 mm": 0}),
    "dust layer": (20000, {"standoff within a cell, peak at the layer top": 0}),
    "no shock": (20000, {"no shock (not sustained)": 62}),
    "demo rows": (20000, {"standoff within a cell": 9}),
    "thick shock 0.2 mm": (20000, {"standoff within half a cell": 0}),
    "thick shock 0.5 mm": (20000, {"standoff within half a cell": 6}),
    "thick shock 1 mm": (20000, {"standoff within half a cell": 714}),
    "untouched layer": (5000, {"axis drop within 3 sigma of 0": 42, "no crater": 120,
                               "median sigma in (0.015, 0.04) mm": 1, "nothing eroded": 5}),
    "compacted layer": (5000, {"axis drop within 3 sigma of H/2": 42,
                               "crater depth within 4 sigma of H/2": 312, "nothing eroded": 0}),
    "known crater": (5000, {"axis drop within 3 sigma of D": 94,
                            "crater depth within 4 sigma of D": 87, "radius within 1 mm": 9,
                            "eroded on the axis within 0.15 of 0.6": 5,
                            "eroded layer within 0.006": 36}),
    "dilute ejecta": (5000, {"axis drop within 1 sigma of the drop without the cloud": 1737,
                             "axis drop within 3 sigma of D": 175,
                             "eroded on the axis within 0.05 of that without the cloud": 95}),
}
#: Mean and sd of sigma_scale over blocks of N_LAYERS untouched calibration
#: layers (calibrate())
SCALE_CALIBRATION = (0.980, 0.019)
#: Bias and sd of the case's standoff at each time over CAL_DRAWS noises
#: (calibrate())
CASE_SHOCK_ERROR = {"1e-05": (1.26e-05, 4.96e-05), "2e-05": (-6.78e-05, 4.94e-05)}
#: The module's comparisons: every check of every scenario, and the spread
COMPARISONS = sum(len(checks) for _, checks in CALIBRATION.values()) + 1

HEADER = "FoamFile {{ version 2.0; format ascii; class {cls}; object {name}; }}\n"
HALF = math.radians(2.5)

BLOCKMESH = f"""FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
scale 1;
vertices
(
    (0 0 0) ({X_S} 0 0)
    ({X_S} {0.03*math.cos(HALF):.12g} {-0.03*math.sin(HALF):.12g})
    (0 {0.03*math.cos(HALF):.12g} {-0.03*math.sin(HALF):.12g})
    ({X_S} {0.03*math.cos(HALF):.12g} {0.03*math.sin(HALF):.12g})
    (0 {0.03*math.cos(HALF):.12g} {0.03*math.sin(HALF):.12g})
);
blocks (hex (0 1 2 3 0 1 4 5) (40 30 1) simpleGrading (1 1 1));
boundary
(
    nozzle {{ type patch; faces ((0 3 5 0)); }}
    surface {{ type wall; faces ((1 4 2 1)); }}
    outer {{ type patch; faces ((3 5 4 2)); }}
    front {{ type wedge; faces ((0 1 2 3)); }}
    back {{ type wedge; faces ((0 5 4 1)); }}
    axis {{ type empty; faces ((0 1 1 0)); }}
);
"""

CONTROL = """FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application rarefiedMultiphaseFoam; startFrom startTime; startTime 0; stopAt endTime;
endTime 3e-05; deltaT 1e-06; writeControl timeStep; writeInterval 10;
writeFormat ascii; writePrecision 10; timeFormat general; timePrecision 6;
"""
SCHEMES = """FoamFile { version 2.0; format ascii; class dictionary; object fvSchemes; }
ddtSchemes { default none; } gradSchemes { default none; } divSchemes { default none; }
laplacianSchemes { default none; } interpolationSchemes { default linear; }
snGradSchemes { default none; }
"""
SOLUTION = "FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }\n"
OBSERVABLES = f"""FoamFile {{ version 2.0; format ascii; class dictionary;
           object observablesDict; }}
surface {X_S};          // x of the wall patch surface [m]
nozzleRadius {R_NOZZLE};
layerTop {TOP};
layerRadius {R_LAYER};
crossingRadius {R_C};
"""


def write_field(case, time, name, values):
    os.makedirs(os.path.join(case, time), exist_ok=True)
    with open(os.path.join(case, time, name), "w") as f:
        f.write(HEADER.format(cls="volScalarField", name=name))
        f.write("dimensions [0 0 0 0 0 0 0];\n")
        f.write(f"internalField nonuniform List<scalar> {len(values)}\n(\n")
        f.write("\n".join(f"{v:.10g}" for v in values))
        f.write('\n);\nboundaryField { ".*" { type calculated; value uniform 0; } }\n')


def write_parcels(case, time, p):
    base = os.path.join(case, time, "lagrangian", "grains")
    os.makedirs(base, exist_ok=True)
    with open(os.path.join(base, "positions"), "w") as f:
        f.write(HEADER.format(cls="Cloud<basicKinematicParcel>", name="positions"))
        f.write(f"{len(p['pos'])}\n(\n")
        f.write("\n".join(f"({x:.10g} {y:.10g} {z:.10g}) {c}"
                          for (x, y, z), c in zip(p["pos"], p["cell"])))
        f.write("\n)\n")
    with open(os.path.join(base, "U"), "w") as f:
        f.write(HEADER.format(cls="vectorField", name="U"))
        f.write(f"{len(p['U'])}\n(\n")
        f.write("\n".join(f"({a:.10g} {b:.10g} {c:.10g})" for a, b, c in p["U"]))
        f.write("\n)\n")
    for name in ("T", "d", "nParticle"):
        with open(os.path.join(base, name), "w") as f:
            f.write(HEADER.format(cls="scalarField", name=name))
            f.write(f"{len(p[name])}\n(\n" + "\n".join(f"{v:.10g}" for v in p[name]) + "\n)\n")


def crater_depth(r, time):
    if time not in CRATERS:
        return np.zeros_like(r)
    D0, Rc = CRATERS[time]
    return np.where(r < Rc, D0*(1 - (r/Rc)**2), 0.0)


def expected_depth(time, a, b, q=psi.SURFACE_QUANTILE):
    """H - Q_q/q of the heights of a uniform real-grain density over the
    annulus [a, b] below the surface H - D(r) (quadrature and bisection):
    the surface drop of psi.surface_profile for this crater."""
    r = np.linspace(a, b, 20001)
    h = H - crater_depth(r, time)
    total = np.trapz(r*h, r)
    lo, hi = 0.0, H
    for _ in range(60):
        y = 0.5*(lo + hi)
        lo, hi = (y, hi) if np.trapz(r*np.minimum(y, h), r) < q*total else (lo, y)
    return H - 0.5*(lo + hi)/q


def group(x, r, psi_angle, U, n, d, T):
    m = len(x)
    pos = np.stack([x, r*np.cos(psi_angle), r*np.sin(psi_angle)], -1)
    return dict(pos=pos, U=np.asarray(U, float).reshape(m, 3), nParticle=np.full(m, float(n)),
                d=np.full(m, d), T=np.full(m, float(T)))


def lattice(x0, x1, step, refine=1):
    """Resting parcels on the (x, r) lattice over [x0, x1] x [0, R_LAYER],
    nParticle proportional to r (uniform real-grain density in the wedge);
    refine > 1: that many times more parcels, each that many times lighter."""
    step = step/refine
    xs = x0 + (np.arange(int(round((x1 - x0)/step))) + 0.5)*step
    rs = (np.arange(int(round(R_LAYER/LATTICE_R))) + 0.5)*LATTICE_R
    x, r = [a.ravel() for a in np.meshgrid(xs, rs, indexing="ij")]
    g = group(x, r, np.zeros_like(x), np.zeros((len(x), 3)), 0, D_P, 200)
    g["nParticle"] = 1000*r/LATTICE_R/refine
    return g


def layer(time):
    """The layer with the crater of time; at 2e-05 twice as many parcels,
    half as heavy (as after cloning: only real grains count)."""
    g = lattice(TOP, X_S, LATTICE_X, 2 if time == "2e-05" else 1)
    r = np.hypot(g["pos"][:, 1], g["pos"][:, 2])
    keep = g["pos"][:, 0] >= TOP + crater_depth(r, time)
    return {k: v[keep] for k, v in g.items()}


def dust_cloud():
    """Resting dilute dust above the layer (1e-05): x in [10, 17] mm at a
    fifth of the layer's density, below the surface threshold (0.5)."""
    return lattice(0.010, 0.017, 5*LATTICE_X)


def ejecta_groups(rng):
    """Ejecta and distractors of time 1e-05 (module docstring)."""
    groups = []

    def at(n, x0, x1, r0, r1):
        return (rng.uniform(x0, x1, n), rng.uniform(r0, r1, n),
                rng.uniform(-HALF*0.8, HALF*0.8, n), rng.uniform(0, 2*math.pi, n))

    def velocity(speed, theta_deg, phi):
        th = math.radians(theta_deg)
        return speed*np.stack([-np.full_like(phi, math.sin(th)), math.cos(th)*np.cos(phi),
                               math.cos(th)*np.sin(phi)], -1)

    for n, theta, speed, d, nP, T in ((60, 30, 50, D_P, 100, 250), (40, 60, 100, 2*D_P, 50, 300)):
        x, r, a, phi = at(n, 0.012, 0.0175, 2e-3, 11e-3)
        groups.append(group(x, r, a, velocity(speed, theta, phi), nP, d, T))
    # falling back onto the layer (U_x > 0)
    x, r, a, phi = at(20, 0.012, 0.0175, 2e-3, 11e-3)
    groups.append(group(x, r, a, -velocity(200, 80, phi), 7, D_P, 220))
    # inside the layer, lifting off (U_x < 0): not ejecta yet
    x, r, a, phi = at(20, 0.0195, 0.01995, 2e-3, 5e-3)
    groups.append(group(x, r, a, velocity(150, 45, phi), 1, D_P, 210))
    # crossing shell: radial velocity v_r, azimuthal 5 m/s, U_x = +5 (not ejecta)
    for n, vr, nP, r0, r1 in ((30, -20, 10, R_C - 0.4e-3, R_C + 0.4e-3),
                              (10, 10, 20, R_C - 0.4e-3, R_C + 0.4e-3),
                              (10, 50, 30, 12e-3 - 0.05e-3, 12e-3 + 0.05e-3),
                              (10, 50, 30, 14e-3 - 0.05e-3, 14e-3 + 0.05e-3)):
        x, r, a, _ = at(n, 0.012, 0.0175, r0, r1)
        U = np.stack([np.full(n, 5.0), vr*np.cos(a) - 5*np.sin(a), vr*np.sin(a) + 5*np.cos(a)], -1)
        groups.append(group(x, r, a, U, nP, D_P, 230))
    return groups


def join(groups):
    return {k: np.concatenate([g[k] for g in groups]) for k in groups[0]}


def locate(p, C):
    """Cell of each parcel on the structured wedge (by its x and r rows)."""
    key = {(int(cx // DX_CELL), int(cr // DR_CELL)): i
           for i, (cx, cr) in enumerate(zip(C[:, 0], np.hypot(C[:, 1], C[:, 2])))}
    r = np.hypot(p["pos"][:, 1], p["pos"][:, 2])
    p["cell"] = np.array([key[(min(int(x // DX_CELL), 39), min(int(rr // DR_CELL), 29))]
                          for x, rr in zip(p["pos"][:, 0], r)])
    return p


def axis_density(x, x_sh, rng):
    rho = 1e21*(1 + x/4e-3)**-2
    if x_sh is not None:
        post = 6*1e21*(1 + x_sh/4e-3)**-2*(1 + 0.5*(x - x_sh)/(X_S - x_sh))
        rho = np.where(x < x_sh, rho, post)
    return rho*(1 + 0.05*rng.standard_normal(len(x)))


def build(case, times=("0", "1e-05", "2e-05", "3e-05")):
    if os.path.exists(case):
        shutil.rmtree(case)
    os.makedirs(os.path.join(case, "system"))
    os.makedirs(os.path.join(case, "0"))
    for name, text in (("blockMeshDict", BLOCKMESH), ("controlDict", CONTROL),
                       ("fvSchemes", SCHEMES), ("fvSolution", SOLUTION),
                       ("observablesDict", OBSERVABLES)):
        with open(os.path.join(case, "system", name), "w") as f:
            f.write(text)
    foam.run(case, "blockMesh")
    C = foam.cell_centres(case, "0")
    x, r = C[:, 0], np.hypot(C[:, 1], C[:, 2])
    rng = np.random.default_rng(seed(7))
    in_layer = (x > TOP) & (r < R_LAYER)
    for t in times:
        alpha = np.where(in_layer, 0.01, 0.0)
        if t in ALPHA_MAX:
            alpha[np.argmin(np.hypot(x - 0.019, r - 3e-3))] = ALPHA_MAX[t]
        write_field(case, t, "alpha.grains", alpha)
        if t != "3e-05":
            groups = [layer(t)] + ([dust_cloud()] + ejecta_groups(rng) if t == "1e-05" else [])
            write_parcels(case, t, locate(join(groups), C))
        if t == "0":
            continue            # no gas fields at time 0
        write_field(case, t, "rhoN", axis_density(x, SHOCKS.get(t), rng))
        if t == "1e-05":
            knp = np.where(x > 0.017, 10.0, 0.0)
            knp[np.argmin(np.hypot(x - 0.01825, r - 2.5e-3))] = 0.5
            knp[np.argmin(np.hypot(x - 0.01925, r - 25.5e-3))] = 0.1
            write_field(case, t, "Knp.grains", knp)
        if t == "2e-05":
            write_field(case, t, "lambda.gas", 1e-4*(1 + 10*(X_S - x)))
    return case


@pytest.fixture(scope="module")
def case():
    return build(os.path.join(BUILD, "synthetic"))


@pytest.fixture(scope="module")
def analysis(case):
    return psi.analyse(case)


def row(analysis, time):
    return next(r for r in analysis["rows"] if r["time"] == time)


@pytest.mark.parametrize("time", ["1e-05", "2e-05"])
def test_crater(analysis, time):
    c = row(analysis, time)["crater"]
    edges = c["r_edges"]
    expected = np.array([expected_depth(time, a, b) for a, b in zip(edges[:-1], edges[1:])])
    dev = np.abs(c["depth"] - expected)
    print(f"crater {time}: depth {1e3*c['max_depth']:.4f} mm at r = {1e3*c['r_max']:.2f} mm, "
          f"expected {1e3*expected.max():.4f}; worst annulus deviation {1e3*dev.max():.4f} mm "
          f"(tolerance {1e3*CRATER_TOL:g} mm)")
    assert dev.max() < CRATER_TOL, (1e3*c["depth"], 1e3*expected)
    assert abs(c["max_depth"] - expected.max()) < CRATER_TOL
    assert c["r_max"] < edges[1]          # deepest at the axis
    np.testing.assert_allclose(c["height"], H - c["depth"])
    # half-depth radius of D0 (1 - r^2/Rc^2): Rc/sqrt(2), from the annulus
    # values linear between centres (1 mm apart): measured within 0.02 mm
    Rc = CRATERS[time][1]
    print(f"crater radius {1e3*c['radius']:.3f} mm, expected {1e3*Rc/math.sqrt(2):.3f}")
    assert abs(c["radius"] - Rc/math.sqrt(2)) < 0.1e-3


def test_crater_initial_layer_is_flat(analysis):
    """The lattice layer: the quantile's interpolation between cumulative
    midpoints is exact for equal weights; the weights here grow with r
    across an annulus (1 to 19 in the axis one): measured 0.0032 mm
    there, tolerance 0.005 mm.  No annulus is deeper than 3 sigma."""
    c = row(analysis, "0")["crater"]
    assert np.abs(c["depth"]).max() < 0.005e-3
    assert c["max_depth"] == 0.0 and c["r_max"] is None
    assert abs(c["eroded_layer"]) < 1e-12


def case_shock(cells, time):
    """The scenario of test_shock_standoff for calibrate: the axis density
    build writes at time, with the noise of seed s, through the analysis's
    axis profile and shock."""
    def scenario(s):
        rho = axis_density(cells["x"], SHOCKS[time], np.random.default_rng(s))
        x, values = psi.axis_density(cells["x"], cells["r"], rho,
                                     dict(surface=X_S, nozzleRadius=R_NOZZLE))
        shock = psi.shock_standoff(x, values, X_S)
        return {"standoff within a cell": shock["standoff"] is not None and
                abs(shock["standoff"] - (X_S - SHOCKS[time])) < SHOCK_TOL}, shock
    return scenario


@pytest.mark.parametrize("time", ["1e-05", "2e-05"])
def test_shock_standoff(analysis, time):
    """One realisation of the noise (seed(7)): the standoff within a cell.
    Its calibrated error (CASE_SHOCK_ERROR, bias and sd over CAL_DRAWS
    noises, no miss among them) must leave the tolerance z_limit of the
    comparison's share of the budget (a Gaussian model of the error, a
    smooth function of the noise near the step)."""
    shock = row(analysis, time)["shock"]
    expected = X_S - SHOCKS[time]
    bias, sd = CASE_SHOCK_ERROR[time]
    assert CALIBRATION[f"case shock {time}"][1]["standoff within a cell"] == 0
    assert (SHOCK_TOL - abs(bias))/sd > rmf_testing.z_limit(COMPARISONS), (bias, sd)
    assert report(f"shock {time}", abs(shock["standoff"] - expected) < SHOCK_TOL,
                  f"standoff {1e3*shock['standoff']:.3f} mm, expected {1e3*expected:.3f} "
                  f"(tolerance {1e3*SHOCK_TOL:g} mm; calibrated error {1e3*bias:+.3f} +- "
                  f"{1e3*sd:.3f} mm)")


def test_no_shock_and_missing_data_are_noted(analysis):
    assert row(analysis, "3e-05")["shock"]["standoff"] is None
    assert row(analysis, "0")["shock"] is None
    notes = "\n".join(analysis["notes"])
    assert "t = 0: no gas density" in notes
    assert "t = 3e-05: no grains parcels written" in notes
    assert "t = 3e-05: no shock on the axis" in notes
    assert "t = 2e-05: no ejecta" in notes


def test_ejection_angle_and_speeds(analysis):
    r = row(analysis, "1e-05")
    a, s = r["angles"], r["speeds"]
    mean = (6000*30 + 16000*60)/22000
    print(f"ejection angle: mean {a['mean']:.4f} deg (expected {mean:.4f}), median "
          f"{a['median']:.1f}; ejecta speed mean {s['ejecta_mean']:.4f}, max {s['ejecta_max']:.4f}")
    assert a["parcels"] == 100
    assert a["mean"] == pytest.approx(mean, rel=EXACT)
    assert a["median"] == pytest.approx(60, rel=EXACT)
    assert s["ejecta_mean"] == pytest.approx(62.5, rel=EXACT)
    assert s["ejecta_max"] == pytest.approx(100, rel=EXACT)
    assert s["max"] == pytest.approx(200, rel=EXACT)


def test_crossing(analysis):
    c = row(analysis, "1e-05")["crossing"]
    print(f"crossing r_c: toward the axis {c['fraction_toward']:.6f} (flux), "
          f"{c['fraction_toward_grains']:.6f} (grains); expected 0.75, 0.6")
    assert c["fraction_toward"] == pytest.approx(0.75, rel=EXACT)
    assert c["fraction_toward_grains"] == pytest.approx(0.6, rel=EXACT)
    assert row(analysis, "2e-05")["crossing"] is None   # the resting layer crosses nothing


def test_max_alpha(analysis):
    for t, expected in ALPHA_MAX.items():
        assert row(analysis, t)["alpha"]["max"] == pytest.approx(expected, rel=EXACT)
    assert row(analysis, "0")["alpha"]["max"] == pytest.approx(0.01, rel=EXACT)


def test_knp(analysis):
    k1 = row(analysis, "1e-05")
    assert k1["knp_source"] == "Knp.grains"
    assert k1["knp_min"]["min"] == pytest.approx(0.5, rel=EXACT)
    k2 = row(analysis, "2e-05")
    assert k2["knp_source"] == "lambda.gas / mean parcel d"
    wall_row = X_S - DX_CELL/2
    expected = 1e-4*(1 + 10*(X_S - wall_row))/D_P
    print(f"Kn_p stagnation: {k1['knp_min']['min']:.4g} (Knp.grains, expected 0.5), "
          f"{k2['knp_min']['min']:.6g} (lambda/d, expected {expected:.6g})")
    assert k2["knp_min"]["min"] == pytest.approx(expected, rel=1e-6)  # cell centres to 1e-7 m
    assert row(analysis, "3e-05")["knp_min"] is None


def test_temperatures(analysis):
    T = row(analysis, "1e-05")["T"]
    layer_grains = layer("1e-05")["nParticle"].sum() + dust_cloud()["nParticle"].sum()
    groups = [(6000, 250), (2000, 300), (140, 220), (20, 210), (300, 230), (200, 230),
              (300, 230), (300, 230)]
    total = layer_grains + sum(n for n, _ in groups)
    mean = (200*layer_grains + sum(n*t for n, t in groups))/total
    assert (T["min"], T["max"]) == (200, 300)
    assert T["mean"] == pytest.approx(mean, rel=EXACT)


def run_module(*args):
    env = dict(os.environ, PYTHONPATH=os.path.join(foam.PROJECT_DIR, "src", "python"))
    proc = subprocess.run([sys.executable, "-m", "rmf.psi", *args], env=env,
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return proc.stdout


PNGS = ("crater_profile.png", "timeseries.png", "axis_density.png", "ejection_angle.png",
        "speed_histogram.png", "Tp_histogram.png", "knp_map.png")


def test_cli(case):
    """Default output CASE/observables (test_compare uses --output)."""
    out = os.path.join(case, "observables")
    if os.path.exists(out):
        shutil.rmtree(out)
    run_module(case, "--times", "1e-05", "2e-05")
    for name in PNGS + ("summary.md",):
        assert os.path.getsize(os.path.join(out, name)) > 0, name
    with open(os.path.join(out, "summary.md")) as f:
        text = f.read()
    m = re.search(r"- Surface drop on the axis [^\n]*: ([0-9.]+) \+- ([0-9.]+) mm "
                  r"at t = 2e-05 s", text)
    assert m, text
    expected = expected_depth("2e-05", 0.0, 1e-3)          # the axis annulus
    assert abs(float(m.group(1))*1e-3 - expected) < CRATER_TOL
    assert re.search(r"- Crater depth [^\n]*: [0-9.]+ \+- [0-9.]+ mm at t = 2e-05 s", text)
    assert "Ejecta max speed: 100.00 m/s at t = 1e-05 s" in text
    assert not re.search(r"\bnan\b", text, re.I)
    for name in PNGS:
        assert f"- {name}" in text


def test_compare(case):
    other = build(os.path.join(BUILD, "shorter"), times=("0", "1e-05"))
    out = os.path.join(BUILD, "compare")
    if os.path.exists(out):
        shutil.rmtree(out)
    run_module("--compare", case, other, case, "--labels", "stochastic", "MPPIC", "hybrid",
               "--output", out)
    with open(os.path.join(out, "summary.md")) as f:
        text = f.read()
    assert "Times written by every case: 0, 1e-05 s" in text
    assert "Profiles and histograms at: 0, 1e-05 s" in text
    for name in ("compare_crater.png", "compare_timeseries.png", "compare_speed.png",
                 "compare_ejecta_speed.png",
                 "compare_ejection_angle.png", "compare_Tp.png", "compare_knp.png"):
        assert os.path.getsize(os.path.join(out, name)) > 0, name
    assert len(re.findall(r"^\| MPPIC \|", text, re.M)) == 2
    assert not re.search(r"\bnan\b", text, re.I)


def test_flat_or_empty_data_give_notes_not_nan(tmp_path):
    """A zero density (an initial rhoN) has no shock; an empty positions
    file ("0()", a cloud that emptied) holds no parcel."""
    x = np.linspace(0.25e-3, 19.75e-3, 40)
    for rho in (np.zeros_like(x), np.full_like(x, 1e20)):
        shock = psi.shock_standoff(x, rho, X_S)
        assert shock["standoff"] is None and "no rise" in shock["note"], shock
    base = tmp_path / "0" / "lagrangian" / "grains"
    base.mkdir(parents=True)
    (base / "positions").write_text(HEADER.format(cls="Cloud<solidParcel>", name="positions")
                                    + "0()\n")
    assert psi.parcels(str(tmp_path), "0") is None


def test_radial_weight(case):
    """--radial-weight W R: real grains = nParticle (1 + (W - 1) r/R)."""
    g = layer("0")
    r = np.hypot(g["pos"][:, 1], g["pos"][:, 2])
    p = psi.parcels(case, "0", radial_weight=(10, 0.05))
    assert p["n"].sum() == pytest.approx((g["nParticle"]*(1 + 9*r/0.05)).sum(), rel=1e-9)


def test_cli_without_settings(tmp_path):
    """A case without system/observablesDict stops with a message naming it."""
    (tmp_path / "system").mkdir()
    (tmp_path / "0").mkdir()
    env = dict(os.environ, PYTHONPATH=os.path.join(foam.PROJECT_DIR, "src", "python"))
    proc = subprocess.run([sys.executable, "-m", "rmf.psi", str(tmp_path)], env=env,
                          capture_output=True, text=True)
    assert proc.returncode != 0
    assert "observablesDict: missing" in proc.stderr, proc.stderr


def thick_shock(width):
    """A shock of finite thickness (tanh of half width `width`, density
    ratio 5 over the jet at x_sh = 15 mm) before a cold-wall layer (the
    density tripling over the last 0.5 mm), 5 % noise of seed s, 0.5 mm
    cells: the standoff within half a cell (0.25 mm)."""
    x_sh = 0.015

    def scenario(s):
        rng = np.random.default_rng(s)
        x = np.arange(DX_CELL/2, X_S, DX_CELL)
        jet = 1e21*(1 + x/4e-3)**-2
        rho = jet + (5e21*(1 + x_sh/4e-3)**-2 - jet)*0.5*(1 + np.tanh((x - x_sh)/width))
        rho = rho*(1 + 2*np.exp(-(X_S - x)/0.5e-3))*(1 + 0.05*rng.standard_normal(len(x)))
        shock = psi.shock_standoff(x, rho, X_S)
        return {"standoff within half a cell": shock["standoff"] is not None and
                abs(shock["standoff"] - (X_S - x_sh)) < DX_CELL/2}, shock
    return scenario


@pytest.mark.parametrize("width", THICK_WIDTHS)
def test_thick_shock_before_a_cold_wall(width):
    """thick_shock over N_DRAWS seeds for half widths 0.2-1 mm (count
    test, module docstring).  Calibrated misses: 0, 6 and 714 of 20000
    (the 1 mm shock misses half a cell in 3.6 % of draws); a 2 mm half
    width near the wall biases it by up to 0.9 mm (not tested: the shock
    is then as thick as the standoff)."""
    count_test(f"thick shock {1e3*width:g} mm", thick_shock(width))


def test_compare_nearest_times(case):
    """Cases written at other times (1.1e-05, 2.1e-05 against 1e-05, 2e-05):
    each is taken at its time nearest to the first case's, and says so."""
    other = build(os.path.join(BUILD, "shifted"), times=("1.1e-05", "2.1e-05"))
    path, analyses = psi.compare([case, other], ["A", "B"], os.path.join(BUILD, "compareNearest"))
    with open(path) as f:
        text = f.read()
    assert "each case at its time nearest to A's" in text
    assert "Profiles and histograms at: 1e-05, 2e-05 s" in text
    assert re.search(r"^\| B \| 21 \|", text, re.M)


def test_axis_profile_on_a_graded_mesh():
    """Two blocks whose first rows lie at different radii (0.3 mm for x <
    10 mm, 1.2 mm beyond), second rows further out: every column gives its
    first row's value (1), never a second row's (99)."""
    x = np.repeat((np.arange(40) + 0.5)*DX_CELL, 2)
    first = np.where(x < 0.010, 0.3e-3, 1.2e-3)
    r = np.where(np.arange(80) % 2 == 0, first, 3*first)
    values = np.where(np.arange(80) % 2 == 0, 1.0, 99.0)
    xs, v = psi.axis_profile(x, r, values, cap=0.25*R_NOZZLE)
    assert len(xs) == 40 and np.all(v == 1.0)


def demo_axis(rng, standoff=3e-3, dip=None, dust_top=None, cells=80, noise=0.2):
    """An axis profile like the demo's (80 cells of 0.25 mm): a jet of flat
    density 1e22 with 20 % noise per cell (the batch mean of one axis row:
    about 25 independent simulators per cell), a shock at X_s - standoff
    to 5 x the jet, rising to 40 x at the wall over the last 1 mm (the
    cold-wall layer); dip = (x, depth): the jet 30 % lower over 4 cells
    there (the kind of noise that made the old criterion jump); dust_top
    = x: the gas held off the wall by a dust layer (the density falls to a
    tenth beyond it)."""
    x = (np.arange(cells) + 0.5)*X_S/cells
    x_sh = X_S - standoff
    rho = np.where(x < x_sh, 1e22, 5e22*(1 + 7*np.exp(-(X_S - x)/0.4e-3)))
    if dip is not None:
        rho = np.where(np.abs(x - dip[0]) < 0.5e-3, rho*(1 - dip[1]), rho)
    if dust_top is not None:
        rho = np.where(x > dust_top, 0.1*rho, rho)
    return x, rho*(1 + noise*rng.standard_normal(cells))


DEMO_SHOCK_TOL = 0.25e-3      # one demo cell: the density is known at cell centres


def flat_jet(noise, tolerance):
    """The demo's case: a flat jet with the noise of seed s, standoff 3
    mm, a 30 % dip of the jet over 1 mm at x = 7 mm (about where the hybrid
    demo's spurious 11.9 mm came from): the standoff within tolerance."""
    def scenario(s):
        x, rho = demo_axis(np.random.default_rng(s), dip=(7e-3, 0.3), noise=noise)
        shock = psi.shock_standoff(x, rho, X_S)
        return {f"standoff within {1e3*tolerance:g} mm": shock["standoff"] is not None and
                abs(shock["standoff"] - 3e-3) < tolerance}, shock
    return scenario


@pytest.mark.parametrize("noise, tolerance", [(0.2, 0.4e-3), (0.05, DEMO_SHOCK_TOL)])
def test_shock_on_a_noisy_flat_jet(noise, tolerance):
    """flat_jet over N_DRAWS seeds (count test, module docstring).  Noise
    20 % per cell (one axis row of the demo's batch means): tolerance 0.4
    mm (the 3-cell running mean smears the one-cell step: bias about -0.1
    mm); noise 5 % (the rows within nozzleRadius/8 averaged): one cell,
    0.25 mm.  The old criterion (first midpoint crossing after the global
    minimum) puts the shock at 7-13 mm for most seeds (crater.md): it
    would miss in most draws."""
    count_test(f"flat jet, noise {100*noise:g} %", flat_jet(noise, tolerance))


def dust_layer(s):
    """The gas held off the wall by a dust layer 1 mm thick (the MPPIC
    demo), 5 % noise of seed s: its density peaks at the layer top and
    falls inside the layer.  The shock is searched up to that peak:
    standoff 3 mm within a cell, the peak between 17 and 19 mm."""
    x, rho = demo_axis(np.random.default_rng(s), dust_top=0.019, noise=0.05)
    shock = psi.shock_standoff(x, rho, X_S)
    return {"standoff within a cell, peak at the layer top": shock["standoff"] is not None
            and abs(shock["standoff"] - 3e-3) < DEMO_SHOCK_TOL
            and 0.017 < shock["x_peak"] < 0.019}, shock


def test_shock_before_a_dust_layer():
    """dust_layer over N_DRAWS seeds (count test)."""
    count_test("dust layer", dust_layer)


def no_shock(s):
    """The flat jet of 20 % noise (seed s) without a shock, with a dip and
    a one-cell spike near the wall (a rise not sustained over 3 cells): no
    shock."""
    rng = np.random.default_rng(s)
    x = (np.arange(80) + 0.5)*X_S/80
    rho = 1e22*(1 + 0.2*rng.standard_normal(80))
    rho[25:29] *= 0.6
    rho[-1] *= 4
    shock = psi.shock_standoff(x, rho, X_S)
    return {"no shock (not sustained)": shock["standoff"] is None and
            "sustained" in shock["note"]}, shock


def test_no_shock_in_a_noisy_jet():
    """no_shock over N_DRAWS seeds (count test)."""
    count_test("no shock", no_shock)


def test_axis_band_averages_rows():
    """Rows within the band are averaged with weights r (a wedge cell's
    volume on a uniform radial spacing): four rows 0.125-0.875 mm of one
    column hold 1, 2, 3, 4 -> (0.125 + 0.75 + 1.875 + 3.5)/2 = 3.125; a
    column whose first row lies beyond the band keeps its first row only."""
    rows = np.array([0.125, 0.375, 0.625, 0.875])*1e-3
    x = np.concatenate([np.full(4, 1e-3), np.full(2, 2e-3)])
    r = np.concatenate([rows, [1.5e-3, 2.5e-3]])
    values = np.array([1.0, 2, 3, 4, 7, 99])
    xs, v = psi.axis_profile(x, r, values, cap=2e-3, band=1e-3)
    np.testing.assert_allclose(v, [3.125, 7.0])


# ------------------------------------------ crater of a demo-like layer ----
# The demo's layer (tutorials/psi/apolloScaledPSI, MPPIC): H = 1 mm from
# x = 19 mm to the wall at 20 mm, out to r = 45 mm, 5000 parcels placed at
# random (uniform real-grain density) with the grains' radial weight
# 1 + 9 r/R (parcels sparser, heavier outward, as in the run).

DEMO = dict(surface=0.020, nozzleRadius=0.0081, layerTop=0.019, layerRadius=0.045,
            crossingRadius=0.013)
DEMO_H = 1e-3


def demo_layer(seed, n=5000, height=DEMO_H):
    """n parcels uniform in the wedge's layer of the given height."""
    rng = np.random.default_rng(seed)
    R = DEMO["layerRadius"]
    r = np.empty(0)
    while len(r) < n:                        # density of parcels ~ r/(1 + 9 r/R)
        c = R*np.sqrt(rng.uniform(size=2*n))
        r = np.concatenate([r, c[rng.uniform(size=2*n) < 1/(1 + 9*c/R)]])
    r = r[:n]
    h = height*rng.uniform(size=n)
    a = rng.uniform(-HALF/2, HALF/2, n)
    pos = np.stack([DEMO["surface"] - h, r*np.cos(a), r*np.sin(a)], -1)
    return dict(pos=pos, n=1e7*(1 + 9*r/R))


def heights(p):
    return DEMO["surface"] - p["pos"][:, 0]


def with_heights(p, h, keep=None):
    q = dict(pos=p["pos"].copy(), n=p["n"].copy())
    q["pos"][:, 0] = DEMO["surface"] - h
    if keep is not None:
        q = dict(pos=q["pos"][keep], n=q["n"][keep])
    return q


def untouched(s):
    """The layer of seed s at t = 0 against itself: the surface drop on
    the axis within 3 of its sigma of 0, no annulus with a significant
    drop (crater depth 0), the median sigma 0.015-0.04 mm (0.027 mm for
    100 parcels), nothing eroded."""
    ref = demo_layer(s)
    c = psi.surface_profile(ref, ref, DEMO)
    assert np.all(c["parcels"] >= psi.MIN_PARCELS)        # by construction
    return {"axis drop within 3 sigma of 0": abs(c["surface_drop"]) < 3*c["surface_drop_sigma"],
            "no crater": c["max_depth"] == 0.0 and c["radius"] is None,
            "median sigma in (0.015, 0.04) mm": 0.015e-3 < c["max_depth_sigma"] < 0.04e-3,
            "nothing eroded": abs(c["eroded_layer"]) < 1e-12}, c


def sigma_scale(profiles):
    """The spread of drop/sigma over every annulus of the profiles, robust
    to the quantile's long tail: 1.4826 x the median of |drop/sigma| (1
    for a Gaussian of unit sd)."""
    return 1.4826*float(np.median(np.abs(np.concatenate([c["depth"]/c["sigma"]
                                                          for c in profiles]))))


def test_crater_of_an_untouched_layer_is_zero():
    """untouched over N_LAYERS seeds (count test, module docstring): every
    annulus holds >= 100 parcels (the axis one about 3-4 mm wide).  The
    old definition (slab counts, max over 45 annuli) read 0.97 mm on the
    demo's t = 0: "no crater" would miss in every layer.  Spurious
    craters (the count test z > 3) are rare, not absent (about 1 % of
    layers; judged on drop > 3 sigma instead, 30 %: the quantile's error
    has a long tail toward low surfaces, about 6 effective grains above
    Q_0.9).  The stated sigma against the spread: sigma_scale of the
    N_LAYERS layers' annuli within 1 +- 0.15 (SCALE_CALIBRATION: its mean
    and sd over blocks of N_LAYERS calibration layers; the test asserts
    that 0.15 leaves the comparison's z_limit of that sd).  Not the rms
    (the old check, 1 +- 0.15 over 20 layers): the tail makes it 1.05 +-
    0.05 over blocks of 100 layers (0.15 is 2 sd: a false alarm in about
    3 % of runs), and an outlier of 45 sigma dominates it."""
    results = count_test("untouched layer", untouched, N_LAYERS)
    scale = sigma_scale([c for _, c in results])
    mean, sd = SCALE_CALIBRATION
    assert (0.15 - abs(mean - 1))/sd > rmf_testing.z_limit(COMPARISONS), SCALE_CALIBRATION
    assert report("untouched layer: spread of drop/sigma", abs(scale - 1) < 0.15,
                  f"{scale:.3f} over {N_LAYERS} layers (1 +- 0.15; calibrated {mean:.3f} +- "
                  f"{sd:.3f})")


def compacted(s):
    """The grains of the layer of seed s compacted to half the height (h ->
    h/2): the surface drops by H/2 = 0.5 mm everywhere (3 sigma on the
    axis, 4 sigma for the deepest of ~38 annuli: the max of ~38 Gaussian
    estimates is ~2.3 sigma high) and nothing is eroded (every grain is in
    the dense layer)."""
    ref = demo_layer(s)
    c = psi.surface_profile(with_heights(ref, heights(ref)/2), ref, DEMO)
    return {"axis drop within 3 sigma of H/2":
            abs(c["surface_drop"] - DEMO_H/2) < 3*c["surface_drop_sigma"],
            "crater depth within 4 sigma of H/2":
            abs(c["max_depth"] - DEMO_H/2) < 4*c["max_depth_sigma"],
            "nothing eroded": abs(c["eroded_axis"]) < 1e-12 and abs(c["eroded_layer"]) < 1e-12}, c


def test_compacted_layer_reads_a_surface_drop():
    """compacted over N_LAYERS seeds (count test).  The old definition
    (grain count over the initial packing) read no drop at all."""
    count_test("compacted layer", compacted, N_LAYERS)


CRATER_D, CRATER_R = 0.6e-3, 10e-3


def cratered(ref):
    """A flat-bottomed crater: grains above H - D removed within r < R_c."""
    r, h = psi.radius(ref["pos"]), heights(ref)
    return with_heights(ref, h, ~((r < CRATER_R) & (h > DEMO_H - CRATER_D)))


def known_crater(s):
    """A crater of depth D = 0.6 mm, radius R_c = 10 mm (grains removed)
    in the layer of seed s: surface drop on the axis and crater depth D
    within 3 and 4 sigma (as above); crater radius (half depth) R_c within
    1 mm (the annulus holding R_c averages the two depths; annuli ~1 mm
    wide there, half depth met between their centres: measured 0.2 mm);
    eroded fraction on the axis D/H = 0.6 and of the layer D/H (R_c/R)^2 =
    0.0296, within 3 binomial sigma of the grains counted (about 0.15 and
    0.006)."""
    ref = demo_layer(s)
    c = psi.surface_profile(cratered(ref), ref, DEMO)
    return {"axis drop within 3 sigma of D": abs(c["surface_drop"] - CRATER_D) <
            3*c["surface_drop_sigma"],
            "crater depth within 4 sigma of D": c["max_depth"] is not None and
            abs(c["max_depth"] - CRATER_D) < 4*c["max_depth_sigma"],
            "radius within 1 mm": c["radius"] is not None and
            abs(c["radius"] - CRATER_R) < 1e-3,
            "eroded on the axis within 0.15 of 0.6": abs(c["eroded_axis"] - 0.6) < 0.15,
            "eroded layer within 0.006": abs(c["eroded_layer"] - 0.6*(
                CRATER_R/DEMO["layerRadius"])**2) < 0.006}, c


def test_known_crater():
    """known_crater over N_LAYERS seeds (count test)."""
    count_test("known crater", known_crater, N_LAYERS)


def dilute_ejecta(s):
    """The crater of known_crater (seed s) with a dilute cloud of ejecta
    over it (drawn with seed (s, 1)): 10 % of the layer's real-grain
    density from the crater floor (0.4 mm) to 5 mm above the wall, r < R_c:
    they hold as many real grains as 0.46 mm of layer, enough to lift the
    0.9 quantile into the cloud if counted.  The surface drop and eroded
    fraction on the axis as without the cloud, within one sigma and 0.05
    (the cloud's grains in the slab holding the surface are counted:
    measured 0.01 mm), and the drop within 3 sigma of D."""
    ref = demo_layer(s)
    base = psi.surface_profile(cratered(ref), ref, DEMO)
    rng = np.random.default_rng([s, 1])
    inner = psi.radius(ref["pos"]) < CRATER_R
    cloud_n = int(0.1*inner.sum()*(5e-3 - 0.4e-3)/DEMO_H)
    pick = rng.choice(np.nonzero(inner)[0], cloud_n)
    cloud = with_heights(dict(pos=ref["pos"][pick], n=ref["n"][pick]),
                         rng.uniform(0.4e-3, 5e-3, cloud_n))
    p = cratered(ref)
    p = dict(pos=np.concatenate([p["pos"], cloud["pos"]]), n=np.concatenate([p["n"], cloud["n"]]))
    c = psi.surface_profile(p, ref, DEMO)
    return {"axis drop within 1 sigma of the drop without the cloud":
            abs(c["surface_drop"] - base["surface_drop"]) < c["surface_drop_sigma"],
            "axis drop within 3 sigma of D": abs(c["surface_drop"] - CRATER_D) <
            3*c["surface_drop_sigma"],
            "eroded on the axis within 0.05 of that without the cloud":
            abs(c["eroded_axis"] - base["eroded_axis"]) < 0.05}, c


def test_dilute_ejecta_do_not_raise_the_surface():
    """dilute_ejecta over N_LAYERS seeds (count test)."""
    count_test("dilute ejecta", dilute_ejecta, N_LAYERS)


def test_sparse_layer_is_not_measurable():
    """Fewer than 100 parcels in the whole layer: one annulus, not
    measurable: NaN arrays, None numbers (n/a in the tables).  Exact for
    any draw (60 < 100)."""
    ref = demo_layer(seed(5), n=60)
    c = psi.surface_profile(ref, ref, DEMO)
    assert len(c["r"]) == 1 and np.isnan(c["height"]).all()
    assert c["surface_drop"] is None and c["max_depth"] is None


def demo_rows(s):
    """The demo's mesh near the axis: 80 columns of 0.25 mm, rows at r =
    0.17, 0.39, 0.64, 0.89 and 1.15 mm (the demo's first rows), each cell
    with 20 % noise of its own (a batch mean of ~25 simulators; seed s)
    and the jet dip of flat_jet.  The analysis's profile (psi.axis_density:
    the rows within nozzleRadius/8 = 1.01 mm) finds the standoff within
    one cell (0.25 mm); the first row alone (AXIS_BAND = 0) misses it for
    some draws (seed 12 of the old fixed seeds)."""
    rng = np.random.default_rng(s)
    rows = np.array([0.16871, 0.39366, 0.6411, 0.89175, 1.15])*1e-3
    x = (np.arange(80) + 0.5)*X_S/80
    xs, rs, values = [], [], []
    for r in rows:
        _, rho = demo_axis(rng, dip=(7e-3, 0.3))
        xs.append(x), rs.append(np.full(80, r)), values.append(rho)
    settings = dict(surface=X_S, nozzleRadius=R_NOZZLE)
    xa, rho = psi.axis_density(np.concatenate(xs), np.concatenate(rs),
                               np.concatenate(values), settings)
    assert len(xa) == 80
    shock = psi.shock_standoff(xa, rho, X_S)
    return {"standoff within a cell": shock["standoff"] is not None and
            abs(shock["standoff"] - 3e-3) < DEMO_SHOCK_TOL}, shock


def test_shock_from_the_demo_rows():
    """demo_rows over N_DRAWS seeds (count test)."""
    count_test("demo rows", demo_rows)


# ------------------------------------ count tests and their calibration ----

def scenarios(cells):
    """Every scenario of a count test (and of the case's shock, on its
    cells), by name: {name: (scenario, calibration draws)}."""
    out = {f"case shock {t}": (case_shock(cells, t), CAL_DRAWS) for t in SHOCKS}
    out.update({
        "flat jet, noise 20 %": (flat_jet(0.2, 0.4e-3), CAL_DRAWS),
        "flat jet, noise 5 %": (flat_jet(0.05, DEMO_SHOCK_TOL), CAL_DRAWS),
        "dust layer": (dust_layer, CAL_DRAWS),
        "no shock": (no_shock, CAL_DRAWS),
        "demo rows": (demo_rows, CAL_DRAWS)})
    out.update({f"thick shock {1e3*w:g} mm": (thick_shock(w), CAL_DRAWS) for w in THICK_WIDTHS})
    out.update({"untouched layer": (untouched, CAL_LAYERS),
                "compacted layer": (compacted, CAL_LAYERS),
                "known crater": (known_crater, CAL_LAYERS),
                "dilute ejecta": (dilute_ejecta, CAL_LAYERS)})
    return out


def miss_rate(name, check):
    """Upper bound of the miss rate of a check: the 99.9 % Clopper-Pearson
    bound of its misses among the calibration draws (CALIBRATION)."""
    draws, misses = CALIBRATION[name][0], CALIBRATION[name][1][check]
    return float(stats.beta.ppf(1 - 1e-3, misses + 1, draws - misses))


def miss_limit(n, rate):
    """The most misses among n independent draws that a check may have:
    more has probability at most MODULE_ALPHA/COMPARISONS at the rate."""
    return int(stats.binom.isf(rmf_testing.MODULE_ALPHA/COMPARISONS, n, rate))


def count_test(name, scenario, n=N_DRAWS):
    """Runs scenario for the seeds seed(1) .. seed(n); for each of its
    checks the misses must be at most miss_limit at the calibrated rate,
    and that limit below n (else the check would be vacuous).  Returns the
    per-draw (checks, result)."""
    results = [scenario(seed(k)) for k in range(1, n + 1)]
    ok = True
    for check in results[0][0]:
        misses = sum(not checks[check] for checks, _ in results)
        rate = miss_rate(name, check)
        limit = miss_limit(n, rate)
        ok &= report(f"{name}: {check}", misses <= limit < n,
                     f"{misses} misses in {n} draws (limit {limit}, calibrated miss rate "
                     f"below {rate:.2g})")
    assert ok
    return results


def calibrate():
    """Misses of every check over the calibration draws, seeds CAL_SEED +
    i (outside every seed set's), and sigma_scale over blocks of N_LAYERS
    untouched layers: the figures of CALIBRATION and SCALE_CALIBRATION.  Run (after . etc/bashrc: blockMesh) in the project
    directory as PYTHONPATH=src/python:testing /usr/bin/python3
    validation/psiObservables/test_psiObservables.py."""
    cells = psi.mesh(build(os.path.join(BUILD, "calibration"), times=("0",)))
    for name, (scenario, draws) in scenarios(cells).items():
        misses, profiles, errors = {}, [], []
        for i in range(draws):
            checks, result = scenario(CAL_SEED + i)
            for check, ok in checks.items():
                misses[check] = misses.get(check, 0) + (not ok)
            if name == "untouched layer":
                profiles.append(result)
            if name.startswith("case shock") and result["standoff"] is not None:
                errors.append(result["standoff"] - (X_S - SHOCKS[name.split()[-1]]))
        print(f'    "{name}": ({draws}, {misses}),', flush=True)
        if errors:
            print(f"    error {np.mean(errors):.4e} +- {np.std(errors, ddof=1):.4e}, largest "
                  f"{np.abs(errors).max():.4e} m", flush=True)
        if profiles:
            scale = [sigma_scale(profiles[i:i + N_LAYERS])
                     for i in range(0, len(profiles), N_LAYERS)]
            print(f"    sigma_scale over blocks of {N_LAYERS}: {np.mean(scale):.4f} +- "
                  f"{np.std(scale, ddof=1):.4f} ({len(scale)} blocks)", flush=True)


if __name__ == "__main__":
    calibrate()
