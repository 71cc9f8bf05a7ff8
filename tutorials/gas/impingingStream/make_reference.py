#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Makes reference.json: surface loads of the reduced impingingStream run
(reduced.py) for randomSeed 1..K, the ensemble check.py's prediction
interval comes from.  A changed reference is a reviewed commit with a
reason.

Usage (after . etc/bashrc): make_reference.py [K]   (default 6)
"""

import json
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import check
import reduced
from rmf import foam

BUILD = os.path.join(foam.PROJECT_DIR, "build", "tutorials", "impingingStream", "reference")


def main():
    K = int(sys.argv[1]) if len(sys.argv) > 1 else 6
    cases = [reduced.reduced_case(os.path.join(BUILD, f"seed{k}"), seed=k)
             for k in range(1, K + 1)]
    with ThreadPoolExecutor(max_workers=2) as pool:
        list(pool.map(reduced.run, cases))
    time = foam.latest_time(cases[0])
    ref = {time: {
        "origin": f"rarefiedMultiphaseFoam, reduced settings (reduced.py), "
                  f"serial, randomSeed 1..{K}",
        "runs": [check.surface_loads(c, time) for c in cases],
    }}
    with open(os.path.join(reduced.HERE, "reference.json"), "w") as f:
        json.dump(ref, f, indent=2)
    print(json.dumps(ref, indent=2))


if __name__ == "__main__":
    main()
