# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""impingingStream, reduced (reduced.py), serial, randomSeed
rmf_testing.seed(7) (outside the reference's 1..6 in every seed set): the
checks of check.py, the analytic inflow rate (within the accumulators'
carry) and the account of simulators (exact), and the surface loads
within the prediction interval of the stored reference (reference.json,
randomSeed 1..K): |x - mean| <= t s sqrt(1 + 1/K), s the reference runs'
sd, t Student's of K - 1 degrees of freedom at MODULE_ALPHA/2 each (here,
not check.py's 1e-3: t 10.7 for K = 6 against check.py's 6.9).
Family-wise error: 2.5e-4 (rmf_testing.MODULE_ALPHA) over m = 2
comparisons (normal force, heat load), Bonferroni, 1.25e-4 each."""

import json
import math
import os

import numpy as np

import check
import reduced
from rmf import foam
from rmf_testing import report, seed, t_limit

BUILD = os.path.join(foam.PROJECT_DIR, "build", "tutorials", "impingingStream")
LOADS = 2


def loads_within_reference(case):
    """(name, ok, text) of each surface load against reference.json's
    prediction interval at the module's share of the budget; none when
    the reference holds no run at the case's time."""
    time = foam.latest_time(case)
    with open(os.path.join(check.HERE, "reference.json")) as f:
        ref = json.load(f).get(time)
    if ref is None:
        return []
    K = len(ref["runs"])
    t = t_limit(K - 1, LOADS)
    results = []
    for name, value in check.surface_loads(case, time).items():
        runs = np.array([r[name] for r in ref["runs"]])
        tol = t*runs.std(ddof=1)*math.sqrt(1 + 1/K)
        results.append((name, abs(value - runs.mean()) <= tol,
                        f"{value:.5g} vs reference {runs.mean():.5g} (tol {tol:.3g}, "
                        f"t {t:.2f})"))
    return results


def test_impingingStream_reduced():
    case = reduced.run(reduced.reduced_case(os.path.join(BUILD, "test"), seed=seed(7)))
    exact = [r for r in check.checks(case) if r[0] in ("inflow per step",
                                                        "account of simulators")]
    loads = loads_within_reference(case)
    assert len(exact) == 2
    assert len(loads) == LOADS, "surface loads not checked: no reference for this time"
    ok = all([report(*r) for r in exact + loads])
    assert ok, [r for r in exact + loads if not r[1]]
