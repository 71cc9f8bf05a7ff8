# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Plume-surface interaction observables (doc/physics.md#apollo-psi).

    /usr/bin/python3 -m rmf.psi CASE [--output DIR] [--times T ...]
    /usr/bin/python3 -m rmf.psi --compare CASE1 CASE2 ... [--labels L ...]
                                [--output DIR]
    options: --dr M (crater annuli before merging), --dx M (slabs of the
    dense layer), --shell M (crossing shell half
    width), --radial-weight W R (parcels weighted implicitly by radius)

The first form writes PNGs and summary.md to DIR (default CASE/observables);
the second puts the cases side by side at equal physical times (the times
written by every case; when there are none, each case's time nearest to
the first case's) and writes compare_*.png and summary.md to DIR (default
./psiCompare).  The observables are defined in rmf/psi/observables.py.
"""

import argparse
import os
import sys

from .observables import SHELL
from .report import compare, run_case


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m rmf.psi",
                                     description=__doc__.split("\n")[0])
    parser.add_argument("cases", nargs="*", help="case directory")
    parser.add_argument("--compare", nargs="+", metavar="CASE",
                        help="cases to compare at equal times")
    parser.add_argument("--labels", nargs="+")
    parser.add_argument("--output", help="directory for the PNGs and summary.md")
    parser.add_argument("--times", nargs="+", help="times of the profiles and histograms")
    parser.add_argument("--dr", type=float, help="crater annulus width before merging to 100 parcels [m]")
    parser.add_argument("--dx", type=float, help="slab height of the crater's dense-layer criterion [m]")
    parser.add_argument("--shell", type=float, default=SHELL,
                        help="half width of the crossing shell [m]")
    parser.add_argument("--radial-weight", nargs=2, type=float, metavar=("W", "R"),
                        help="parcels carry the implicit radial weight 1 + (W-1) r/R")
    args = parser.parse_args(argv)
    try:
        run(args)
    except (OSError, KeyError, ValueError, RuntimeError) as error:
        sys.exit(f"psi: {error}")


def run(args):
    options = dict(dr=args.dr, dx=args.dx, shell=args.shell, radial_weight=args.radial_weight)
    if args.compare:
        cases = args.compare + args.cases
        labels = args.labels or [os.path.basename(os.path.abspath(c)) for c in cases]
        if len(labels) != len(cases):
            sys.exit(f"psi: {len(cases)} cases but {len(labels)} labels")
        path, _ = compare(cases, labels, args.output or "psiCompare", **options)
    else:
        if len(args.cases) != 1:
            sys.exit("psi: one CASE (or --compare CASE ...)")
        path, analysis = run_case(args.cases[0], args.output, args.times, **options)
        for n in analysis["notes"]:
            print(f"psi: note: {n}")
    print(f"psi: wrote {path}")
    with open(path) as f:
        print(f.read())


if __name__ == "__main__":
    main()
