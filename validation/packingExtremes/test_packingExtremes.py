# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The stability matrix's packing rows (doc/speed-accuracy.md, "Stability
at the extremes"): a bed filled just below close packing, alpha_0 = 0.59
against alpha_cp = 0.6, and the Harris-Crighton stress near its
singularity, eps = 1e-12 (doc/physics.md#mppic), with the project's
twoSided packing model, end to end on the solver.

Case: the Snider tutorial's set-up (glass beads d = 0.3 mm, parcels of
749 beads, P_s = 10 Pa, beta = 2, e = 0.85, its damping and isotropy,
cachedDual averaging, dt = 1 ms) in a column of 5 x 5 of its cells
(0.046 m square, 0.3 m high, 40 layers), filled from the floor to
0.1 m at alpha_0 = 0.59 (11 790 parcels) and left to settle under
gravity for 0.3 s, written every 0.05 s.  alpha_0 at or above alpha_cp
is refused by the initialiser (validation/solidInputErrors).

Expected outcome, both runs (written down before they were run): the
bed is held, not blown apart or compacted through its limit.
- Every parcel present and finite at every write, no NaN in the log.
- The packing model's averaged volume fraction (alphaAverage.grains)
  at most 0.68 in every cell at every write: the cell bound of the
  Snider validation (doc/physics.md#mppic, rmf.snider), which this
  parcel weight is set for.
- The bed's mean alpha over the layers below 0.09 m (away from its
  loosening top) within 0.60 +- 0.02 at 0.3 s: the Snider bed's
  tolerance (rmf.snider BED_TOL).
- Above 0.12 m no grains at 0.3 s (alpha < 0.01): the bed neither
  erupts nor throws grains up.
eps = 1e-12 makes the stress at and above alpha_cp some 1e10 times
larger than at eps = 1e-7; the limiter of Snider's eqs. 39-41 caps the
velocity correction a parcel receives, so both runs must meet the same
expected outcome.  Each run is checked against it on its own; the two
runs are not compared with each other.

