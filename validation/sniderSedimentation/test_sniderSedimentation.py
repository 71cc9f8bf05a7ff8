"""Snider sedimentation (issue 3): reduced in ./Alltest, full-size with
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
