# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Regolith erosion box (doc/physics.md#erosion-box): the grains before
they settle, the erosion series of a run, its figures and plots.

    /usr/bin/python3 -m rmf.erosion bed CASE [--seed N]
    /usr/bin/python3 -m rmf.erosion settled TIMEDIR CASE
    /usr/bin/python3 -m rmf.erosion profile CASE [--u0 U0] [--length L]
    /usr/bin/python3 -m rmf.erosion plot CASE [--png FILE]
    /usr/bin/python3 -m rmf.erosion compare RUN... [--png FILE] [--table FILE]

`bed` writes CASE/constant/bedPositions (800 grains of 1 mm on a loose
jittered lattice, at rest); `settled` writes it from the grains of a
run's time directory (the DEM's settled bed, for the parcel variants);
`profile` writes CASE/constant/plumeProfile, U_x(y) = U0 tanh(y/L) at
Berger's gas density and temperature (the tutorial's: U0 = 200 m/s,
L = 0.03 m, the calibration in its README).
`plot` reads the erosionPlanes series of a run
(postProcessing/lagrangian/grains/erosionPlanes/<start>/
erosionPlanes.csv, the files of a restarted run joined), prints its
figures and draws the erosion number, the crossings of the erosion plane,
the fractional collision number and the planes against the time since
the plume's onset.  `compare` does the same for several runs (the
variants of the tutorial) on common axes and writes the table of their
figures (markdown).

Figures (t: time since the plume's onset, the series' first row):
- onset: the first t with an erosion number of at least ONSET grains;
- erosion number N_e at 0.05, 0.1 and 0.2 s, and its rate over the last
  half of the run (least squares) [grains/s];
- negative erosion: the first t after which N_e falls ONSET grains below
  its running maximum (none if it never does);
- depletion: the first t with N_e of at least DEPLETED of the grains
  (none if never);
- fractional collision number as Berger count it: the grains above the
  erosion plane overlapping another grain at a contact step over the
  grains above it, averaged over the last 1000 contact steps (erosionPlanes'
  contactStepCollisions, weighted by each step's contactSteps; a series
  without them: the end-of-step snapshot, fractionalCollisions, over a
  window of 5.9e-4 s): its peak and when, and its mean over the last half
  of the run (the plateau);
