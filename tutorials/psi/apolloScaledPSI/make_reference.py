#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Makes the stored ensembles of test_apolloScaledPSI.py:
- reference.json: the observables (test_apolloScaledPSI.observables) of
  the test's reduced run, serial, for randomSeed 2..K+1;
- reference-vibration.json (--vibration): the bend mode's mean level near
  the surface (test_apolloScaledPSI.bend_level) of the run with vibration,
  serial (the test's run is on 2 ranks: the parallel code is tested
  against serial runs), for randomSeed 2..K+1;
- reference-cao.json (--cao): rmf.psi's observables at 20 us of each
  model of test_apolloScaledPSI.CAO and of the main job (the crater
  settings' first 20 us, serial; test_apolloScaledPSI.cao_observables),
  for randomSeed 2..K+1.
The test's prediction intervals come from them.  The test's own runs use
seed 1 of the suite's seed set (1, 501, ...), outside the ensembles, so
that a run is checked against runs it is independent of.  A changed
reference is a reviewed commit with a reason.

Usage (after . etc/bashrc): make_reference.py [--vibration | --cao [--reuse]] [K]
(default K: 24 serial runs, 8 runs with vibration, 4 runs of each model;
--reuse: the models' runs already in build/ are read, not run again)
"""

import json
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import test_apolloScaledPSI as t


def main():
    args = sys.argv[1:]
    vibration, cao, reuse = ("--vibration" in args, "--cao" in args,
                             "--reuse" in args)
    args = [a for a in args if a not in ("--vibration", "--cao", "--reuse")]
    K = int(args[0]) if args else 8 if vibration else 4 if cao else 24
    seeds = range(2, K + 2)
    if cao:
        jobs = [(name, k) for k in seeds for name in t.CAO]
        if reuse:
            cases = [os.path.join(t.BUILD, t.cao_dir(name, k)) for name, k in jobs]
        else:
            with ThreadPoolExecutor(max_workers=2) as pool:
                cases = list(pool.map(lambda job: t.cao_case(*job), jobs))
        runs = {}
        for (name, _), case in zip(jobs, cases):
            runs.setdefault(name, []).append(t.cao_observables(case))
        ref = {
            "origin": ("rarefiedMultiphaseFoam, the crater settings' first 20 us "
                       "(test_apolloScaledPSI.cao_case), serial, each model, "
                       f"randomSeed {seeds[0]}..{seeds[-1]}"),
            "time": t.foam.latest_time(cases[0]),
            "models": runs,
        }
        with open(os.path.join(t.HERE, "reference-cao.json"), "w") as f:
            json.dump(ref, f, indent=2)
        print(json.dumps(ref, indent=2))
        return
    if vibration:
        cases = [t.prepare(os.path.join("reference", f"vibration{k}"), seed=k,
                           steps=t.STEPS_VIBRATION) for k in seeds]
        with ThreadPoolExecutor(max_workers=2) as pool:
            cases = list(pool.map(lambda c: t.run(c, vibration=True), cases))
        runs = [{"bend level near the surface": t.bend_level(c)[0]} for c in cases]
        what = (f"the reduced run with vibration of test_apolloScaledPSI.py "
                f"({t.STEPS_VIBRATION} steps), serial")
        name = "reference-vibration.json"
    else:
        cases = [t.prepare(os.path.join("reference", f"seed{k}"), seed=k) for k in seeds]
        with ThreadPoolExecutor(max_workers=2) as pool:
            cases = list(pool.map(t.run, cases))
        runs = [t.observables(c) for c in cases]
        what = (f"the reduced run of test_apolloScaledPSI.py (hybrid, demo settings, "
                f"{t.STEPS} steps, {t.PARCELS} parcels), serial")
        name = "reference.json"
    ref = {
        "origin": f"rarefiedMultiphaseFoam, {what}, randomSeed {seeds[0]}..{seeds[-1]}",
        "time": t.foam.latest_time(cases[0]),
        "runs": runs,
    }
    with open(os.path.join(t.HERE, name), "w") as f:
        json.dump(ref, f, indent=2)
    print(json.dumps(ref, indent=2))


if __name__ == "__main__":
    main()
