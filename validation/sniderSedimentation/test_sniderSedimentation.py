"""Snider sedimentation (issue 3): reduced in ./Alltest, full-size with
./Alltest --long.  Checks and tolerances: rmf.snider."""

import os
import sys

sys.path.insert(0, os.path.dirname(__file__))

import validate  # noqa: E402


def test_snider_sedimentation(request):
    ok, figures = validate.validate(full=request.config.getoption("--long"))
    for path in figures["pngs"]:
        assert os.path.getsize(path) > 0
    assert ok, "a Snider check failed (PASS/FAIL lines above)"
