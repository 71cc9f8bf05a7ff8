# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The grains' Cartesian tracking (tracking cartesian,
doc/physics.md#grain-tracking) follows upstream's barycentric tracking to
round-off.

A reduced copy of the Snider sedimentation set-up (20 000 parcels, MPPIC
as the tutorial has it: twoSided packing, relaxation damping, walls
rebounding with e = 0.85; but no isotropy model and packedCells false,
see below) falls for STEPS = 40 steps of 1 ms from one initial state,
once with tracking barycentric (upstream's tet tracking everywhere) and
once with cartesian (every cell of the column is a blockMesh box),
serially and on 2 METIS ranks (parcels cross the processor boundary as
they fall), written with 17 digits.  In that time free fall would be
7.8 mm; the parcels fall 5.9 mm on average (the bed forming at the floor
holds those below), 15 882 of the 20 000 into another of the 9.2 mm
cells, and those at the floor rebound off it.

Expected: the same parcels (matched by origProcId, origId, since the
cloud re-orders its parcels) in the same cells, at positions and with
velocities that agree to round-off.  Tolerances: POSITION_TOL = 1e-9 m
(1e-7 of a cell) and VELOCITY_TOL = 1e-6 m/s (the fall is 0.39 m/s).
Measured: 7.6e-14 m and 5.6e-12 m/s, serially and on 2 ranks.  Later, as the bed forms, the packing
model amplifies any round-off: at 80 steps the two trackings differ by
up to 6.9e-9 m and 1.2e-6 m/s, in the same cells.  That is why the
comparison stops at 40 steps.

Why no isotropy model: the tutorial's (restartableStochastic, upstream's
algorithm) redraws a parcel's velocity when a uniform draw exceeds
exp(-dt/tau) interpolated at the parcel, and a redraw takes further
draws from the cloud's one stream.  tau comes from cell averages near
close packing, which turn round-off into visible differences (here
exp(-dt/tau) differed by 1e-3 at one parcel after the first step); one
comparison flips, and the later parcels in the list draw other
numbers.  With it, the two trackings differ by up to 0.66 m/s
after a single step (676 of 20 000 parcels), while their positions agree
to 5e-16 m and the velocities before the redraw to 1e-16.  The
comparison would then test the stream, not the tracking.

Why packedCells false: it stops a parcel where its cell's or a
neighbour's averaged alpha reaches alpha_cp (doc/physics.md#two-sided), and
at 40 steps the two trackings then differ by up to 3.8e-9 m serially
and 3.0e-8 m on 2 ranks, in the same cells: the bed forming at the floor
amplifies round-off sooner, as it does later without it.

A face found on the wrong side, a parcel put into the wrong tetrahedron
or a wall hit missed moves a parcel by up to a cell, 1e7 times the
tolerance.  So that the comparison is not trivial, the parcels must
have fallen 5 mm on average and (serially) more than half of them into
another cell.

Deterministic: no statistical comparison.
"""

import os

import numpy as np

from rmf import foam, snider

BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "grainTracking")
PROPS = "constant/grainsProperties"
PARCELS = 20000         # of the tutorial's weight per alpha_0 (rmf.snider)
STEPS = 40
POSITION_TOL = 1e-9     # m
VELOCITY_TOL = 1e-6     # m/s


def initial_state(name):
    return snider.reduced_column(
        os.path.join(BUILD, name), PARCELS, STEPS,
        {("system/controlDict", "writePrecision"): 17,
         (PROPS, "subModels/isotropyModel"): "none",
         (PROPS, "subModels/twoSidedCoeffs/packedCells"): "false"})


def run(base, tracking, np_):
    """The run with that tracking: its log and its last parcels, in the
    order of their identities."""
    case = foam.copy_case(base, f"{base}-{tracking}")
    foam.set_entry(case, PROPS, "tracking", tracking)
    if np_ > 1:
        foam.run(case, "decomposePar")
    log = foam.run(case, "rarefiedMultiphaseFoam", np_=np_)
    if np_ > 1:
        foam.run(case, "reconstructPar", "-latestTime")
    time = foam.latest_time(case)
    assert time != "0", f"{case}: the run wrote no time"
    path = os.path.join(case, time, "lagrangian", "grains")
    x, cells = foam.read_positions(os.path.join(path, "positions"), cells=True)
    U = foam.read_list(os.path.join(path, "U"))
    ident = (foam.read_list(os.path.join(path, "origProcId")).astype(np.int64) << 32) \
        + foam.read_list(os.path.join(path, "origId")).astype(np.int64)
    order = np.argsort(ident, kind="stable")
    return log, ident[order], x[order], cells[order], U[order]


def compare(np_):
    base = initial_state(f"np{np_}")
    start = os.path.join(base, "0", "lagrangian", "grains")
    x0, c0 = foam.read_positions(os.path.join(start, "positions"), cells=True)
    c0 = c0[np.argsort(foam.read_list(os.path.join(start, "origId")), kind="stable")]
    logs = {}
    runs = {}
    for tracking in ("barycentric", "cartesian"):
        logs[tracking], *runs[tracking] = run(base, tracking, np_)
    ib, xb, cb, Ub = runs["barycentric"]
    ic, xc, cc, Uc = runs["cartesian"]

    with open(logs["cartesian"]) as f:
        assert "Grain tracking (grains): Cartesian through 9000 of 9000 cells" in f.read()
    assert len(ib) == PARCELS and np.array_equal(ib, ic), "not the same parcels"

    # The runs moved the parcels (free fall would be 7.8 mm)
    fallen = np.abs(np.mean(xb[:, 2]) - np.mean(x0[:, 2]))
    assert fallen > 5e-3, f"the parcels fell {fallen*1e3:.2f} mm on average"
    # ... and most across a face (serially, where origId alone names them)
    if np_ == 1:
        moved = np.count_nonzero(cb != c0)
        assert moved > PARCELS/2, f"{moved} parcels changed cell"
        print(f"{moved} parcels in another cell than at the start")

    dx = np.max(np.linalg.norm(xc - xb, axis=1))
    dU = np.max(np.linalg.norm(Uc - Ub, axis=1))
    other_cell = np.count_nonzero(cc != cb)
    print(f"{np_} rank(s), {STEPS} steps: mean fall {fallen*1e3:.1f} mm; largest "
          f"|x_cartesian - x_barycentric| {dx:.3g} m, |U| {dU:.3g} m/s; "
          f"{other_cell} parcels in another cell")
    assert other_cell == 0, f"{other_cell} parcels in another cell"
    assert dx <= POSITION_TOL, f"positions differ by up to {dx:.3g} m"
    assert dU <= VELOCITY_TOL, f"velocities differ by up to {dU:.3g} m/s"


def test_cartesian_is_barycentric():
    compare(1)


def test_cartesian_is_barycentric_parallel():
    compare(2)
