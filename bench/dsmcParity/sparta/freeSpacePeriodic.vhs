# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
#
# freeSpacePeriodic's variable hard spheres for SPARTA
# (in.freeSpacePeriodic), dsmcFoam tutorial's values: ID, diameter [m],
# viscosity exponent omega, reference temperature [K], VSS alpha (1: VHS)
N2  4.17e-10  0.74  273.0  1.0
O2  4.07e-10  0.77  273.0  1.0
