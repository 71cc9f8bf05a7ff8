#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Cost of a step of the PSI scene, against a previous build of the code.

Case: tutorials/psi/apolloScaledPSI, --variant (default MPPIC) with
--settings (default full: 1.16M cells, 1.0M parcels), meshed and
initialised once.  Each repetition runs the solver serially, each on a
fresh copy, for --steps steps from t = 0 with nothing written: the
previous build first (--previous, a checkout of an earlier commit built
with its own ./Allwmake), then this one.  The cost per step comes from
the solver's own ExecutionTime (CPU) after the first two steps (start-up,
reading the mesh and the parcels, and the first steps' one-off
allocations left out):

    t_step = (ExecutionTime_N - ExecutionTime_2)/(N - 2)

With the default 12 steps the window holds one re-allocation of the
parcels in cell order (every 10 steps, at steps 1, 11, ...), so its cost
is counted in proportion.  Reported: t_step per run, the minimum over the
repetitions, the ratio this/previous (target <= 0.5: issue 16, item 2,
"half of today's") and this build's t_step against the issue's 7 s (full
MPPIC settings).  Without --previous only this build runs.  Exit status 0
unless a run fails.

A previous build, e.g. of the commit before the speed-up:

    git worktree add ../previous <commit> && ../previous/Allwmake

Run from the project directory:

    . etc/bashrc && bench/psiStep/bench.py [--previous DIR]
        [--settings demo|full] [--variant V] [--steps N] [--repeat R]

Defaults: --settings full --variant MPPIC --steps 12 --repeat 1 (about
5 minutes with a previous build, 3.6 GB).
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "src", "python"))
from rmf import foam, psi  # noqa: E402

BUILD = os.path.join(foam.PROJECT_DIR, "build", "bench", "psiStep")
SKIP = 2            # steps left out at the start
TARGET_RATIO = 0.5  # this/previous
TARGET_FULL = 7.0   # s per serial step, full MPPIC settings


def step_cost(init, name, solver):
    """t_step of one run: solver is the command (a list) to run."""
    case = foam.copy_case(init, os.path.join(BUILD, name))
    log = foam.run(case, *solver, log="log.rarefiedMultiphaseFoam")
    et = foam.execution_times(log)
    if len(et) <= SKIP:
        raise RuntimeError(f"{log}: {len(et)} steps timed, need more than {SKIP}")
    return (et[-1] - et[SKIP - 1])/(len(et) - SKIP)


def previous_solver(tree):
    """The command running the solver of the built checkout tree."""
    platforms = os.path.join(os.path.abspath(tree), "platforms")
    solver = os.path.join(platforms, "bin", "rarefiedMultiphaseFoam")
    if not os.access(solver, os.X_OK):
        sys.exit(f"--previous {tree}: no {solver} (build it with its ./Allwmake)")
    libs = os.path.join(platforms, "lib")
    return ["env", f"LD_LIBRARY_PATH={libs}:{os.environ.get('LD_LIBRARY_PATH', '')}",
            solver]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--previous", help="checkout of an earlier commit, built")
    parser.add_argument("--settings", choices=("demo", "full"), default="full")
    parser.add_argument("--variant", choices=("MPPIC", "hybrid", "stochastic"),
                        default="MPPIC")
    parser.add_argument("--steps", type=int, default=12)
    parser.add_argument("--repeat", type=int, default=1)
    args = parser.parse_args()
    if args.steps <= SKIP + 1:
        parser.error(f"--steps must be at least {SKIP + 2}")

    solvers = {"this": ["rarefiedMultiphaseFoam"]}
    if args.previous:
        solvers = {"previous": previous_solver(args.previous), **solvers}

    init = psi.prepare_steps(os.path.join(BUILD, f"{args.settings}-{args.variant}-init"),
                             args.settings, args.variant, args.steps)   # nothing written
    costs = {name: [] for name in solvers}
    for rep in range(args.repeat):
        for name, solver in solvers.items():
            cost = step_cost(init, f"{args.settings}-{args.variant}-{name}-{rep}", solver)
            costs[name].append(cost)
            print(f"repetition {rep}: {name:8s} {cost:.3f} s per step")

    best = {name: min(c) for name, c in costs.items()}
    summary = (f"bench psiStep apolloScaledPSI {args.variant} {args.settings}, "
               f"{args.steps} steps (first {SKIP} left out): this {best['this']:.3f} s per step")
    if "previous" in best:
        ratio = best["this"]/best["previous"]
        verdict = "" if ratio <= TARGET_RATIO else " MISSES TARGET"
        summary += (f", previous {best['previous']:.3f} s; ratio this/previous = "
                    f"{ratio:.3f} (target <= {TARGET_RATIO}){verdict}")
    if args.settings == "full" and args.variant == "MPPIC":
        verdict = "" if best["this"] <= TARGET_FULL else " MISSES TARGET"
        summary += f"; target <= {TARGET_FULL} s{verdict}"
    print(summary + " (CPU)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
