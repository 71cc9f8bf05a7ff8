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

The gas (issue 48): --settings crater --variant hybrid is the main job's
case.  Its domain starts empty and fills from the nozzle, so --develop N
first runs this build N steps from t = 0 (written once at the end) and
the timed runs start from there; --np 2 runs them on 2 ranks (the
tutorial's decomposition of the developed state).  Reported besides the
step: the CPU per simulator-step, the window's CPU over the sum of the
simulators present at its steps (the gas log's 'Simulators present'), and
its ratio this/previous (target <= 1/3: the gas engine issue, item 3).

    . etc/bashrc && bench/psiStep/bench.py --previous DIR --settings crater
        --variant hybrid --develop 2000 --steps 200 [--np 2]
"""

import argparse
import os
import sys

from rmf import foam, psi

BUILD = os.path.join(foam.PROJECT_DIR, "build", "bench", "psiStep")
SKIP = 2            # steps left out at the start
TARGET_RATIO = 0.5  # this/previous
TARGET_FULL = 7.0   # s per serial step, full MPPIC settings
TARGET_GAS = 1/3    # this/previous, CPU per simulator-step (crater settings)


def step_cost(init, name, solver, np_=1):
    """t_step of one run and its CPU per simulator-step (None without a
    gas): solver is the command (a list) to run."""
    case = foam.copy_case(init, os.path.join(BUILD, name))
    log = foam.run(case, *solver, log="log.rarefiedMultiphaseFoam", np_=np_)
    et = foam.execution_times(log)
    if len(et) <= SKIP:
        raise RuntimeError(f"{log}: {len(et)} steps timed, need more than {SKIP}")
    cost = (et[-1] - et[SKIP - 1])/(len(et) - SKIP)
    present = foam.log_values(log, "Simulators present")
    if len(present) == 0:
        return cost, None
    if len(present) != len(et):
        raise RuntimeError(f"{log}: {len(et)} steps timed, {len(present)} gas counts")
    return cost, (et[-1] - et[SKIP - 1])/present[SKIP:, 0].sum()


def developed(init, settings, steps, develop, np_):
    """Run init develop steps from t = 0 with this build and set it to run
    steps more from there (decomposed for np_ > 1)."""
    foam.run(init, "rarefiedMultiphaseFoam")
    dt = float(foam.get_entry(init, f"settings/{settings}", "deltaT"))
    foam.set_entry(init, f"settings/{settings}", "endTime", f"{(develop + steps)*dt:.6g}")
    foam.set_entry(init, f"settings/{settings}", "writeInterval",
                   f"{10*(develop + steps)*dt:.6g}")
    if np_ > 1:
        foam.run(init, "decomposePar", "-latestTime")
    return init


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
    parser.add_argument("--settings", choices=("demo", "crater", "full"),
                        default="full")
    parser.add_argument("--variant", choices=("MPPIC", "hybrid", "stochastic"),
                        default="MPPIC")
    parser.add_argument("--steps", type=int, default=12)
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--develop", type=int, default=0,
                        help="steps run from t = 0 before the timed ones")
    parser.add_argument("--np", type=int, default=1, help="ranks")
    args = parser.parse_args()
    if args.steps <= SKIP + 1:
        parser.error(f"--steps must be at least {SKIP + 2}")

    solvers = {"this": ["rarefiedMultiphaseFoam"]}
    if args.previous:
        solvers = {"previous": previous_solver(args.previous), **solvers}

    name = f"{args.settings}-{args.variant}-np{args.np}"
    if args.develop:
        init = psi.prepare_steps(os.path.join(BUILD, f"{name}-init"), args.settings,
                                 args.variant, args.develop, write_steps=args.develop)
        developed(init, args.settings, args.steps, args.develop, args.np)
    else:
        init = psi.prepare_steps(os.path.join(BUILD, f"{name}-init"),
                                 args.settings, args.variant, args.steps)  # nothing written
    costs = {solver: [] for solver in solvers}
    gas = {solver: [] for solver in solvers}
    for rep in range(args.repeat):
        for solver, command in solvers.items():
            cost, per_simulator = step_cost(init, f"{name}-{solver}-{rep}", command, args.np)
            costs[solver].append(cost)
            gas[solver].append(per_simulator)
            figures = f"{cost:.3f} s per step"
            if per_simulator:
                figures += f", {1e6*per_simulator:.3f} us per simulator-step"
            print(f"repetition {rep}: {solver:8s} {figures}")

    best = {solver: min(c) for solver, c in costs.items()}
    summary = (f"bench psiStep apolloScaledPSI {args.variant} {args.settings}, "
               f"{args.np} rank(s), {args.steps} steps (first {SKIP} left out"
               f"{f', after {args.develop}' if args.develop else ''}): "
               f"this {best['this']:.3f} s per step")
    if "previous" in best:
        ratio = best["this"]/best["previous"]
        summary += (f", previous {best['previous']:.3f} s; ratio this/previous = "
                    f"{ratio:.3f}")
        if args.settings != "crater":   # the gas's target is per simulator-step
            verdict = "" if ratio <= TARGET_RATIO else " MISSES TARGET"
            summary += f" (target <= {TARGET_RATIO}){verdict}"
    if all(all(g) for g in gas.values()):
        per = {solver: min(g) for solver, g in gas.items()}
        summary += f"; gas: this {1e6*per['this']:.3f} us per simulator-step"
        if "previous" in per:
            ratio = per["this"]/per["previous"]
            verdict = "" if ratio <= TARGET_GAS else " MISSES TARGET"
            summary += (f", previous {1e6*per['previous']:.3f} us; ratio this/previous = "
                        f"{ratio:.3f} (target <= {TARGET_GAS:.3f}){verdict}")
    if args.settings == "full" and args.variant == "MPPIC":
        verdict = "" if best["this"] <= TARGET_FULL else " MISSES TARGET"
        summary += f"; target <= {TARGET_FULL} s{verdict}"
    print(summary + " (CPU)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
