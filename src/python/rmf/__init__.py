# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""rarefiedMultiphaseFoam post-processing and OpenFOAM file helpers (run on
/usr/bin/python3); test support lives in testing/ at the top level."""
