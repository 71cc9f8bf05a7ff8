# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Plume-surface interaction observables (doc/physics.md#apollo-psi).

    /usr/bin/python3 -m rmf.psi CASE ...            (see __main__.py)

Modules: observables (the case's input, each observable, analyse and the
reading of its result; the definitions in its docstring), plots (the
PNGs), report (summary.md and the comparison of cases), case (a case
prepared for a few steps, for the benchmarks), __main__ (the command
line).  Their public names are re-exported here: psi.<name>.
"""

from .observables import (CLOUD, SETTINGS, SURFACE_QUANTILE, SURFACE_FRACTION,
                          MIN_PARCELS, SLAB_PARCELS, SIGNIFICANCE, SHOCK_RISE,
                          AXIS_FRACTION, AXIS_BAND, SMOOTH_CELLS, SHOCK_SUSTAIN,
                          JET_QUANTILE, PEAK_REGION, SHELL, STAGNATION_HEIGHT,
                          HISTOGRAM_TIMES, MAX_POLYGONS, DENSITIES, ALPHA_VALID,
                          KN_SWITCH, read_settings,
                          parcels, radius, radial_velocity, mesh, meridian_cells, field,
                          annuli, weighted_quantile, surface_profile, axis_profile,
                          axis_density, shock_standoff, ejecta, weighted_median,
                          ejection_angles, speeds, crossing, max_alpha, knp_cells,
                          min_knp_stagnation, temperatures, binary_validity,
                          transitional, analyse, density_note,
                          value, series, last, nearest_row)
from .plots import (pick_times, plot_crater, plot_histogram, plot_knp, TIMESERIES,
                    plot_timeseries, plot_case)
from .case import TUTORIAL, prepare_steps
from .report import (COLUMNS, table, key_numbers, definitions, write_summary, run_case,
                     common_times, compare)

__all__ = ["TUTORIAL", "prepare_steps", "CLOUD", "SETTINGS", "SURFACE_QUANTILE", "SURFACE_FRACTION", "MIN_PARCELS",
           "SLAB_PARCELS", "SIGNIFICANCE", "SHOCK_RISE", "AXIS_FRACTION", "AXIS_BAND",
           "SMOOTH_CELLS", "SHOCK_SUSTAIN", "JET_QUANTILE", "PEAK_REGION", "SHELL",
           "STAGNATION_HEIGHT", "HISTOGRAM_TIMES", "MAX_POLYGONS", "DENSITIES",
           "ALPHA_VALID", "KN_SWITCH",
           "read_settings", "parcels", "radius", "radial_velocity", "mesh",
           "meridian_cells", "field", "annuli", "weighted_quantile", "surface_profile",
           "axis_profile", "axis_density", "shock_standoff", "ejecta",
           "weighted_median", "ejection_angles", "speeds", "crossing", "max_alpha",
           "knp_cells", "min_knp_stagnation", "temperatures", "binary_validity",
           "transitional", "analyse", "density_note",
           "value", "series", "last", "nearest_row", "pick_times", "plot_crater",
           "plot_histogram", "plot_knp", "TIMESERIES", "plot_timeseries", "plot_case",
           "COLUMNS", "table", "key_numbers", "definitions", "write_summary",
           "run_case", "common_times", "compare"]
