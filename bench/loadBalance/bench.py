#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Speed-up of the dense PSI demo on 2 ranks, split by cell count and by
measured cost, against the serial run (doc/physics.md#load-balance).

Case: tutorials/psi/apolloScaledPSI, `-variant hybrid -settings demo` (the
dense demo of issue 16's target; the main job runs `-settings crater`), to
--end (default the demo's 100 us).  Four runs, one after
another, each on a fresh copy through the case's Allrun:

- serial: `./Allrun`;
- byCount: `./Allrun -parallel` with METIS by cell count and the
  controlDict's maxImbalance commented out: never re-balanced (the code
  before the load balance);
- cellCost: METIS with `weightField cellCost` (the phases' sum),
  re-balanced at writes whose imbalance exceeds maxImbalance;
- phaseBalanced: the tutorial as it is (each phase's cost a constraint of
  its own), re-balanced likewise.

Two times per run: the whole job, the wall time of its Allrun (mesh,
initialisation, the (re)decompositions and reconstructions, the solver,
the post-processing: what the user waits for); and the solver's, the sum
of its segments' last "ClockTime".  The speed-ups are serial/parallel of
each; target >= 1.7 for the tutorial's (phaseBalanced) whole job (the
speed issue).  The imbalance lines of the parallel
logs are summarised (mean of max/mean over the writes, overall and per
phase).  Run on an otherwise idle machine: the parallel runs need both
cores.

    . etc/bashrc && bench/loadBalance/bench.py [--end T]
"""

import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import time

from rmf import foam

TUTORIAL = os.path.join(foam.PROJECT_DIR, "tutorials", "psi", "apolloScaledPSI")
BUILD = os.path.join(foam.PROJECT_DIR, "build", "bench", "loadBalance")
TARGET = 1.7
BALANCE = re.compile(r"Load balance since the last write: compute time per processor "
                     r"max/mean = (\S+) \(.*gas (\S+), coupling (\S+), grains (\S+)\)")


METIS = "method              metis;"


def prepare(name, end):
    case = os.path.join(BUILD, name)
    if os.path.exists(case):
        shutil.rmtree(case)
    shutil.copytree(TUTORIAL, case, ignore=shutil.ignore_patterns(
        "test_*.py", "__pycache__", "log.*", "observables", "processor*",
        "[1-9]*", "polyMesh", "lagrangian", "uniform", "*SigmaTcRMax"))
    subprocess.run([os.path.join(case, "Allclean")], check=True,
                   stdout=subprocess.DEVNULL)
    if end:
        foam.substitute(os.path.join(case, "settings", "demo"),
                        r"(\nendTime\s+)[^;]+;", rf"\g<1>{end};")
    decompose = os.path.join(case, "system", "decomposeParDict")
    if name == "byCount":
        foam.substitute(os.path.join(case, "system", "controlDict"),
                        r"maxImbalance\s+[^;]+;", r"// \g<0>")
        foam.substitute(decompose, r"method\s+phaseBalanced;", METIS)
    elif name == "cellCost":
        foam.substitute(decompose, r"method\s+phaseBalanced;",
                        METIS + "\nweightField         cellCost;")
    return case


def last_clock(log):
    found = foam.execution_times(log, clock=True)
    return found[-1] if found else 0.0


def run(case, parallel):
    """Wall time [s] of the whole Allrun and of the solver's segments, the
    number of re-balances, and the imbalance lines."""
    start = time.monotonic()
    proc = subprocess.run([os.path.join(case, "Allrun"), "-variant", "hybrid",
                           "-settings", "demo"] + (["-parallel"] if parallel else []),
                          cwd=case, capture_output=True, text=True)
    whole = time.monotonic() - start
    if proc.returncode != 0:
        sys.exit(f"{case}: Allrun failed\n{proc.stdout[-2000:]}{proc.stderr[-2000:]}")
    logs = sorted(glob.glob(os.path.join(case, "log.rarefiedMultiphaseFoam*")))
    solver = sum(last_clock(log) for log in logs)
    balance = []
    for log in logs:
        with open(log) as f:
            balance += [tuple(float(x) for x in m) for m in BALANCE.findall(f.read())]
    return whole, solver, len(logs) - 1, balance


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--end", help="endTime [s] (default: the demo's)")
    args = parser.parse_args()

    load = os.getloadavg()[0]
    results = {}
    for name in ("serial", "byCount", "cellCost", "phaseBalanced"):
        parallel = name != "serial"
        results[name] = run(prepare(name, args.end), parallel)
        whole, solver, rebalances, balance = results[name]
        line = f"{name}: whole job {whole:.1f} s, solver {solver:.1f} s"
        if parallel:
            n = max(len(balance), 1)
            line += (f"; speed-up {results['serial'][0]/whole:.2f} (solver "
                     f"{results['serial'][1]/solver:.2f}), {rebalances} re-balances, "
                     f"imbalance max/mean over the writes: mean "
                     f"{sum(b[0] for b in balance)/n:.3f} (gas "
                     f"{sum(b[1] for b in balance)/n:.3f}, coupling "
                     f"{sum(b[2] for b in balance)/n:.3f}, grains "
                     f"{sum(b[3] for b in balance)/n:.3f}), largest "
                     f"{max((b[0] for b in balance), default=1):.3f}")
        print(line, flush=True)

    def speedup(name):
        return (results["serial"][0]/results[name][0],
                results["serial"][1]/results[name][1])

    verdict = "" if speedup("phaseBalanced")[0] >= TARGET else "  MISSES TARGET"
    print(f"bench loadBalance apolloScaledPSI hybrid demo (load average {load:.2f} at "
          f"the start): speed-up on 2 ranks, whole job (solver): by cell count "
          + ", by cellCost ".join(f"{a:.2f} ({b:.2f})" for a, b in
                                  (speedup("byCount"), speedup("cellCost")))
          + f", phaseBalanced {speedup('phaseBalanced')[0]:.2f} "
          f"({speedup('phaseBalanced')[1]:.2f}) (target >= {TARGET}){verdict}")


if __name__ == "__main__":
    main()
