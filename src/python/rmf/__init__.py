# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""rarefiedMultiphaseFoam post-processing and OpenFOAM file helpers (run on
/usr/bin/python3; importable after . etc/bashrc, which puts src/python on
PYTHONPATH), and the code tests, benchmarks and scripts share: rmf.foam
(files, runs, logs), rmf.figures (saving a figure), rmf.kinetic (the
drag and heat references), rmf.bench (the speed-accuracy study), rmf.stats,
rmf.dem, rmf.keywords (the keyword tables of the model pages in
doc/models); test support lives in testing/ at the top level."""
