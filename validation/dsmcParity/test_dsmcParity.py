# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Parity with stock dsmcFoam on its four tutorials (see parity.py):
exact reproduction with the same random stream, agreement within the
noise of a ten-seed ensemble for an independent-stream and a 2-rank METIS
run, and the initial state against its analytic distribution.  Reduced
runs by default, the tutorials unchanged with --long.

Family-wise error: rmf_testing.MODULE_ALPHA (2.5e-4) per mode over m = 131
comparisons (34 per case, 29 for supersonicCorner), Bonferroni: Student
t_9 10.6-10.8 (ensemble levels), 9.8-10.0 (patterns), normal z 4.7-4.8
(initial state); parity.py's docstring has the details.  Seeds through
rmf_testing.seed (dsmcFoam's own is fixed)."""

import pytest

import parity


def _run(case, full):
    failures = []
    exact, initial, results = parity.check(parity.run_all(case, full))
    print()
    parity.report(case, exact, initial, results)
    if exact:
        failures.append("not identical to dsmcFoam: " + ", ".join(exact))
    failures += [f"initial {name}: {text}" for name, ok, text in initial if not ok]
    failures += [str(r) for r in results if not r.passed]
    assert not failures, "\n".join(failures)


@pytest.mark.parametrize("case", parity.CASES)
def test_parity_reduced(case):
    _run(case, full=False)


@pytest.mark.long
@pytest.mark.parametrize("case", parity.CASES)
def test_parity_full(case):
    _run(case, full=True)
