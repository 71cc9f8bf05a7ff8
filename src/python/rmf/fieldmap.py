# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Field maps of a 2-D case as a PNG picture.

    /usr/bin/python3 -m rmf.fieldmap CASE [--time T] [--fields F ...]
                                     [--output FILE.png]

Plots the named cell fields of the latest (or given) time on the x-y plane,
one panel each, with UMean arrows over the first panel when present, and
prints the picture's path.  Cell centres come from OpenFOAM's
`postProcess -func writeCellCentres` (run when missing).
"""

import argparse
import os

import matplotlib.tri as mtri
import numpy as np

from rmf import figures, foam

plt = figures.pyplot()

LABELS = {
    "rhoNMean": "number density [1/m$^3$]",
    "translationalT": "translational temperature [K]",
    "overallT": "overall temperature [K]",
    "p": "pressure [Pa]",
}


def arrow_cells(C, per_side=20):
    """Cells for about per_side x per_side evenly spread arrows."""
    pick = np.ones(len(C), bool)
    for axis in (0, 1):
        lines, index = np.unique(np.round(C[:, axis], 9), return_inverse=True)
        stride = max(1, len(lines)//per_side)
        pick &= index % stride == stride//2
    return pick


def field_map(case, fields, output, time=None):
    time = time or foam.latest_time(case)
    n = foam.n_cells(case)
    C = foam.cell_centres(case, time)
    tri = mtri.Triangulation(C[:, 0], C[:, 1])
    width = np.ptp(C[:, 0])/max(np.ptp(C[:, 1]), 1e-30)
    fig, axes = plt.subplots(len(fields), 1, squeeze=False,
                             figsize=(1.0 + 4.0*min(width, 3), 3.2*len(fields)))
    for ax, name in zip(axes[:, 0], fields):
        values = foam.read_field(os.path.join(case, time, name), n)
        if values.ndim > 1:
            values = np.linalg.norm(values, axis=1)
        art = ax.tripcolor(tri, values, shading="gouraud", cmap="viridis")
        fig.colorbar(art, ax=ax, label=LABELS.get(name, name))
        ax.set_aspect("equal")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
        ax.set_title(f"{name}, t = {time} s")
    U_path = os.path.join(case, time, "UMean")
    if os.path.exists(U_path):
        U = foam.read_field(U_path, n)
        pick = arrow_cells(C)
        axes[0, 0].quiver(C[pick, 0], C[pick, 1], U[pick, 0], U[pick, 1],
                          color="white", alpha=0.7, width=0.002)
    fig.tight_layout()
    figures.save(fig, output)
    return os.path.abspath(output)


def main():
    parser = argparse.ArgumentParser(description="Field maps of a 2-D case (PNG)")
    parser.add_argument("case")
    parser.add_argument("--time")
    parser.add_argument("--fields", nargs="+", default=["rhoNMean", "translationalT"])
    parser.add_argument("--output", default="fieldMap.png")
    args = parser.parse_args()
    output = args.output if os.path.isabs(args.output) else os.path.join(args.case, args.output)
    print(field_map(args.case, args.fields, output, args.time))


if __name__ == "__main__":
    main()
