#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Cost of a step with averagingMethod cachedDual against upstream's dual.

Case: tutorials/psi/apolloScaledPSI, variant MPPIC (explicit packing,
relaxation damping, stochastic isotropy: about eleven averages built per
step), settings --settings (demo: 8160 cells, 5000 parcels; full: 1.16M
cells, 1.0M parcels), meshed and initialised once.  Each repetition runs
the solver serially with dual and then with cachedDual, each on a fresh
copy, for --steps steps from t = 0.  The cost per step is taken from the
solver's own ExecutionTime (CPU) between the end of its first and its last
step, so start-up (reading the mesh and the parcels) and the first step
are left out:

    t_step = (ExecutionTime_N - ExecutionTime_1)/(N - 1)

Reported: t_step of each per repetition, the minimum over the repetitions
and the ratio cachedDual/dual of the minima (target < 1: cachedDual gives
the same results, checked here too: the last time directories must be
byte-identical, every file below them but the measured cost per cell
(cellCost*: timings the tutorial writes for its load balance, different
in every run), else the run counts as failed).  Exit status 0 unless a
run fails.  The demo's first steps (the jet still on its way: ~140 steps)
hold no dense gas-grain work, so the demo's ratio over its whole run is
nearer 1 than over the first steps; --steps 2000 runs the whole demo.

Run from the project directory:

    . etc/bashrc && bench/cachedDual/bench.py [--settings demo|full]
        [--steps N] [--repeat R]

Defaults: --settings full --steps 3 --repeat 1 (about 3 minutes, 3.3 GB).
"""

import argparse
import os
import sys

from rmf import foam, psi

BUILD = os.path.join(foam.PROJECT_DIR, "build", "bench", "cachedDual")
METHODS = ("dual", "cachedDual")


def timings(fa, fb, rel):
    """The measured cost per cell (cellCost and its parts, cellCost*):
    CPU times, never equal in two runs"""
    return os.path.basename(fa).startswith("cellCost")


def step_cost(init, settings, method, rep):
    case = foam.copy_case(init, os.path.join(BUILD, f"{settings}-{method}-{rep}"))
    foam.set_entry(case, "settings/MPPIC", "averaging", method)
    log = foam.run(case, "rarefiedMultiphaseFoam")
    et = foam.execution_times(log)
    if len(et) < 2:
        raise RuntimeError(f"{log}: fewer than 2 steps timed")
    return (et[-1] - et[0])/(len(et) - 1), case


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--settings", choices=("demo", "full"), default="full")
    parser.add_argument("--steps", type=int, default=3)
    parser.add_argument("--repeat", type=int, default=1)
    args = parser.parse_args()
    if args.steps < 2:
        parser.error("--steps must be at least 2")

    # The last step written: the two methods' results are compared
    init = psi.prepare_steps(os.path.join(BUILD, f"{args.settings}-init"), args.settings,
                             "MPPIC", args.steps, write_steps=args.steps)
    costs = {m: [] for m in METHODS}
    for rep in range(args.repeat):
        cases = {}
        for method in METHODS:
            cost, cases[method] = step_cost(init, args.settings, method, rep)
            costs[method].append(cost)
            print(f"repetition {rep}: {method:10s} {cost:.3f} s per step")
        last = {m: os.path.join(c, foam.latest_time(c)) for m, c in cases.items()}
        differ = foam.differing_files(last["dual"], last["cachedDual"], equivalent=timings)
        if differ:
            print(f"FAILED: dual and cachedDual differ: {differ[:5]}")
            return 1

    best = {m: min(c) for m, c in costs.items()}
    ratio = best["cachedDual"]/best["dual"]
    verdict = "" if ratio < 1 else " MISSES TARGET"
    print(f"bench cachedDual apolloScaledPSI MPPIC {args.settings}, {args.steps} steps: "
          f"ratio cachedDual/dual = {ratio:.3f} (target < 1){verdict}, "
          f"dual {best['dual']:.3f} s per step, cachedDual {best['cachedDual']:.3f} s "
          f"per step (CPU, first step left out); results identical")
    return 0


if __name__ == "__main__":
    sys.exit(main())
