# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Snider sedimentation: reduced in ./Alltest, full-size with
./Alltest --long.  Checks and tolerances: rmf.snider; runs: validate.py."""

import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(__file__))

import validate  # noqa: E402
from rmf import snider  # noqa: E402


@pytest.fixture(scope="module")
def results(request):
    _, figures = validate.validate(full=request.config.getoption("--long"))
    return figures


def test_pictures(results):
    for path in results["pngs"]:
        assert os.path.getsize(path) > 0


def test_snider_checks(results):
    """Every check but the over-packing bounds (next test)."""
    failed = [name for name, ok in results["checks"].items()
              if not ok and not name.endswith(snider.OVERPACKING)]
    assert not failed, failed


def test_overpacking_bounds(results):
    failed = [name for name, ok in results["checks"].items()
              if not ok and name.endswith(snider.OVERPACKING)]
    assert not failed, failed


@pytest.fixture(scope="module")
def variant_results(request, results):
    variants, png = validate.variants(results["serial"],
                                      full=request.config.getoption("--long"))
    return variants, png


def test_variants_picture(variant_results):
    assert os.path.getsize(variant_results[1]) > 0


def test_stochastic_overpacks(variant_results):
    """doc/physics.md 7.1: NTC collisions alone know only binary collisions and
    let the bed pack beyond what MPPIC's stress allows: its bottom layer
    exceeds the layer bound that the MPPIC run keeps, parcels conserved."""
    passed, s = variant_results[0]["stochastic"]
    checks = s["checks"]
    assert checks["parcels"] and checks["properties"] and checks["heated"]
    assert not checks["layer bound"], max(s["alphaMaxLayer"].values())


def test_hybrid_checks(variant_results):
    """The hybrid keeps MPPIC in the bed: every check of the MPPIC run
    but the over-packing bounds (those: next test)."""
    passed, s = variant_results[0]["hybrid"]
    failed = [name for name, ok in s["checks"].items()
              if not ok and name not in snider.OVERPACKING]
    assert not failed, failed


def test_hybrid_overpacking_bounds(variant_results):
    passed, s = variant_results[0]["hybrid"]
    failed = [name for name, ok in s["checks"].items()
              if not ok and name in snider.OVERPACKING]
    assert not failed, failed
