# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""A PSI tutorial case prepared for a run of a few steps (the benchmarks)."""

import os

from rmf import foam

TUTORIAL = os.path.join(foam.PROJECT_DIR, "tutorials", "psi", "apolloScaledPSI")


def prepare_steps(dst, settings, variant, steps, write_steps=None):
    """Copy the tutorial to dst with settings/<settings> and the variant
    (constant/caseSettings, as Allrun writes it), the end time after
    steps steps and a write every write_steps steps (None: no write within
    the run), then mesh and initialise it; returns the case."""
    case = foam.copy_case(TUTORIAL, dst)
    with open(os.path.join(case, "constant", "caseSettings"), "w") as f:
        f.write(f"settings {settings};\nvariant {variant};\n")
    entries = f"settings/{settings}"
    dt = float(foam.get_entry(case, entries, "deltaT"))
    foam.set_entry(case, entries, "endTime", f"{steps*dt:.6g}")
    foam.set_entry(case, entries, "writeInterval",
                   f"{(write_steps or 10*steps)*dt:.6g}")
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case
