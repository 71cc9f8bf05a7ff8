# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Parity with stock dsmcFoam on its four tutorials (see parity.py):
exact reproduction with the same random stream, and agreement within the
noise of a six-seed ensemble for an independent-stream and a 2-rank METIS
run.  Reduced runs by default, the tutorials unchanged with --long."""

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
