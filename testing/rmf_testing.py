# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Test support shared by the tests under applications/test, tutorials/
and validation/ (on sys.path through the top-level conftest.py): helpers
that assert or make bad input, which have no place in the rmf package."""

import re
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


def set_in_list(path, list_keyword, block, keyword, value):
    """Set keyword in the dictionary named block of a list (e.g. the
    patches of localInteractionCoeffs), which foamDictionary cannot
    address: by text, inside block's braces after list_keyword (block
    quoted or not; value None removes the keyword)."""
    with open(path) as f:
        text = f.read()
    start = text.index(list_keyword)
    name = re.escape(block)
    found = re.compile(rf'(?:"{name}"|\b{name})\s*\{{').search(text, start)
    end = text.index("}", found.end())
    body = text[found.end():end]
    pattern = re.compile(r"\b" + re.escape(keyword) + r"\s+[^;]*;")
    if value is None:
        new = pattern.sub("", body, count=1)
    elif pattern.search(body):
        new = pattern.sub(f"{keyword} {value};", body, count=1)
    else:
        new = body + f" {keyword} {value}; "
    with open(path, "w") as f:
        f.write(text[:found.end()] + new + text[end:])
