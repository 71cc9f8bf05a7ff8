# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The stability matrix's "one simulator per cell"
(doc/speed-accuracy.md, "Stability at the extremes"), end to end on the
solver.

Case: stock dsmcFoam's freeSpacePeriodic tutorial (N2 + O2, 300 K,
drifting at 1950 m/s, 5120 cells, fully periodic: nothing enters or
leaves) with nEquivalentParticles 12.5 times the tutorial's, about one
simulator per cell (5128), 40 steps of the tutorial's deltaT, with its
function objects (fieldAverage, dsmcFields).  Most cells hold 0, 1 or 2
simulators: NTC collides only in cells with two or more, and the cell
averages (lambda.gas, the step criteria, dsmcFields' temperatures) meet
cells with no gas.

Expected outcome (written before the run):
- the run completes; the simulator count is the fill's at every step
  (the account: none in, none out);
- upstream's system totals, momentum and total energy, constant to the
  10 digits the log prints (1e-9 relative): NTC conserves both per pair
  and nothing else acts;
- collisions do happen (cells with two simulators), and the collision
  and transit criteria are logged as numbers;
- every written cell field (the sampled ones, dsmcFields', lambda.gas)
  finite: no NaN from an empty cell;
- the step's sampled fields (SAMPLED) zero in every cell that held no
  simulator at the write (dsmcRhoN 0; about 1900 of the 5120 cells):
  at most ZERO, as rhoN, rhoM and iDof start from upstream's VSMALL,
  written 1e-280 once scaled to real densities.  The time averages
  (the ...Mean fields and dsmcFields' outputs made from them) and
  lambda.gas (the gas cell averages' window) average over steps in
  which the cell held gas: only finite.
Not checked here: the collision rate, which in so sparse a gas waits on
the majorant's convergence (validation/stepCriteria's NTC guard).
"""

import glob
import math
import os
import re

import numpy as np

from rmf import foam
from rmf_testing import report

BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "sparseGas")
STEPS = 40
SPARSE = 12.5           # nEquivalentParticles over the tutorial's
SAMPLED = ("dsmcRhoN", "rhoN", "rhoM", "iDof", "linearKE", "momentum", "internalE")
ZERO = 1e-250           # upstream's VSMALL floor of rhoN, rhoM, iDof (1e-280 written)


def test_one_simulator_per_cell():
    case = foam.copy_case(foam.dsmc_tutorial("freeSpacePeriodic"),
                          os.path.join(BUILD, "oneSimulatorPerCell"))
    props = "constant/dsmcProperties"
    w = float(foam.get_entry(case, props, "nEquivalentParticles"))*SPARSE
    foam.set_entry(case, props, "nEquivalentParticles", f"{w:g}")
    foam.set_steps(case, STEPS)
    foam.run(case, "blockMesh")
    foam.run(case, "dsmcInitialise")
    log = foam.run(case, "rarefiedMultiphaseFoam")
    with open(log) as f:
        text = f.read()

    present = foam.log_values(log, "Simulators present")[:, 0]
    n_cells = foam.n_cells(case)
    momentum = foam.log_values(log, "Average linear momentum")
    energy = foam.log_values(log, "Average total energy")[:, 0]
    collisions = foam.log_values(log, "Collisions")[:, 0]
    criteria = re.search(r"deltaT/\(mean collision time\) largest (\S+) .*transit .* "
                         r"deltaT/h largest (\S+) ", text)

    ok = report("one simulator per cell: run and account",
                len(present) == STEPS and len(set(present)) == 1
                and "Simulators in / out since start = 0 / 0" in text,
                f"{present[0]:.0f} simulators in {n_cells} cells "
                f"({present[0]/n_cells:.2f} per cell) at each of {len(present)} steps")
    dp = np.abs(momentum - momentum[0]).max()/np.abs(momentum[0]).max()
    de = np.abs(energy/energy[0] - 1).max()
    ok &= report("one simulator per cell: momentum and energy", dp < 1e-9 and de < 1e-9,
                 f"largest relative change: momentum {dp:.1e}, total energy {de:.1e}"
                 " (tolerance 1e-9, the log's digits)")
    ok &= report("one simulator per cell: collisions and criteria",
                 collisions.sum() > 0 and criteria is not None
                 and all(math.isfinite(float(v)) for v in criteria.groups()),
                 f"{collisions.sum():.0f} collisions in {STEPS} steps; criteria "
                 f"{criteria.groups() if criteria else None}")

    t = foam.latest_time(case)
    bad = []
    checked = 0
    empty = foam.read_field(os.path.join(case, t, "dsmcRhoN"), n_cells) == 0
    not_zero, sampled = [], []
    for path in sorted(glob.glob(os.path.join(case, t, "*"))):
        if not os.path.isfile(path):
            continue
        try:
            values = foam.read_field(path, n_cells)
        except ValueError:
            continue        # not a cell field
        checked += 1
        if not np.all(np.isfinite(values)):
            bad.append(os.path.basename(path))
        name = os.path.basename(path)
        if name in SAMPLED:
            largest = np.abs(values[empty]).max()
            if not largest <= ZERO:
                not_zero.append(f"{name} {largest:.3g}")
            sampled.append(name)
    ok &= report("one simulator per cell: written fields finite",
                 checked >= 20 and not bad,
                 f"{checked} cell fields at {t} s, non-finite: {bad or 'none'}")
    ok &= report("one simulator per cell: sampled fields zero where no gas",
                 sorted(sampled) == sorted(SAMPLED) and empty.sum() > 0.1*n_cells
                 and not not_zero,
                 f"{empty.sum()} cells without a simulator at the write; "
                 f"{len(sampled)} of {len(SAMPLED)} sampled fields read, "
                 f"above {ZERO:g} there: {not_zero or 'none'}")
    assert ok
