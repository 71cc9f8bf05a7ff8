# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Figures: matplotlib on its Agg backend (files only, no display) and the
one way the project saves a figure (PNG at DPI, then closed)."""

DPI = 110


def pyplot():
    """matplotlib.pyplot, on the Agg backend."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def save(fig, path):
    """Writes fig to path at DPI and closes it; returns path."""
    fig.savefig(path, dpi=DPI)
    pyplot().close(fig)
    return path
