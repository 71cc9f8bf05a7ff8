#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Speed of rarefiedMultiphaseFoam's gas against stock dsmcFoam.

Method: for each case (dsmcFoam tutorials; by default freeSpacePeriodic
and supersonicCorner), the tutorial is copied to
build/bench/dsmcParity/<case>/init, set to run --steps steps (endTime =
steps*deltaT, written once at the end, from startTime), meshed with
blockMesh and initialised with dsmcInitialise once.  Each repetition then
runs stock dsmcFoam and our rarefiedMultiphaseFoam, alternately (stock,
ours, stock, ours, ...), one at a time, serially on one rank (no mpirun;
OMPI_/PMIX_ variables are removed from the environment), each on a fresh
copy of the initialised case.  Ours moves the gas with --tracking
(cartesian, its default, or barycentric: upstream's tracking, the same as
dsmcFoam's).  Each run's wall clock is timed from here around the whole
process (start-up and the final write included); its CPU time (user+sys)
is shown beside it, as a check for a busy machine: the wall time of a run
that had a core to itself is close to its CPU time.

Particle-steps: the solvers print per step "Number of molecules = ..." (real
molecules); divided by nEquivalentParticles this gives the simulators of
that step, summed over all steps of the log.  Particle-steps per second
are reported for each solver's best (minimum) time.

The result is a ratio measured in one invocation on one machine, not an
absolute timing: the last lines give, per case, ours/stock of the minimum
times, its inverse (the speed-up) and both rates; the target is 0.2 with
the Cartesian move, 1.10 with upstream's tracking ("MISSES TARGET" when
above).  The exit status is 0 unless a run fails: a benchmark is not a
test.

