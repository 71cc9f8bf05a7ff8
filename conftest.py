# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""pytest configuration for ./Alltest: project helpers and test support on
sys.path, --long, --seed-set, and under ./Alltest's two workers
(pytest-xdist) testing/bin first on PATH (testing/README.md, Time)."""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "src", "python"))     # the rmf package
sys.path.insert(0, os.path.join(HERE, "testing"))           # test support (testing/)


def pytest_addoption(parser):
    parser.addoption("--long", action="store_true",
                     help="also run the long checks (full-size tutorials)")
    parser.addoption("--seed-set", type=int, default=None,
                     help="run the statistical tests with seed set N (0: the "
                          "default seeds; testing/README.md)")


def pytest_configure(config):
    if config.getoption("--seed-set") is not None:
        os.environ["RMF_SEED_SET"] = str(config.getoption("--seed-set"))
    config.addinivalue_line("markers", "long: long run, only with --long")
    if os.environ.get("PYTEST_XDIST_WORKER"):
        # ./Alltest's workers start the solvers and mpirun through
        # testing/bin: an mpirun runs with no solver of the other worker
        # beside it (testing/README.md, Time)
        os.environ["PATH"] = os.path.join(HERE, "testing", "bin") + os.pathsep \
            + os.environ["PATH"]


def pytest_collection_modifyitems(config, items):
    import pytest
    if config.getoption("--long"):
        return
    skip = pytest.mark.skip(reason="long run: use ./Alltest --long")
    for item in items:
        if "long" in item.keywords:
            item.add_marker(skip)
