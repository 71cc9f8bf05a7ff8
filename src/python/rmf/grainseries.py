# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Mean grain speed and temperature against time, one curve per case.

    /usr/bin/python3 -m rmf.grainseries CASE [CASE ...] [--labels L ...]
        [--cloud grains] [--output FILE.png] [--table FILE.csv]

For each case, at every written time (0 included: the initialiser's
parcels), the parcels' mean velocity along the stream (x), mean speed |U|
and mean temperature (parcels of equal weight, as the tutorial's; parcels
that left the domain no longer count), from <time>/lagrangian/<cloud>/U
and T.  Prints the series, writes them as CSV (--table) and draws them in
one PNG (--output): mean speed and mean temperature against time, one
curve per case (label: --labels, default the case directory's name).
Used by tutorials/coupling/dustCloudStream.
"""

import argparse
import os
import sys

import numpy as np

from rmf import figures, foam


def series(case, cloud="grains"):
    """Rows (t, parcels, mean U_x, mean |U|, mean T) at every written time
    that holds the cloud."""
    rows = []
    for t in foam.times(case):
        base = os.path.join(case, t, "lagrangian", cloud)
        if not os.path.exists(os.path.join(base, "U")):
            continue
        U = foam.read_list(os.path.join(base, "U")).reshape(-1, 3)
        T = foam.read_list(os.path.join(base, "T"))
        rows.append((float(t), len(T), U[:, 0].mean(), np.linalg.norm(U, axis=1).mean(),
                     T.mean()))
    return np.array(rows)


def plot(curves, output):
    """curves: {label: series}; mean speed and temperature against time."""
    plt = figures.pyplot()

    fig, (ax_u, ax_t) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    # Distinct styles: curves that coincide (adaptive in its free-molecular
    # branch and oneWay) stay visible
    lines = ["-", "--", "-.", ":"]
    markers = [".", "o", "x", "s"]
    for i, (label, s) in enumerate(curves.items()):
        style = dict(linestyle=lines[i % 4], marker=markers[i % 4], markersize=5,
                     markerfacecolor="none", label=label)
        ax_u.plot(1e3*s[:, 0], s[:, 3], **style)
        ax_t.plot(1e3*s[:, 0], s[:, 4], **style)
    ax_u.set_xlabel("t [ms]")
    ax_u.set_ylabel("mean grain speed [m/s]")
    ax_t.set_xlabel("t [ms]")
    ax_t.set_ylabel("mean grain temperature [K]")
    for ax in (ax_u, ax_t):
        ax.grid(alpha=0.3)
        ax.legend(title="interphaseCoupling")
    fig.suptitle("Dust cloud in an argon stream (500 m/s, 1000 K): grains per coupling type")
    figures.save(fig, output)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("cases", nargs="+")
    parser.add_argument("--labels", nargs="+")
    parser.add_argument("--cloud", default="grains")
    parser.add_argument("--output")
    parser.add_argument("--table")
    args = parser.parse_args(argv)
    labels = args.labels or [os.path.basename(os.path.abspath(c)) for c in args.cases]
    if len(labels) != len(args.cases):
        sys.exit("grainseries: one label per case")

    curves = {}
    lines = ["label,t,parcels,meanUx,meanSpeed,meanT"]
    for label, case in zip(labels, args.cases):
        s = series(case, args.cloud)
        if len(s) == 0:
            sys.exit(f"grainseries: {case}: no {args.cloud} parcels written")
        curves[label] = s
        print(f"{label}: t [ms], parcels, mean U_x, mean |U| [m/s], mean T [K]")
        for t, n, ux, speed, T in s:
            print(f"  {1e3*t:7.3f} {int(n):6d} {ux:10.4f} {speed:10.4f} {T:10.4f}")
            lines.append(f"{label},{t:.9g},{int(n)},{ux:.9g},{speed:.9g},{T:.9g}")
    if args.table:
        with open(args.table, "w") as f:
            f.write("\n".join(lines) + "\n")
    if args.output:
        plot(curves, args.output)
        print(f"grainseries: wrote {args.output}")


if __name__ == "__main__":
    main()