Not a statistical comparison: the bounds are those of the Snider
validation (rmf.snider), each run one realisation of the case files'
seeds.
"""

import os
import re

import numpy as np
import pytest

from rmf import foam, snider
from rmf_testing import report

BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "packingExtremes")
PROPS = "constant/grainsProperties"
INIT = "system/grainsInitialiseDict"
CELLS, FILL_TOP = 5, 0.1
ALPHA0, END = 0.59, 0.3
BED_BELOW, CLEAR_ABOVE = 0.09, 0.12


def make_case(name, eps):
    case, side = snider.narrow_column(os.path.join(BUILD, name), CELLS)
    region = "regions/column/"
    foam.set_entry(case, INIT, region + "max", f"({side:.6g} {side:.6g} {FILL_TOP:g})")
    foam.remove_entry(case, INIT, region + "nParcels")
    foam.set_entry(case, INIT, region + "alpha0", ALPHA0)
    foam.set_entry(case, PROPS, "subModels/twoSidedCoeffs/particleStressModel/eps", eps)
    foam.set_entry(case, "system/controlDict", "endTime", END)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    foam.run(case, "rarefiedMultiphaseFoam")
    return case


def parcels_at_writes(case):
    """(write times, the first's parcel count, the count at each, whether
    every parcel velocity is finite at each and the log holds no NaN)."""
    times = foam.times(case)
    counts, finite = [], True
    for t in times:
        U = foam.read_list(os.path.join(case, t, "lagrangian", "grains", "U"))
        finite &= bool(np.all(np.isfinite(U)))
        counts.append(snider.n_parcels(case, t))
    with open(os.path.join(case, "log.rarefiedMultiphaseFoam")) as f:
        finite &= "nan" not in f.read().lower()
    return times, counts[0], counts, finite


@pytest.mark.parametrize("eps", [1e-7, 1e-12])
def test_bed_just_below_close_packing(eps):
    case = make_case(f"eps{eps:g}", eps)
    times, n0, counts, finite = parcels_at_writes(case)
    averaged = [snider.averaged_max(case, t) for t in times[1:]]
    ok_n = report(f"eps {eps:g}: parcels kept, finite", finite and set(counts) == {n0},
                  f"{n0} parcels at every one of {len(times)} writes"
                  if set(counts) == {n0} else f"counts {counts}")

    ok_cell = report(f"eps {eps:g}: averaged alpha at most {snider.AVERAGED_CELL_BOUND:.2f}",
                     None not in averaged and max(averaged) <= snider.AVERAGED_CELL_BOUND,
                     "largest per write " + ", ".join(f"{a:.3f}" if a is not None else
                                                      "not written" for a in averaged))

    heights, index = snider.layers(case)
    alpha, _ = snider.profile(case, times[-1], heights, index)
    bed = float(alpha[heights < BED_BELOW].mean())
    ok_bed = report(f"eps {eps:g}: bed mean alpha below {BED_BELOW} m within 0.60 +- "
                    f"{snider.BED_TOL}", abs(bed - snider.ALPHA_PACKED) <= snider.BED_TOL,
                    f"{bed:.4f} at {times[-1]} s (filled at {ALPHA0})")
    top = float(alpha[heights > CLEAR_ABOVE].max())
    ok_top = report(f"eps {eps:g}: nothing above {CLEAR_ABOVE} m", top < snider.CLEAR_MAX,
                    f"largest layer alpha {top:.2g}")
    assert ok_n and ok_cell and ok_bed and ok_top


TRAVEL = re.compile(r"Grain step criterion since the last write: travel \|U\| deltaT/h largest"
                    r" (\S+) \((\S+) parcel-steps above 1\)")


@pytest.mark.parametrize("scale", [1, 10, 50])
def test_long_steps(scale):
    """The stability matrix's "deltaT at 1x, 2x and 10x the MPPIC limit":
    a parcel should cross less than its cell per step (the explicit
    stress correction and the averaging see the parcels once a step;
    doc/physics.md#mppic).  SolidCloud logs at every write the largest
    travel |U| deltaT/h since the last write and warns above 1.  The
    narrow Snider column (the tutorial's settling, twoSided packing, 0.6
    s) at the tutorial's deltaT (1 ms: the falling grains reach about a
    quarter of a cell per step), and at 10 and 50 times it (2x and 10x
    the limit at least, the parcels falling longer between corrections;
    deltaT still divides the write interval).
    Expected: no warning at 1 ms, the warning at 10 and 50 ms with the
    travel at least 2 and 10; every parcel present and finite at every
    write, none lost; the settled bed and the cell bound of the Snider
    checks (rmf.snider: bed 0.60 +- 0.02, averaged alpha at most 0.68)
    are checked at 1 ms and printed at the long steps, where they are
    what the long step costs (measured with packedCells, 2026-12-05:
    travel 0.31, 4.12 and 19.8; at 10 ms the bed's mean 0.556, single
    cells' averaged alpha 2.9, a layer at 0.37 left above 0.16 m and the
    interface 95 mm wide, at 50 ms 0.604, 3.8 and 129 mm)."""
    dt = 1e-3*scale
    case, _ = snider.narrow_column(os.path.join(BUILD, f"dt{scale}"), CELLS)
    foam.set_entry(case, "system/controlDict", "deltaT", f"{dt:g}")
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    log = foam.run(case, "rarefiedMultiphaseFoam")
    with open(log) as f:
        text = f.read()
    rows = [(float(a), float(b)) for a, b in TRAVEL.findall(text)]
    travel = max(r[0] for r in rows) if rows else float("nan")
    warned = "is too long for the grains" in text
    times, n0, counts, finite = parcels_at_writes(case)
    passed, s = snider.check(case, layer_bound=False)
    ok = report(f"deltaT {dt:g} s: step criterion",
                len(rows) == len(times) - 1 and warned == (scale > 1)
                and (travel < 1 if scale == 1 else travel >= (2 if scale == 10 else 10)),
                f"largest travel {travel:.3g} ({len(rows)} reports), warned {warned}"
                f" (expected {scale > 1})")
    ok &= report(f"deltaT {dt:g} s: parcels kept, finite",
                 finite and set(counts) == {n0} and snider.account_lost(case) == 0,
                 f"{n0} parcels at each of {len(times)} writes" if set(counts) == {n0}
                 else f"counts {counts}")
    summary = (f"bed {s.get('bedMean', float('nan')):.4f}, largest averaged alpha "
               f"{s.get('alphaMaxAveragedAll') or float('nan'):.3f}, interface "
               f"{1e3*s.get('interfaceWidth', float('nan')):.1f} mm; the Snider checks "
               f"{'pass' if passed else 'fail'}")
    if scale == 1:
        ok &= report(f"deltaT {dt:g} s: Snider checks", passed, summary)
    else:
        print(f"\ninfo  deltaT {dt:g} s: {summary}")
    assert ok
