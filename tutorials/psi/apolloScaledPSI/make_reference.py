#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Makes reference.json: the observables (test_apolloScaledPSI.observables)
of the test's reduced run, serial, for randomSeed 2..K+1, the ensemble
the test's prediction intervals come from.  The test's own runs use seed
1, outside the ensemble, so that a run is checked against runs it is
independent of.  A changed reference is a reviewed commit with a reason.

Usage (after . etc/bashrc): make_reference.py [K]   (default 8)
"""

import json
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import test_apolloScaledPSI as t


def main():
    K = int(sys.argv[1]) if len(sys.argv) > 1 else 8
    seeds = range(2, K + 2)
    cases = [t.prepare(os.path.join("reference", f"seed{k}"), seed=k) for k in seeds]
    with ThreadPoolExecutor(max_workers=2) as pool:
        cases = list(pool.map(t.run, cases))
    ref = {
        "origin": f"rarefiedMultiphaseFoam, the reduced run of test_apolloScaledPSI.py "
                  f"(hybrid, demo settings, {t.STEPS} steps, {t.PARCELS} parcels), "
                  f"serial, randomSeed {seeds[0]}..{seeds[-1]}",
        "time": t.foam.latest_time(cases[0]),
        "runs": [t.observables(c) for c in cases],
    }
    with open(os.path.join(t.HERE, "reference.json"), "w") as f:
        json.dump(ref, f, indent=2)
    print(json.dumps(ref, indent=2))


if __name__ == "__main__":
    main()