SPARTA (--sparta BIN, a serial SPARTA binary built from its public
repository, e.g. under build/; not part of the project): on
freeSpacePeriodic, the only case written as a SPARTA input
(sparta/in.freeSpacePeriodic: the same box, cells, gas, weight, step and
collision model), each repetition also runs SPARTA, timed the same way
(the whole process), and the summary adds ours/SPARTA per particle-step
(SPARTA's particle-steps from its "Particle moves" line); the issue's
moonshot is 2 (within twice SPARTA's time per particle-step on a core).

Run from the project directory:

    . etc/bashrc && bench/dsmcParity/bench.py [--case C ...]
        [--tracking cartesian|barycentric] [--steps N] [--repeat R]
        [--sparta BIN]
"""

import argparse
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import time

from rmf import foam

CASES = ("freeSpacePeriodic", "freeSpaceStream", "supersonicCorner", "wedge15Ma5")
SOLVERS = {"stock": "dsmcFoam", "ours": "rarefiedMultiphaseFoam"}
# Largest ratio of the best times, ours/stock, per tracking of ours: the
# Cartesian move at least five times as fast as dsmcFoam (the gas engine
# issue, item 3), upstream's tracking at parity with it
TARGETS = {"cartesian": 0.2, "barycentric": 1.10}
# Largest ratio ours/SPARTA per particle-step (the gas engine issue's
# moonshot: within twice SPARTA's time on a core)
SPARTA_MOONSHOT = 2.0
SPARTA_INPUTS = {"freeSpacePeriodic": os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "sparta")}
SPARTA_MOVES = re.compile(r"^Particle moves\s*=\s*(\d+)", re.M)
BUILD = os.path.join(foam.PROJECT_DIR, "build", "bench", "dsmcParity")
MOLECULES = re.compile(r"^\s*Number of molecules\s*=\s*(\S+)\s*$", re.M)


def prepare(case, steps):
    """Meshed and initialised copy of the tutorial: (root, init)."""
    root = os.path.join(BUILD, case)
    init = foam.copy_case(foam.dsmc_tutorial(case), os.path.join(root, "init"))
    foam.set_steps(init, steps)
    foam.run(init, "blockMesh")
    foam.run(init, "dsmcInitialise")
    return root, init


def particle_steps(log, n_equivalent, steps):
    """Sum over the steps of a solver log of the number of simulators."""
    with open(log) as f:
        molecules = [float(v) for v in MOLECULES.findall(f.read())]
    if len(molecules) != steps:
        raise RuntimeError(f"{log}: {len(molecules)} steps reported, {steps} expected")
    return sum(round(m/n_equivalent) for m in molecules)


def timed_run(root, init, solver, rep, n_equivalent, steps, tracking):
    """Run one solver on a fresh copy of init: (wall, CPU time [s], particle-steps)."""
    case = foam.copy_case(init, os.path.join(root, f"{solver}{rep}"))
    if solver == "ours" and tracking != "cartesian":
        foam.set_entry(case, "constant/dsmcProperties", "tracking", tracking)
    cpu = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    log = foam.run(case, SOLVERS[solver])
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - cpu.ru_utime - cpu.ru_stime
    return wall, cpu, particle_steps(log, n_equivalent, steps)


def timed_sparta(root, sparta, case, rep, steps):
    """Run SPARTA on case's input in a fresh directory: (wall, CPU time
    [s], particle-steps)."""
    run = os.path.join(root, f"sparta{rep}")
    os.makedirs(run, exist_ok=True)
    source = SPARTA_INPUTS[case]
    for name in os.listdir(source):
        shutil.copy(os.path.join(source, name), run)
    cpu = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    log = foam.run(run, sparta, "-in", f"in.{case}", "-var", "steps", str(steps),
                   "-var", "seed", str(12345 + rep), "-log", "none",
                   log="log.sparta")
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - cpu.ru_utime - cpu.ru_stime
    with open(log) as f:
        moves = SPARTA_MOVES.findall(f.read())
    if len(moves) != 1:
        raise RuntimeError(f"{log}: no 'Particle moves' line")
    return wall, cpu, int(moves[0])


def bench_case(case, steps, repeat, tracking, sparta=None):
    """Time both solvers (and SPARTA, if given and the case has an input)
    on one case; print the figures; return the summary line."""
    root, init = prepare(case, steps)
    n_equivalent = float(foam.get_entry(init, "constant/dsmcProperties",
                                        "nEquivalentParticles"))
    print(f"bench dsmcParity {case}: {steps} steps, {repeat} repetitions, serial, "
          f"ours with tracking {tracking}, in {root}")

    runs = list(SOLVERS) + (["sparta"] if sparta and case in SPARTA_INPUTS else [])
    times = {solver: [] for solver in runs}
    cpus = {solver: [] for solver in runs}
    work = {solver: [] for solver in runs}
    for rep in range(1, repeat + 1):
        for solver in runs:
            if solver == "sparta":
                wall, cpu, ps = timed_sparta(root, sparta, case, rep, steps)
            else:
                wall, cpu, ps = timed_run(root, init, solver, rep, n_equivalent,
                                          steps, tracking)
            times[solver].append(wall)
            cpus[solver].append(cpu)
            work[solver].append(ps)
        print(f"  repetition {rep}: stock {times['stock'][-1]:.2f} s, "
              f"ours {times['ours'][-1]:.2f} s, "
              f"ratio {times['ours'][-1]/times['stock'][-1]:.3f} "
              f"(CPU: stock {cpus['stock'][-1]:.2f} s, ours {cpus['ours'][-1]:.2f} s)"
              + (f"; SPARTA {times['sparta'][-1]:.2f} s (CPU {cpus['sparta'][-1]:.2f} s)"
                 if "sparta" in runs else ""),
              flush=True)

    best = {solver: min(times[solver]) for solver in runs}
    rate = {solver: work[solver][times[solver].index(best[solver])]/best[solver]
            for solver in runs}
    median = {solver: statistics.median(times[solver]) for solver in SOLVERS}
    ratio = best["ours"]/best["stock"]
    print(f"  best:   stock {best['stock']:.2f} s, ours {best['ours']:.2f} s, "
          f"ratio {ratio:.3f}")
    print(f"  median: stock {median['stock']:.2f} s, ours {median['ours']:.2f} s, "
          f"ratio {median['ours']/median['stock']:.3f}")
    print(f"  best CPU time (user+sys; wall >> CPU means a busy machine): "
          f"ratio {min(cpus['ours'])/min(cpus['stock']):.3f}")
    print(f"  particle-steps per run: stock {work['stock'][0]}, ours {work['ours'][0]}")
    target = TARGETS[tracking]
    verdict = " MISSES TARGET" if ratio > target else ""
    summary = (f"bench dsmcParity {case} ({tracking}): ratio ours/stock = {ratio:.3f} "
               f"(target <= {target:.2f}){verdict}, speed-up {1/ratio:.2f}, "
               f"stock {rate['stock']:.2e} particle-steps/s, "
               f"ours {rate['ours']:.2e} particle-steps/s")
    if "sparta" in runs:
        print(f"  SPARTA: best {best['sparta']:.2f} s, particle-steps per run "
              f"{work['sparta'][0]}")
        against = rate["sparta"]/rate["ours"]
        verdict = " MISSES MOONSHOT" if against > SPARTA_MOONSHOT else ""
        summary += (f"; ours/SPARTA per particle-step = {against:.2f} (moonshot <= "
                    f"{SPARTA_MOONSHOT:.0f}){verdict}, SPARTA "
                    f"{rate['sparta']:.2e} particle-steps/s")
    return summary


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--case", choices=CASES, nargs="+",
                        default=["freeSpacePeriodic", "supersonicCorner"])
    parser.add_argument("--tracking", choices=tuple(TARGETS), default="cartesian")
    parser.add_argument("--steps", type=int, default=300)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--sparta", metavar="BIN",
                        help="a serial SPARTA binary, run on freeSpacePeriodic too")
    args = parser.parse_args()
    if "FOAM_TUTORIALS" not in os.environ:
        sys.exit("bench dsmcParity: no OpenFOAM environment (. etc/bashrc first)")

    for name in [n for n in os.environ if n.startswith(("OMPI_", "PMIX_"))]:
        del os.environ[name]

    sparta = os.path.abspath(args.sparta) if args.sparta else None
    summaries = [bench_case(case, args.steps, args.repeat, args.tracking, sparta)
                 for case in args.case]
    for line in summaries:
        print(line)


if __name__ == "__main__":
    try:
        main()
    except (subprocess.CalledProcessError, RuntimeError, OSError) as error:
        print(f"bench dsmcParity: FAILED: {error}", file=sys.stderr)
        if getattr(error, "output", None):
            print(error.output, file=sys.stderr)
        sys.exit(1)
