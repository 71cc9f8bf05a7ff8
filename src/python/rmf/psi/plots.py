# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Plume-surface interaction plots: the PNGs of a case and the panels
rmf.psi.report puts side by side."""

import os

import numpy as np

from rmf import figures

from .observables import AXIS_BAND, HISTOGRAM_TIMES, nearest_row, series


def pick_times(analysis, wanted=None, count=HISTOGRAM_TIMES):
    """Rows to show in profiles and histograms: the named times, else up to
    count times with parcels evenly spread, the last included."""
    rows = [r for r in analysis["rows"] if r.get("p") is not None]
    if wanted:
        chosen = [nearest_row(analysis, float(t)) for t in wanted]
        return [r for r in chosen if r is not None]
    if len(rows) <= count:
        return rows
    index = np.unique(np.round(np.linspace(0, len(rows) - 1, count)).astype(int))
    return [rows[i] for i in index]


def plot_crater(ax, analysis, rows, title=None):
    s = analysis["settings"]
    H = s["surface"] - s["layerTop"]
    ax.axhline(1e3*H, color="0.5", linestyle="--", label="initial layer top")
    for r in rows:
        c = r.get("crater")
        if c is None:
            continue
        line = ax.stairs(1e3*c["height"], 1e3*c["r_edges"], baseline=None,
                         label=f"t = {r['time']} s")
        ax.stairs(1e3*(c["height"] + c["sigma"]), 1e3*c["r_edges"],
                  baseline=1e3*(c["height"] - c["sigma"]), fill=True, alpha=0.2,
                  color=line.get_edgecolor())
    ax.axvline(1e3*s["nozzleRadius"], color="0.7", linestyle=":", label="nozzle radius")
    ax.set_xlabel("r [mm]")
    ax.set_ylabel("dust surface height above the wall [mm] (band: +- sigma)")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    if title:
        ax.set_title(title)


def plot_histogram(ax, rows, key, values, weights, xlabel, bins=40, span=None):
    """Real-grain (or mass) fraction per bin, one step line per row."""
    data = [(r, r[key]) for r in rows if r.get(key) is not None
            and r[key].get(values) is not None and len(r[key][values])]
    if not data:
        ax.text(0.5, 0.5, f"no {values} data at these times", ha="center",
                transform=ax.transAxes)
        return
    if span is None:
        lo = min(d[values].min() for _, d in data)
        hi = max(d[values].max() for _, d in data)
        span = (lo, hi if hi > lo else lo + 1)
    edges = np.linspace(span[0], span[1], bins + 1)
    for r, d in data:
        h, _ = np.histogram(d[values], edges, weights=d[weights])
        ax.stairs(h/max(h.sum(), 1e-300), edges, label=f"t = {r['time']} s")
    ax.set_xlabel(xlabel)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)


def plot_knp(ax, fig, analysis, row, title=None, span=None):
    """Kn_p map on the (r, height) plane, log colours (over span when
    given: one scale for the cases of a comparison)."""
    from matplotlib import colors, tri as mtri
    knp = row.get("knp") if row else None
    if knp is None or not (knp > 0).any():
        ax.text(0.5, 0.5, "no Kn_p (no grains or no field)", ha="center",
                transform=ax.transAxes)
        return
    s, cells = analysis["settings"], analysis["cells"]
    positive = knp[knp > 0]
    lo, hi = span or (positive.min(), positive.max())
    norm = colors.LogNorm(vmin=lo, vmax=max(hi, lo*1.01))
    polygons = analysis.get("polygons")
    if polygons is not None and len(polygons) == len(knp):
        from matplotlib.collections import PolyCollection
        show = np.nonzero(knp > 0)[0]
        art = PolyCollection([np.stack([1e3*polygons[i][:, 1],
                                        1e3*(s["surface"] - polygons[i][:, 0])], -1)
                              for i in show], array=knp[show], norm=norm, cmap="viridis",
                             edgecolors="face", linewidths=0.2)
        ax.add_collection(art)
        outline = np.concatenate(polygons)
        ax.set_xlim(0, 1e3*outline[:, 1].max())
        ax.set_ylim(1e3*(s["surface"] - outline[:, 0].max()),
                    1e3*(s["surface"] - outline[:, 0].min()))
    else:           # no wedge outline: interpolated between cell centres
        height = 1e3*(s["surface"] - cells["x"])
        triangles = mtri.Triangulation(1e3*cells["r"], height)
        bad = ~(knp > 0)
        triangles.set_mask(bad[triangles.triangles].any(axis=1))
        art = ax.tripcolor(triangles, np.where(bad, positive.min(), knp), norm=norm,
                           shading="gouraud", cmap="viridis")
    ax.axvline(1e3*s["nozzleRadius"], color="0.6", linestyle=":", linewidth=0.8)
    shock = row.get("shock")
    if shock and shock.get("standoff") is not None:
        ax.axhline(1e3*shock["standoff"], color="0.4", linestyle="--", linewidth=0.8)
    fig.colorbar(art, ax=ax, label=r"Kn$_p$ = $\lambda$/d$_p$")
    ax.set_xlabel("r [mm]")
    ax.set_ylabel("height above the surface [mm]")
    ax.set_aspect("equal")
    ax.set_title(title or f"Kn_p, t = {row['time']} s ({row['knp_source']})\n"
                 "dashed: shock; dotted: nozzle radius", fontsize=9)


TIMESERIES = (
    ("crater [mm]", (("crater", "surface_drop", 1e3, "surface drop, axis"),
                     ("crater", "max_depth", 1e3, "depth (max, significant)"))),
    ("shock standoff [mm]", (("shock", "standoff", 1e3, "axis"),)),
    ("max alpha", (("alpha", "max", 1, "max alpha"),)),
    ("ejection angle [deg]", (("angles", "mean", 1, "mean"), ("angles", "median", 1, "median"))),
    ("ejecta speed [m/s]", (("speeds", "ejecta_mean", 1, "mean"),
                            ("speeds", "ejecta_max", 1, "max"))),
    ("fraction toward the axis", (("crossing", "fraction_toward", 1, "flux"),
                                  ("crossing", "fraction_toward_grains", 1, "grains"))),
)


def plot_timeseries(axes, analysis, label=None, color=None):
    """The TIMESERIES panels; a case's curves in one colour when given
    (first curve of a panel solid, second dashed)."""
    for ax, (ylabel, curves) in zip(axes.ravel(), TIMESERIES):
        for (key, sub, scale, name), style in zip(curves, ("-", "--")):
            s = series(analysis, key, sub)
            if len(s):
                ax.plot(1e6*s[:, 0], scale*s[:, 1], style, color=color, marker="o",
                        markersize=3, label=f"{label}: {name}" if label else name)
        ax.set_xlabel("t [us]")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        if ax.lines:
            ax.legend(fontsize=7)


def plot_case(analysis, output, wanted=None):
    """The PNGs of one case in output; returns their names."""
    plt = figures.pyplot()
    os.makedirs(output, exist_ok=True)
    rows = pick_times(analysis, wanted)
    s = analysis["settings"]
    written = []

    def save(fig, name):
        figures.save(fig, os.path.join(output, name))
        written.append(name)

    fig, ax = plt.subplots(figsize=(7, 4.5), constrained_layout=True)
    plot_crater(ax, analysis, rows, "Dust surface (crater profile)")
    save(fig, "crater_profile.png")

    fig, axes = plt.subplots(2, 3, figsize=(13, 7), constrained_layout=True)
    plot_timeseries(axes, analysis)
    save(fig, "timeseries.png")

    fig, ax = plt.subplots(figsize=(7, 4.5), constrained_layout=True)
    gas_rows = [r for r in analysis["rows"] if r.get("axis") is not None]
    shown = [gas_rows[i] for i in np.unique(np.round(np.linspace(
        0, len(gas_rows) - 1, min(HISTOGRAM_TIMES, len(gas_rows)))).astype(int))] \
        if gas_rows else []
    for r in shown:
        x, rho = r["axis"]
        line, = ax.plot(1e3*(s["surface"] - x), rho, label=f"t = {r['time']} s")
        if r["shock"]["standoff"] is not None:
            ax.axvline(1e3*r["shock"]["standoff"], color=line.get_color(), linestyle="--")
    if not shown:
        ax.text(0.5, 0.5, "no gas density written", ha="center", transform=ax.transAxes)
    ax.set_xlabel("height above the surface on the axis [mm] (dashed: shock)")
    ax.set_ylabel(f"gas density ({shown[-1]['shock']['field'] if shown else 'rhoN'}), "
                  f"rows within {AXIS_BAND} nozzleRadius "
                  "[1/m^3 or kg/m^3]")
    ax.set_yscale("log")
    ax.grid(alpha=0.3)
    if shown:
        ax.legend(fontsize=7)
    save(fig, "axis_density.png")

    fig, ax = plt.subplots(figsize=(7, 4.5), constrained_layout=True)
    plot_histogram(ax, rows, "angles", "angle", "weight", "ejection angle above the surface [deg]",
                   bins=18, span=(0, 90))
    ax.set_ylabel("mass fraction of the ejecta")
    save(fig, "ejection_angle.png")

    fig, (ax, ax_e) = plt.subplots(1, 2, figsize=(12, 4.5), constrained_layout=True)
    plot_histogram(ax, rows, "speeds", "speed", "weight", "grain speed |U| [m/s]")
    ax.set_ylabel("fraction of the real grains")
    ax.set_yscale("log")
    ax.set_title("all grains")
    plot_histogram(ax_e, rows, "speeds", "ejecta_speed", "ejecta_weight",
                   "ejecta speed |U| [m/s]")
    ax_e.set_ylabel("fraction of the ejecta's real grains")
    ax_e.set_title("ejecta (x < layerTop, U_x < 0)")
    save(fig, "speed_histogram.png")

    fig, ax = plt.subplots(figsize=(7, 4.5), constrained_layout=True)
    plot_histogram(ax, rows, "T", "T", "weight", "grain temperature T_p [K]")
    ax.set_ylabel("fraction of the real grains")
    save(fig, "Tp_histogram.png")

    knp_rows = [r for r in analysis["rows"] if r.get("knp") is not None]
    fig, ax = plt.subplots(figsize=(7, 5), constrained_layout=True)
    plot_knp(ax, fig, analysis, knp_rows[-1] if knp_rows else None)
    save(fig, "knp_map.png")
    return written
