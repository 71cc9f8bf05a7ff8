# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The reference table of Test-dragLaws (applications/test/Test-dragLaws/
dragLawsReference.H) is what validation/dragLaws/reference.py makes: a
changed reference is a reviewed commit, never a silent edit."""

import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
HEADER = os.path.join(ROOT, "applications", "test", "Test-dragLaws",
                      "dragLawsReference.H")

sys.path.insert(0, HERE)
import reference  # noqa: E402


def test_header_matches_script():
    made = subprocess.run([sys.executable, os.path.join(HERE, "reference.py"),
                           "--header"], capture_output=True, text=True,
                          check=True).stdout
    with open(HEADER) as f:
        stored = f.read()
    print("PASS" if made == stored else "FAIL",
          "dragLawsReference.H is reference.py's output")
    assert made == stored


def test_integral_matches_closed_form():
    """The surface integral (the reference) and doc/physics.md 4.2's closed form
    agree to 1e-11 (Simpson with 4000 intervals; at s = 0.01 the closed
    form loses ~3 digits to cancellation in double precision)."""
    worst = 0.0
    for s, ratio in reference.FM_POINTS:
        a = reference.cd_fm_integrated(s, ratio)
        b = reference.cd_fm_closed(s, ratio)
        worst = max(worst, abs(a - b)/b)
    print("PASS" if worst < 1e-11 else "FAIL",
          "free-molecular C_D: integral vs closed form, worst rel. diff %.2e"
          " (tol 1e-11)" % worst)
    assert worst < 1e-11
