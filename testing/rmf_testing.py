# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Test support shared by the tests under applications/test, tutorials/
and validation/ (on sys.path through the top-level conftest.py): helpers
that assert or make bad input, and the seeds and statistical limits of the
suite's false-alarm budget (testing/README.md), which have no place in the
rmf package."""

import os
import re
import subprocess

from scipy import stats as _stats


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


# ---------------------------------------------------------------------------
# Seeds and the suite's false-alarm budget (testing/README.md)

#: The suite's family-wise false-alarm budget: the probability that a
#: correct build fails any statistical check of ./Alltest when every seed
#: changes (./Alltest --seed-set N) is at most SUITE_ALPHA.
SUITE_ALPHA = 0.01

#: Test modules that may spend from it, at most (testing/README.md); each
#: gets MODULE_ALPHA, its own family-wise error, which it
#: shares among its comparisons (Bonferroni) and states in its docstring.
MODULES = 40
MODULE_ALPHA = SUITE_ALPHA/MODULES


def seed_set():
    """Which set of seeds the suite runs with: 0 (the default, the seeds
    the figures in the docstrings were measured with) or N from
    ./Alltest --seed-set N (environment RMF_SEED_SET)."""
    return int(os.environ.get("RMF_SEED_SET", "0"))


def seed(k, span=500):
    """Seed k (0 <= k < span) of the current seed set: k itself in set 0,
    k + span*N in set N, so sets never overlap.  The programs take seeds
    from 0 to 2000 (randomSeed): sets 0 to 3."""
    assert 0 <= k < span, f"seed {k} outside 0..{span - 1}"
    s = k + span*seed_set()
    assert s <= 2000, f"seed set {seed_set()} gives seed {s}: randomSeed takes 0..2000"
    return s


def z_limit(m=1, alpha=MODULE_ALPHA, two_sided=True):
    """Normal quantile for one of m comparisons sharing alpha
    (Bonferroni): |z| above it has probability alpha/m under the null."""
    a = alpha/m
    return _stats.norm.isf(a/2 if two_sided else a)


def t_limit(dof, m=1, alpha=MODULE_ALPHA, two_sided=True):
    """Student's t quantile with dof degrees of freedom for one of m
    comparisons sharing alpha (Bonferroni)."""
    a = alpha/m
    return _stats.t.isf(a/2 if two_sided else a, dof)


def poisson_limits(mean, m=1, alpha=MODULE_ALPHA):
    """Two-sided acceptance range [lo, hi] of a Poisson count of the given
    mean, one of m comparisons sharing alpha (Bonferroni)."""
    a = alpha/m
    return (_stats.poisson.ppf(a/2, mean), _stats.poisson.isf(a/2, mean))
