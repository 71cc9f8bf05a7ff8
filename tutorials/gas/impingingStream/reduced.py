# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Reduced settings of impingingStream for the test suite and its stored
reference: 600 steps instead of 1200, averages from 0.3 ms, serial."""

import os

from rmf import foam

HERE = os.path.dirname(os.path.abspath(__file__))
END = "6e-4"
AVERAGE_FROM = "3e-4"


def reduced_case(dst, seed=None):
    """Meshed, initialised copy of the tutorial with the reduced settings."""
    case = foam.copy_setup(HERE, dst)
    control = "system/controlDict"
    foam.set_entry(case, control, "endTime", END)
    foam.set_entry(case, control, "writeInterval", END)
    for fo in ("fieldAverage1", "dsmcFields1"):
        foam.set_entry(case, control, f"functions/{fo}/timeStart", AVERAGE_FROM)
    if seed is not None:
        foam.set_entry(case, "constant/dsmcProperties", "randomSeed", seed)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case


def run(case):
    foam.run(case, "rarefiedMultiphaseFoam")
    return case
