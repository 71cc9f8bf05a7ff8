#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Cost per collision of the gas's bound majorants, sub-stepped per cell
(collisionSubSteps), against upstream's learnt majorant, on the same case;
and, on the dense case, the cost of the particle ES-BGK model (esBGK)
instead of either.

Method: dsmcFoam's freeSpacePeriodic made single-species (nitrogen at
1e20 m^-3 and 300 K, where the tutorial has air: esBGK takes one
species), drifting at 1950 m/s through a periodic box of 5120 cells;
Delta t = tau_c/28) is copied to build/bench/collisionSubSteps/<density>/init, set
to --steps steps, meshed and initialised once per density: as the
tutorial, and dense, its number density and nEquivalentParticles both
times DENSE (the same simulators, Delta t about 10 mean collision
times).  Each repetition runs rarefiedMultiphaseFoam serially on fresh
copies, alternately with upstream's majorant and with collisionSubSteps
(collisionsPerSubStep 1, maxSubSteps 64); each run is timed around the
whole process (wall and CPU, user+sys).  The collisions are the sum of
the log's per-step "Collisions" lines.

Printed per density: the best CPU time of each, the collisions, the
CPU time per collision [ns] and the ratio bound/upstream per collision
and per run, with the bound's acceptance and the largest sub-steps from
the log; on the dense case also a third run per repetition with esBGK
holding every cell in BGK (switchAbove 1: Lambda is about 10), and its
CPU time over upstream's per run.  A ratio in one invocation, not an absolute timing; the exit
status is 0 unless a run fails (a benchmark is not a test).

    . etc/bashrc && bench/collisionSubSteps/bench.py [--steps N] [--repeat R]
"""

import argparse
import os
import re
import resource
import sys
import time

from rmf import foam

BUILD = os.path.join(foam.PROJECT_DIR, "build", "bench", "collisionSubSteps")
DENSE = 280.0
DENSITIES = {"tutorial": 1.0, "dense": DENSE}
SUB_STEPS = "{ collisionsPerSubStep 1; maxSubSteps 64; }"
BGK = "{ switchAbove 1; switchBelow 0.5; }"
GAS = "constant/dsmcProperties"
FILL = "system/dsmcInitialiseDict"
BOUND = re.compile(r"\(largest (\d+)\), capped (\S+); acceptance of the bound (\S+)")


def prepare(name, factor, steps):
    init = foam.copy_case(foam.dsmc_tutorial("freeSpacePeriodic"),
                          os.path.join(BUILD, name, "init"))
    foam.set_steps(init, steps)
    foam.set_entry(init, GAS, "typeIdList", "(N2)")
    foam.remove_entry(init, FILL, "numberDensities/O2")
    foam.set_entry(init, FILL, "numberDensities/N2", f"{1e20*factor:.6g}")
    w = float(foam.get_entry(init, GAS, "nEquivalentParticles"))
    foam.set_entry(init, GAS, "nEquivalentParticles", f"{w*factor:.6g}")
    foam.set_entry(init, GAS, "randomSeed", 1)
    foam.run(init, "blockMesh")
    foam.run(init, "rarefiedMultiphaseInitialise")
    return init


def timed(init, name, rep, model):
    case = foam.copy_case(init, os.path.join(os.path.dirname(init), f"{name}{rep}"))
    if model == "bound":
        foam.set_entry(case, GAS, "collisionSubSteps", SUB_STEPS)
    elif model == "bgk":
        foam.set_entry(case, GAS, "esBGK", BGK)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    log = foam.run(case, "rarefiedMultiphaseFoam")
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    found = foam.log_values(log, "Collisions")
    collisions = found[:, 0].sum() if len(found) else 0.0
    with open(log) as f:
        found = BOUND.findall(f.read())
    return wall, cpu, collisions, found[-1] if found else None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=100)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    summary = []
    for name, factor in DENSITIES.items():
        init = prepare(name, factor, args.steps)
        best = {}
        for rep in range(1, args.repeat + 1):
            for label in ("upstream", "bound") + (("bgk",) if factor > 1 else ()):
                wall, cpu, collisions, extra = timed(init, label, rep, label)
                print(f"bench collisionSubSteps {name} {label} {rep}: wall {wall:.2f} s, "
                      f"CPU {cpu:.2f} s, collisions {collisions:.0f}", flush=True)
                if label not in best or cpu < best[label][0]:
                    best[label] = (cpu, collisions, extra)
        (cu, nu, _), (cb, nb, extra) = best["upstream"], best["bound"]
        line = (f"bench collisionSubSteps {name} (x{factor:g} density): upstream "
                f"{cu:.2f} s, {1e9*cu/nu:.0f} ns per collision; bound {cb:.2f} s, "
                f"{1e9*cb/nb:.0f} ns per collision (collisions {nb/nu:.4f} of "
                f"upstream's); ratio bound/upstream per collision {(cb/nb)/(cu/nu):.3f}, "
                f"per run {cb/cu:.3f}; largest sub-steps {extra[0]}, capped {extra[1]}, "
                f"acceptance of the bound {float(extra[2]):.3f}")
        if "bgk" in best:
            line += f"; esBGK {best['bgk'][0]:.2f} s, over upstream per run {best['bgk'][0]/cu:.3f}"
        summary.append(line)
    print("\n".join(summary))
    return 0


if __name__ == "__main__":
    sys.exit(main())
