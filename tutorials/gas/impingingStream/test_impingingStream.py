# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""impingingStream, reduced (reduced.py), serial, upstream's random stream:
the checks of check.py (analytic inflow rate, account of simulators,
surface loads within the stored reference's prediction interval)."""

import os

import check
import reduced
from rmf import foam

BUILD = os.path.join(foam.PROJECT_DIR, "build", "tutorials", "impingingStream")


def test_impingingStream_reduced():
    case = reduced.run(reduced.reduced_case(os.path.join(BUILD, "test")))
    results = check.checks(case)
    for name, ok, text in results:
        print(f"{'PASS' if ok else 'FAIL'} {name}: {text}")
    assert len(results) == 4, "surface loads not checked: no reference for this time"
    assert all(ok for _, ok, _ in results), [r for r in results if not r[1]]
