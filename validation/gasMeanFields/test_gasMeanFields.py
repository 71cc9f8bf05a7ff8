# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The gasMeanFields function object (doc/physics.md#gas): the gas's mean
velocity, temperatures and pressure from the batch means, in every cell.

- Where every cell has gas (stock dsmcFoam's freeSpacePeriodic tutorial,
  20 steps), the fields equal those of upstream's dsmcFields on the same
  run (the same seed: the same means) to 1e-12 relative: the same
  formulas in another order of operations (the drift's kinetic energy is
  about 24 times the thermal one, so the subtraction loses a factor 24 of
  the 1e-16 round-off).
- Where some cells had no simulator (stock dsmcFoam's supersonicCorner,
  20 steps, with SPARSE times its simulator weight), upstream writes
  nothing (it refuses if a cell or a boundary face has rhoNMean = 0: at
  the tutorial's weight its inlet and outlet faces already do);
  ours writes zero in the empty cells and, in the others and on the
  wall patches (pressure: the normal part of fDMean), the formulas
  recomputed here from the written means, to 1e-12 relative.  The count
  of empty cells in the log is the count of cells with dsmcRhoNMean = 0
  (rhoN's sums start from a tiny value, 1e-300 per cell volume, not 0).

Deterministic: every comparison is exact to round-off between two
functions of the same run's means, whatever the draws (the tutorials'
own, upstream's random stream); no statistical comparison (no share of
the false-alarm budget).  That supersonicCorner at SPARSE times its
weight leaves some cell empty and that every wall is hit are facts of
this deterministic run (26217 of 77760 cells empty; see the PASS line).
"""

import os
import re

import numpy as np

from rmf import foam
from rmf_testing import report

BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "gasMeanFields")
STEPS = 20
K = 1.38065e-23         # Boltzmann's constant as v1912 reads it (etc/controlDict, SICoeffs)
FIELDS = ("UMean", "translationalT", "internalT", "overallT", "p")
ROUND_OFF = 1e-12       # relative: see the docstring
SPARSE = 100            # supersonicCorner's weight factor: some empty cells


def run(name, tutorial, function, sparse=1):
    """The tutorial for STEPS steps with its dsmcFields1 of type function,
    nEquivalentParticles sparse times the tutorial's, written to 17
    digits; returns (case, log, written time)."""
    case = foam.copy_case(foam.dsmc_tutorial(tutorial), os.path.join(BUILD, name))
    foam.set_steps(case, STEPS)
    control = "system/controlDict"
    foam.set_entry(case, control, "functions/dsmcFields1/type", function)
    foam.set_entry(case, control, "writePrecision", 17)
    props = "constant/dsmcProperties"
    w = float(foam.get_entry(case, props, "nEquivalentParticles"))*sparse
    foam.set_entry(case, props, "nEquivalentParticles", f"{w:g}")
    foam.run(case, "blockMesh")
    foam.run(case, "dsmcInitialise")
    log = foam.run(case, "rarefiedMultiphaseFoam")
    return case, log, foam.latest_time(case)


def relative(a, b):
    scale = np.abs(b).max()
    return np.abs(a - b).max()/scale if scale > 0 else np.abs(a).max()


def expected(n, rho, mom, ke, ie, dof):
    """The formulas of the class description, element by element; zero
    without gas."""
    gas = (n > 0) & (rho > 0)
    safe = lambda x: np.where(gas, x, 1.0)
    u = np.where(gas[:, None], mom/safe(rho)[:, None], 0.0)
    thermal = ke - 0.5*rho*np.einsum("ij,ij->i", u, u)
    tt = np.where(gas, 2*thermal/(3*K*safe(n)), 0.0)
    ti = np.where(gas & (dof > 0), 2*ie/(K*np.where(dof > 0, dof, 1.0)), 0.0)
    to = np.where(gas, 2*(thermal + ie)/(K*(3*safe(n) + dof)), 0.0)
    return {"UMean": u, "translationalT": tt, "internalT": ti,
            "overallT": to, "p": n*K*tt}


def test_same_as_dsmcFields_where_every_cell_has_gas():
    ours, _, t = run("oursFull", "freeSpacePeriodic", "gasMeanFields")
    theirs, _, t2 = run("upstreamFull", "freeSpacePeriodic", "dsmcFields")
    n = foam.n_cells(ours)
    assert t == t2
    worst = {f: relative(foam.read_field(os.path.join(ours, t, f), n),
                         foam.read_field(os.path.join(theirs, t, f), n))
             for f in FIELDS}
    assert report("gasMeanFields equals dsmcFields where every cell has gas",
                  max(worst.values()) < ROUND_OFF,
                  "largest relative difference " + ", ".join(
                      f"{f} {v:.1e}" for f, v in worst.items())
                  + f" (tolerance {ROUND_OFF:g}, round-off)")


def test_empty_cells_zero_and_the_rest_from_the_means():
    case, log, t = run("oursEmpty", "supersonicCorner", "gasMeanFields", SPARSE)
    _, _, t2 = run("upstreamEmpty", "supersonicCorner", "dsmcFields", SPARSE)
    upstream_wrote = os.path.exists(os.path.join(BUILD, "upstreamEmpty", t2, "translationalT"))

    nc = foam.n_cells(case)
    read = lambda f: foam.read_field(os.path.join(case, t, f), nc)
    means = [read(f + "Mean") for f in
             ("rhoN", "rhoM", "momentum", "linearKE", "internalE", "iDof")]
    want = expected(*means)
    empty = read("dsmcRhoNMean") == 0
    worst = {f: relative(read(f), want[f]) for f in FIELDS}
    zero = all(np.all(read(f)[empty] == 0) for f in FIELDS)
    with open(log) as f:
        logged = [int(v) for v in re.findall(
            r"cells without gas in the batch \(fields zero\) : (\d+)", f.read())]

    # Walls: p is the normal momentum flux of fDMean
    walls = [name for name, patch in foam.read_boundary(case).items()
             if patch.get("type") == "wall"]
    wall_worst = 0.0
    walls_hit = True
    for w in walls:
        fd = foam.read_patch_field(os.path.join(case, t, "fDMean"), w)
        normals = wall_normals(case, w)
        p = foam.read_patch_field(os.path.join(case, t, "p"), w)
        want_p = np.einsum("ij,ij->i", fd, normals)
        wall_worst = max(wall_worst, relative(p, want_p))
        walls_hit = walls_hit and np.abs(want_p).max() > 0

    ok = report(f"supersonicCorner at {SPARSE} times the weight after {STEPS} steps: cells without gas",
                empty.sum() > 0 and not upstream_wrote and logged[-1:] == [empty.sum()],
                f"{empty.sum()} of {nc} cells with dsmcRhoNMean = 0; logged {logged[-1:]};"
                f" upstream's dsmcFields wrote translationalT: {upstream_wrote}")
    ok &= report("gasMeanFields: zero without gas, the formulas elsewhere",
                 zero and max(worst.values()) < ROUND_OFF and walls and walls_hit
                 and wall_worst < ROUND_OFF,
                 "largest relative difference " + ", ".join(
                     f"{f} {v:.1e}" for f, v in worst.items())
                 + f"; wall pressure on {walls} {wall_worst:.1e} (every wall hit: {walls_hit})"
                 + f" (tolerance {ROUND_OFF:g}); empty cells all zero: {zero}")
    assert ok


def wall_normals(case, patch):
    """Unit normals of a patch's faces (Newell's area vector of each face)."""
    boundary = foam.read_boundary(case)[patch]
    start, size = int(boundary["startFace"]), int(boundary["nFaces"])
    points = foam.read_points(case)
    normals = []
    for face in foam.read_faces(case, start, size):
        p = points[face]
        a = 0.5*np.cross(p, np.roll(p, -1, axis=0)).sum(axis=0)
        normals.append(a/np.linalg.norm(a))
    return np.array(normals)
