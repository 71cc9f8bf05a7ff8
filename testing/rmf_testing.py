# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Test support shared by the tests under applications/test, tutorials/
and validation/ (on sys.path through the top-level conftest.py): helpers
that assert, which have no place in the rmf package."""

import subprocess


def run_failing(case, app):
    """Run an application that must fail (bad input); returns its output."""
    proc = subprocess.run([app], cwd=case, capture_output=True, text=True)
    assert proc.returncode != 0, f"{app} accepted bad input"
    return proc.stdout + proc.stderr


def report(name, ok, text):
    """Print a check's PASS/FAIL line with its figures; returns ok."""
    print(f"{'PASS' if ok else 'FAIL'} {name}: {text}")
    return ok
