# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The scene at a few written times: gas number density (batch mean,
log colour) on the meridional plane, nozzle on top and the lunar surface
at the bottom, with the grain parcels as dots (a random subset); below
it, the dust layer magnified (heights up to four initial layer depths),
every parcel coloured by its speed.

    /usr/bin/python3 scene.py [CASE] [--output PNG] [--times N]

Default CASE ".", PNG CASE/apolloScaledPSI.png, N = 3 (the first write
after 0, the middle one and the last).  Reads system/observablesDict for
the geometry (as rmf.psi).
"""

import argparse
import os
import sys

import numpy as np

from rmf import figures, foam, psi

MAX_DOTS = 6000


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("case", nargs="?", default=".")
    parser.add_argument("--output")
    parser.add_argument("--times", type=int, default=3)
    args = parser.parse_args(argv)
    case = args.case
    output = args.output or os.path.join(case, "apolloScaledPSI.png")

    plt = figures.pyplot()
    from scipy.interpolate import griddata

    settings = psi.read_settings(case)
    X_s = settings["surface"]
    cells = psi.mesh(case)
    times = [t for t in foam.times(case) if float(t) > 0]
    if not times:
        sys.exit(f"scene: {case}: no written time after 0")
    pick = sorted({times[0], times[len(times)//2], times[-1]}, key=float)[:args.times]

    fig, axes = plt.subplots(2, len(pick), figsize=(5.2*len(pick), 7.6),
                             squeeze=False, constrained_layout=True,
                             gridspec_kw={"height_ratios": [4.4, 2.6]})
    rng = np.random.default_rng(1)
    art = None
    clouds = [psi.parcels(case, t) for t in pick]
    for ax, t, p in zip(axes[0], pick, clouds):
        rho = psi.field(case, t, "rhoNMean", cells["n"])
        if rho is None:
            rho = psi.field(case, t, "rhoN", cells["n"])
        height = 1e3*(X_s - cells["x"])
        r = 1e3*cells["r"]
        if rho is not None:
            # nearest cell on a regular grid (the wedge's cells are not a
            # uniform grid); log10 of the density, empty cells blank
            rmax = 1e3*max(settings["layerRadius"], 3*settings["nozzleRadius"])
            gr, gh = np.meshgrid(np.linspace(0, rmax, 300),
                                 np.linspace(0, 1e3*X_s, 200))
            grid = griddata(np.c_[r, height], rho, (gr, gh), method="nearest")
            low = 1e-4*rho.max()
            grid = np.ma.masked_less(grid, low)
            art = ax.imshow(np.log10(grid), origin="lower", aspect="auto",
                            extent=(0, rmax, 0, 1e3*X_s), cmap="viridis",
                            vmin=np.log10(low), vmax=np.log10(rho.max()))
        if p is not None:
            k = np.arange(len(p["pos"]))
            if len(k) > MAX_DOTS:
                k = rng.choice(k, MAX_DOTS, replace=False)
            ax.plot(1e3*psi.radius(p["pos"][k]), 1e3*(X_s - p["pos"][k, 0]),
                    ",", color="white" if rho is not None else "k", alpha=0.8)
        ax.axhline(1e3*(X_s - settings["layerTop"]), color="w", lw=0.5, ls=":")
        ax.plot([0, 1e3*settings["nozzleRadius"]], [1e3*X_s]*2, color="r", lw=3)
        ax.set_xlim(0, 1e3*max(settings["layerRadius"], 3*settings["nozzleRadius"]))
        ax.set_ylim(0, 1e3*X_s)
        ax.set_xlabel("r [mm]")
        ax.set_ylabel("height above the surface [mm]")
        ax.set_title(f"t = {1e6*float(t):.3g} us")
    dots = layer_row(axes[1], pick, clouds, settings)
    if art is not None:
        fig.colorbar(art, ax=axes[0].tolist(), label="log10 gas number density [1/m^3]")
    if dots is not None:
        fig.colorbar(dots, ax=axes[1].tolist(), label="parcel speed [m/s]",
                     extend="max")
    fig.suptitle("apolloScaledPSI: water-vapour plume (nozzle in red) and "
                 "regolith parcels (dots; dotted: initial layer top)")
    figures.save(fig, output)
    print(f"scene: wrote {output} (times {' '.join(pick)})")


def layer_row(axes, pick, clouds, settings):
    """The dust layer magnified: every parcel of clouds (psi.parcels of
    the times pick) at (r, height) coloured by its speed, one colour scale
    over the times (faster than its top: its top colour); the initial
    layer top dotted.
    Returns the last scatter (for the colour bar), None without parcels."""
    X_s = settings["surface"]
    H = X_s - settings["layerTop"]
    speeds = [None if p is None else np.linalg.norm(p["U"], axis=1) for p in clouds]
    every = np.concatenate([s for s in speeds if s is not None] + [np.zeros(1)])
    # the scale's top at the 99.5th percentile: a few fast ejecta would
    # leave every other parcel in the lowest colour
    vmax = max(np.percentile(every, 99.5), 1e-3)
    dots = None
    for ax, t, p, speed in zip(axes, pick, clouds, speeds):
        if p is not None:
            order = np.argsort(speed)                   # the fastest on top
            dots = ax.scatter(1e3*psi.radius(p["pos"][order]),
                              1e6*(X_s - p["pos"][order, 0]), s=1, lw=0,
                              c=speed[order], cmap="plasma", vmin=0, vmax=vmax)
        ax.axhline(1e6*H, color="k", lw=0.5, ls=":")
        ax.set_xlim(0, 1e3*settings["layerRadius"])
        ax.set_ylim(0, 4e6*H)
        ax.set_xlabel("r [mm]")
        ax.set_ylabel("height above the surface [um]")
        ax.set_title(f"dust layer at t = {1e6*float(t):.3g} us")
    return dots


if __name__ == "__main__":
    main()