- the planes' drop at the end [grain diameters].
"""

import argparse
import glob
import math
import os

import numpy as np

from rmf import foam
from rmf.figures import pyplot, save

LX, LZ = 0.010, 0.005       # periodic box of the tutorial [m]
D = 1e-3                    # grain diameter [m]
N_GRAINS = 800
ONSET = 5                   # grains: the erosion counted as begun
DEPLETED = 0.95             # share of the grains: the bed counted as eroded
WINDOW = 1000*5.88e-7       # Berger's moving average, 1000 contact steps [s]


def bed_positions(seed=1, n=N_GRAINS):
    """Lattice of 9 x 4 grains per layer (spacing 1.11 x 1.25 mm), layers
    1.1 mm apart from y = 0.55 mm, the first n points, each jittered by up
    to 0.45 of the free gap (seed)."""
    nx, nz, dy = 9, 4, 1.1e-3
    sx, sz = LX/nx, LZ/nz
    pts = []
    j = 0
    while len(pts) < n:
        for i in range(nx):
            for k in range(nz):
                if len(pts) < n:
                    pts.append([(i + 0.5)*sx, 0.55e-3 + j*dy, (k + 0.5)*sz])
        j += 1
    pts = np.array(pts)
    gap = 0.45*np.array([sx - D, dy - D, sz - D])
    return pts + np.random.default_rng(seed).uniform(-1, 1, pts.shape)*gap


def write_bed(case, seed=1, points=None, origin=None):
    """CASE/constant/bedPositions: the jittered lattice of seed, or the
    points given (origin: the comment saying where they come from)."""
    digits = 17                 # a run's positions, to the bit
    if points is None:
        points = bed_positions(seed)
        origin = f"rmf.erosion bed --seed {seed}"
        digits = 9              # the shipped lattice's
    path = os.path.join(case, "constant", "bedPositions")
    with open(path, "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class vectorField;"
                " object bedPositions; }\n"
                f"// {origin}\n{len(points)}\n(\n")
        f.writelines("(" + " ".join(f"{c:.{digits}g}" for c in p) + ")\n" for p in points)
        f.write(")\n")
    return path


PLUME_U0, PLUME_L = 200.0, 0.03     # the tutorial's profile [m/s], [m]
RHO_GAS, T_GAS = 1.27, 500.0        # Berger's gas [kg/m^3], [K]


def write_profile(case, u0=PLUME_U0, length=PLUME_L):
    """CASE/constant/plumeProfile: rows (y rho Ux Uy Uz T) of
    U_x = u0 tanh(y/length), every 0.25 mm to 2 mm, 0.5 mm to 50 mm,
    10 mm to 1 m (at length 0.03 m linear interpolation is within
    0.52 m/s, 0.3 %, of the tanh)."""
    ys = ([0.25e-3*i for i in range(8)] + [0.5e-3*i for i in range(4, 100)]
          + [0.05 + 0.01*i for i in range(96)])
    path = os.path.join(case, "constant", "plumeProfile")
    with open(path, "w") as f:
        f.write("/*--------------------------------*- C++ -*----------------------------------*\\\n"
                "  rarefiedMultiphaseFoam: tutorials/psi/regolithErosionBox\n"
                "\\*---------------------------------------------------------------------------*/\n"
                "// The plume's gas over the regolith, a table in y for prescribedGas\n"
                "// (constant/grainsProperties, LothCoeffs/prescribed): rows\n"
                "// (y [m]  rho [kg/m^3]  Ux Uy Uz [m/s]  T [K]), linearly interpolated.\n"
                f"// Written by rmf.erosion profile: U_x(y) = {u0:g} m/s tanh(y/{length:g} m)\n"
                "// at Berger's gas (README: the profile's calibration).\n(\n")
        for y in ys:
            f.write(f"    ({y:.6g} {RHO_GAS:g} {u0*math.tanh(y/length):.6f} 0 0 {T_GAS:g})\n")
        f.write(")\n")
    return path


def read(case, cloud="grains"):
    """The erosionPlanes series of a run, its files in time order (a later
    start supersedes the rows of an earlier file from its start on): a
    dict of numpy arrays by column."""
    pattern = os.path.join(case, "postProcessing", "lagrangian", cloud,
                           "erosionPlanes", "*", "erosionPlanes.csv")
    files = sorted(glob.glob(pattern), key=lambda p: float(os.path.basename(os.path.dirname(p))))
    rows = []
    for path in files:
        data = np.genfromtxt(path, delimiter=",", names=True)
        data = np.atleast_1d(data)
        if len(data) == 0:
            continue
        rows = [r for r in rows if r["time"] < data["time"][0] - 1e-12] + list(data)
    if not rows:
        raise FileNotFoundError(f"{case}: no erosionPlanes series")
    names = rows[0].dtype.names
    return {n: np.array([r[n] for r in rows]) for n in names}


def moving_average(t, x, window=WINDOW):
    """Mean of x over the window ending at each t (the series' steps)."""
    c = np.concatenate([[0.0], np.cumsum(x)])
    start = np.searchsorted(t, t - window + 1e-12)
    idx = np.arange(len(t))
    return (c[idx + 1] - c[start])/(idx + 1 - start)


def collision_number(s, steps=1000):
    """The fractional collision number of a series, averaged over the
    last `steps` contact steps at each row (module docstring); None for
    grains without resolved contacts."""
    if not np.all(s["colliding"] >= 0):
        return None
    n = s.get("contactSteps")
    if n is None or not np.any(n > 0):
        return moving_average(s["time"], s["fractionalCollisions"])
    f = np.where(n > 0, s["contactStepCollisions"], 0.0)*n
    cn = np.concatenate([[0.0], np.cumsum(n)])
    cf = np.concatenate([[0.0], np.cumsum(f)])
    idx = np.arange(len(n))
    # the first row whose steps still fall in the window ending at idx
    start = np.searchsorted(cn, cn[idx + 1] - steps, side="right") - 1
    start = np.clip(start, 0, idx)
    return (cf[idx + 1] - cf[start])/np.maximum(cn[idx + 1] - cn[start], 1)


def figures(s):
    """The figures of the module's docstring from a series s."""
    t = s["time"] - s["time"][0]
    ne = s["erosionNumber"]
    out = {"duration": float(t[-1])}
    begun = np.nonzero(ne >= ONSET)[0]
    out["onset"] = float(t[begun[0]]) if len(begun) else None
    step = float(np.median(np.diff(t))) if len(t) > 1 else 0.0
    for at in (0.05, 0.1, 0.2):
        # (the row nearest to it, within a step of the run's end)
        i = min(np.searchsorted(t, at - step/2), len(t) - 1)
        out[f"Ne{at}"] = float(ne[i]) if t[-1] >= at - 1.5*step else None
    late = t >= t[-1]/2
    out["rate"] = float(np.polyfit(t[late], ne[late], 1)[0]) if late.sum() > 2 else None
    running = np.maximum.accumulate(ne)
    fallen = np.nonzero(ne <= running - ONSET)[0]
    out["negative"] = float(t[fallen[0]]) if len(fallen) else None
    gone = np.nonzero(ne >= DEPLETED*N_GRAINS)[0]
    out["depleted"] = float(t[gone[0]]) if len(gone) else None
    fcn = collision_number(s)
    if fcn is not None:
        i = int(np.argmax(fcn))
        out["fcnPeak"], out["fcnPeakAt"] = float(fcn[i]), float(t[i])
        out["fcnPlateau"] = float(fcn[late].mean())
    else:
        out["fcnPeak"] = out["fcnPeakAt"] = out["fcnPlateau"] = None
    out["drop"] = float((s["erosion"][0] - s["erosion"][-1])/D)
    out["escaped"] = int(N_GRAINS - s["grains"][-1])
    return out


def _fmt(v, f):
    return "-" if v is None else format(v, f)


def summary_line(name, fig):
    return (f"{name}: onset {_fmt(fig['onset'], '.4f')} s, N_e(0.05/0.1/0.2 s)"
            f" {_fmt(fig['Ne0.05'], '.0f')}/{_fmt(fig['Ne0.1'], '.0f')}/{_fmt(fig['Ne0.2'], '.0f')},"
            f" rate {_fmt(fig['rate'], '.0f')} grains/s, negative erosion from"
            f" {_fmt(fig['negative'], '.4f')} s, {100*DEPLETED:.0f} % eroded at"
            f" {_fmt(fig['depleted'], '.4f')} s, fractional collisions peak"
            f" {_fmt(fig['fcnPeak'], '.3f')} at {_fmt(fig['fcnPeakAt'], '.4f')} s,"
            f" plateau {_fmt(fig['fcnPlateau'], '.3f')}, planes down {fig['drop']:.2f} d,"
            f" {fig['escaped']} grains out at the top")


def table(runs):
    """Markdown table of the figures of runs {name: figures}."""
    head = ("| variant | onset [s] | N_e 0.05 s | N_e 0.1 s | N_e 0.2 s | rate [1/s]"
            " | negative from [s] | depleted [s] | FCN peak | at [s] | FCN plateau"
            " | drop [d] |")
    lines = [head, "|" + "---|"*12]
    for name, f in runs.items():
        lines.append(
            f"| {name} | {_fmt(f['onset'], '.4f')} | {_fmt(f['Ne0.05'], '.0f')}"
            f" | {_fmt(f['Ne0.1'], '.0f')} | {_fmt(f['Ne0.2'], '.0f')} | {_fmt(f['rate'], '.0f')}"
            f" | {_fmt(f['negative'], '.4f')} | {_fmt(f['depleted'], '.4f')}"
            f" | {_fmt(f['fcnPeak'], '.3f')}"
            f" | {_fmt(f['fcnPeakAt'], '.4f')} | {_fmt(f['fcnPlateau'], '.3f')}"
            f" | {f['drop']:.2f} |")
    return "\n".join(lines)


def plot(series, output, title=None):
    """Erosion number, cumulative crossings, averaged fractional collision
    number and the planes against the time since onset, one line per run
    of series {name: series}."""
    plt = pyplot()

    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5), sharex=True)
    (a, b), (c, e) = axes
    many = len(series) > 1
    colours = plt.cm.tab20(np.linspace(0, 1, 20))[:max(len(series), 1)]
    for ax in (a, b, c, e):
        ax.set_prop_cycle(color=colours)
    for name, s in series.items():
        t = s["time"] - s["time"][0]
        line, = a.plot(t, s["erosionNumber"], label=name)
        colour = line.get_color()
        b.plot(t, np.cumsum(s["up"]), color=colour, label=None if many else "up")
        b.plot(t, np.cumsum(s["down"]), color=colour, ls="--",
               label=None if many else "down")
        fcn = collision_number(s)
        if fcn is not None:
            c.plot(t, fcn, color=colour)
        e.plot(t, 1e3*s["erosion"], color=colour, label=None if many else "erosion plane")
        e.plot(t, 1e3*s["anchoring"], color=colour, ls="--",
               label=None if many else "anchoring plane")
        e.plot(t, 1e3*s["bedTop"], color=colour, ls=":", label=None if many else "bed top")
    a.set_ylabel("erosion number (grains above the erosion plane)")
    b.set_ylabel("crossings of the erosion plane (cumulative)")
    c.set_ylabel("fractional collision number (1000-step average)")
    e.set_ylabel("height [mm]")
    for ax in (c, e):
        ax.set_xlabel("time since the plume's onset [s]")
    if many:
        a.legend(fontsize=7, ncol=2)
        b.set_title("solid: up, dashed: down", fontsize=9)
        e.set_title("solid: erosion plane, dashed: anchoring plane, dotted: bed top",
                    fontsize=9)
    else:
        b.legend(fontsize=8)
        e.legend(fontsize=8)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    save(fig, output)
    print(output)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("bed", help="write CASE/constant/bedPositions")
    p.add_argument("case")
    p.add_argument("--seed", type=int, default=1)
    p = sub.add_parser("settled", help="CASE/constant/bedPositions from TIMEDIR's grains")
    p.add_argument("timedir")
    p.add_argument("case")
    p = sub.add_parser("profile", help="write CASE/constant/plumeProfile")
    p.add_argument("case")
    p.add_argument("--u0", type=float, default=PLUME_U0)
    p.add_argument("--length", type=float, default=PLUME_L)
    p = sub.add_parser("plot", help="figures and plot of one run")
    p.add_argument("case")
    p.add_argument("--png")
    p = sub.add_parser("compare", help="figures and plot of several runs")
    p.add_argument("runs", nargs="+")
    p.add_argument("--png")
    p.add_argument("--table")
    args = parser.parse_args(argv)

    if args.command == "bed":
        print(write_bed(args.case, args.seed))
        return 0
    if args.command == "profile":
        print(write_profile(args.case, args.u0, args.length))
        return 0
    if args.command == "settled":
        points = foam.read_positions(os.path.join(args.timedir, "lagrangian", "grains",
                                                  "positions"))
        print(write_bed(args.case, points=points,
                        origin=f"rmf.erosion settled {args.timedir}"))
        return 0
    runs = [args.case] if args.command == "plot" else args.runs
    series = {}
    figs = {}
    for run in runs:
        name = os.path.basename(os.path.normpath(os.path.abspath(run)))
        series[name] = read(run)
        figs[name] = figures(series[name])
        print(summary_line(name, figs[name]))
    if args.png:
        plot(series, args.png, title="Regolith erosion box"
             + ("" if len(runs) > 1 else f": {list(series)[0]}"))
    if args.command == "compare" and args.table:
        with open(args.table, "w") as f:
            f.write(table(figs) + "\n")
        print(args.table)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
