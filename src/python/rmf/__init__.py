# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""rarefiedMultiphaseFoam post-processing and test helpers (run on /usr/bin/python3)."""
