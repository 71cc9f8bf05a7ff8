# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Runs every unit-test application (applications/test/Test-*): each exits
non-zero when one of its own checks fails.  Deterministic: Test-dragLaws
compares the laws with limits and stored reference values, Test-
gasInputChecks accepts or refuses input; no random draw, no statistical
comparison (no share of the false-alarm budget)."""

import glob
import os
import subprocess

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
APPS = sorted(os.path.basename(d) for d in glob.glob(os.path.join(HERE, "Test-*")))


@pytest.mark.parametrize("app", APPS)
def test_unit_application(app):
    proc = subprocess.run([app], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    assert " 0 failed" in proc.stdout
