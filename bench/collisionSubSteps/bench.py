#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Cost per collision of the gas's bound majorants, sub-stepped per cell
(collisionSubSteps), against upstream's learnt majorant, on the same case.

Method: dsmcFoam's freeSpacePeriodic (air at 1e20 m^-3 and 300 K,
drifting at 1950 m/s through a periodic box of 5120 cells; Delta t =
tau_c/28) is copied to build/bench/collisionSubSteps/<density>/init, set
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
the log.  A ratio in one invocation, not an absolute timing; the exit
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
GAS = "constant/dsmcProperties"
FILL = "system/dsmcInitialiseDict"
BOUND = re.compile(r"\(largest (\d+)\), capped (\S+); acceptance of the bound (\S+)")


def prepare(name, factor, steps):
    init = foam.copy_case(foam.dsmc_tutorial("freeSpacePeriodic"),
                          os.path.join(BUILD, name, "init"))
    foam.set_steps(init, steps)
    for species in ("N2", "O2"):
        n = float(foam.get_entry(init, FILL, f"numberDensities/{species}"))
        foam.set_entry(init, FILL, f"numberDensities/{species}", f"{n*factor:.6g}")
    w = float(foam.get_entry(init, GAS, "nEquivalentParticles"))
    foam.set_entry(init, GAS, "nEquivalentParticles", f"{w*factor:.6g}")
    foam.set_entry(init, GAS, "randomSeed", 1)
    foam.run(init, "blockMesh")
    foam.run(init, "rarefiedMultiphaseInitialise")
    return init


def timed(init, name, rep, bound):
    case = foam.copy_case(init, os.path.join(os.path.dirname(init), f"{name}{rep}"))
    if bound:
        foam.set_entry(case, GAS, "collisionSubSteps", SUB_STEPS)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    log = foam.run(case, "rarefiedMultiphaseFoam")
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    collisions = foam.log_values(log, "Collisions")[:, 0].sum()
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
            for label, bound in (("upstream", False), ("bound", True)):
                wall, cpu, collisions, extra = timed(init, label, rep, bound)
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
        summary.append(line)
    print("\n".join(summary))
    return 0


if __name__ == "__main__":
    sys.exit(main())
