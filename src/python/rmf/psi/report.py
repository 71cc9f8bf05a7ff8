# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Plume-surface interaction reports: summary.md of a case (tables, key
numbers, definitions) and the side-by-side comparison of cases."""

import os

import numpy as np

from rmf import figures

from .observables import (ALPHA_VALID, AXIS_BAND, AXIS_FRACTION, DENSITIES, GAS_CELL,
                          HISTOGRAM_TIMES, JET_QUANTILE, KN_SWITCH, MIN_PARCELS,
                          PEAK_REGION, SHOCK_RISE, SHOCK_SUSTAIN, SIGNIFICANCE,
                          SLAB_PARCELS, SMOOTH_CELLS, STAGNATION_HEIGHT,
                          SURFACE_FRACTION, SURFACE_QUANTILE, analyse, last,
                          nearest_row, series, value)
from .plots import plot_case, plot_crater, plot_histogram, plot_knp, plot_timeseries


# Columns of the per-time table: (header, key, sub-key, scale, format)
COLUMNS = (
    ("t [us]", None, None, 1e6, "{:.4g}"),
    ("real grains", "grains", None, 1, "{:.4g}"),
    ("surface drop axis [mm]", "crater", "surface_drop", 1e3, "{:.3f}"),
    ("+- [mm]", "crater", "surface_drop_sigma", 1e3, "{:.3f}"),
    ("crater depth [mm]", "crater", "max_depth", 1e3, "{:.3f}"),
    ("+- [mm]", "crater", "max_depth_sigma", 1e3, "{:.3f}"),
    ("at r [mm]", "crater", "r_max", 1e3, "{:.2f}"),
    ("crater radius [mm]", "crater", "radius", 1e3, "{:.2f}"),
    ("eroded axis", "crater", "eroded_axis", 1, "{:.3f}"),
    ("eroded layer", "crater", "eroded_layer", 1, "{:.4f}"),
    ("shock standoff [mm]", "shock", "standoff", 1e3, "{:.3f}"),
    ("ejection angle mean [deg]", "angles", "mean", 1, "{:.1f}"),
    ("median [deg]", "angles", "median", 1, "{:.1f}"),
    ("ejecta mean speed [m/s]", "speeds", "ejecta_mean", 1, "{:.2f}"),
    ("ejecta max speed [m/s]", "speeds", "ejecta_max", 1, "{:.2f}"),
    ("toward axis (flux)", "crossing", "fraction_toward", 1, "{:.3f}"),
    ("toward axis (grains)", "crossing", "fraction_toward_grains", 1, "{:.3f}"),
    ("max alpha", "alpha", "max", 1, "{:.4g}"),
    ("above alphaValid", "validity", "fraction", 1, "{:.3g}"),
    ("min Kn_p stagnation", "knp_min", "min", 1, "{:.3g}"),
    ("Kn_p < 10", "transitional", "fraction", 1, "{:.3g}"),
    ("T_p mean Kn_p < 10 [K]", "transitional", "T", 1, "{:.2f}"),
    ("T_p min [K]", "T", "min", 1, "{:.1f}"),
    ("T_p mean [K]", "T", "mean", 1, "{:.2f}"),
    ("T_p max [K]", "T", "max", 1, "{:.1f}"),
)



def _fmt(v, scale, form):
    return "n/a" if v is None else form.format(v*scale)


def table(rows, columns=COLUMNS):
    lines = ["| " + " | ".join(c[0] for c in columns) + " |",
             "|" + "---|"*len(columns)]
    for r in rows:
        lines.append("| " + " | ".join(_fmt(value(r, c[1], c[2]), c[3], c[4])
                                       for c in columns) + " |")
    return lines


def key_numbers(analysis):
    """Lines of the key numbers of a case (summary.md)."""
    s = analysis["settings"]
    rows = analysis["rows"]
    out = []

    def at_last(label, key, sub, scale, unit, form):
        found = last(analysis, key, sub)
        if found is None:
            out.append(f"- {label}: n/a (never available, see the notes)")
        else:
            out.append(f"- {label}: {form.format(found[1]*scale)}{unit} at t = {found[0]} s")

    H = 1e3*(s['surface'] - s['layerTop'])

    def with_noise(label, sub, noise):
        for r in reversed(rows):
            v, e = value(r, "crater", sub), value(r, "crater", noise)
            if v is not None and e is not None:
                out.append(f"- {label}: {1e3*v:.3f} +- {1e3*e:.3f} mm at t = {r['time']} s")
                return
        out.append(f"- {label}: n/a (never available, see the notes)")

    with_noise(f"Surface drop on the axis (the surface below the initial layer top, "
               f"H = {H:.3g} mm, in the first annulus)", "surface_drop", "surface_drop_sigma")
    with_noise(f"Crater depth (largest surface drop among the annuli where it is "
               f"significant, z > {SIGNIFICANCE})", "max_depth", "max_depth_sigma")
    at_last("Radius of the deepest annulus", "crater", "r_max", 1e3, " mm", "{:.2f}")
    at_last("Crater radius (half depth)", "crater", "radius", 1e3, " mm", "{:.2f}")
    at_last("Eroded real-grain fraction, axis annulus", "crater", "eroded_axis", 1, "",
            "{:.3f}")
    at_last("Eroded real-grain fraction, whole layer", "crater", "eroded_layer", 1, "",
            "{:.4f}")
    for r in reversed(rows):
        g = r.get("resolution")
        if g:
            out.append(f"- Simulators per gas cell (rhoNMean > {GAS_CELL:g} m^-3, "
                       f"dsmcRhoNMean): median {g['median']:.2f}, {100*g['below10']:.0f} % "
                       f"below 10, {100*g['below1']:.0f} % below 1 ({g['cells']} of "
                       f"{g['of']} cells) at t = {r['time']} s")
            break
    at_last("Shock standoff on the axis", "shock", "standoff", 1e3, " mm", "{:.3f}")
    standoffs = series(analysis, "shock", "standoff")
    if len(standoffs) > 1:
        out.append(f"- Shock standoff over {len(standoffs)} times: "
                   f"{1e3*standoffs[:, 1].min():.3f} to {1e3*standoffs[:, 1].max():.3f} mm")
    at_last("Mean ejection angle (mass-weighted)", "angles", "mean", 1, " deg", "{:.1f}")
    at_last("Median ejection angle", "angles", "median", 1, " deg", "{:.1f}")
    at_last("Ejecta mean speed", "speeds", "ejecta_mean", 1, " m/s", "{:.2f}")
    at_last("Ejecta max speed", "speeds", "ejecta_max", 1, " m/s", "{:.2f}")
    at_last(f"Fraction crossing r = {1e3*s['crossingRadius']:g} mm toward the axis "
            "(flux-weighted)", "crossing", "fraction_toward", 1, "", "{:.3f}")
    found = last(analysis, "crossing", "fraction_toward")
    if found:
        out.append(f"- Fraction away from the axis (flux-weighted): {1 - found[1]:.3f} "
                   f"at t = {found[0]} s")
    flux_in = sum(r["crossing"]["toward_flux"] for r in rows if r.get("crossing"))
    flux_out = sum(r["crossing"]["away_flux"] for r in rows if r.get("crossing"))
    if flux_in + flux_out > 0:
        out.append(f"- Toward the axis, pooled over the written times: "
                   f"{flux_in/(flux_in + flux_out):.3f}")
    alphas = series(analysis, "alpha", "max")
    if len(alphas):
        i = int(np.argmax(alphas[:, 1]))
        out.append(f"- Max alpha over time: {alphas[i, 1]:.4g} at t = {alphas[i, 0]:.4g} s")
    else:
        out.append("- Max alpha: n/a (no alpha.grains written)")
    at_last("Min Kn_p near the stagnation region", "knp_min", "min", 1, "", "{:.3g}")
    Ts = [r["T"] for r in rows if r.get("T")]
    if Ts:
        out.append(f"- T_p range over all times: {min(T['min'] for T in Ts):.1f} to "
                   f"{max(T['max'] for T in Ts):.1f} K")
    else:
        out.append("- T_p range: n/a (no parcel temperature written)")
    return out


def definitions(analysis):
    """Definitions of the observables with this run's bins and options."""
    s, o = analysis["settings"], analysis["options"]
    H = s["surface"] - s["layerTop"]
    dr = o["dr"] or s["nozzleRadius"]/8
    first = next((r["crater"] for r in analysis["rows"] if r.get("crater")), None)
    merged = (f"{len(first['r'])} annuli, the first {1e3*first['r_edges'][1]:.3g} mm wide"
              if first else "no annulus")
    weight = "nParticle"
    if o["radial_weight"]:
        W, R = o["radial_weight"]
        weight = f"nParticle x (1 + ({W:g} - 1) r/{R:g} m)"
    return [
        f"- Real grains of a parcel: {weight}; every statistic is weighted by them "
        "(ejection angle: by mass, real grains x d^3).",
        f"- Crater: annuli of {1e3*dr:.3g} mm to r = {1e3*s['layerRadius']:.3g} mm merged "
        f"outward to {MIN_PARCELS} parcels of the reference layer (time "
        f"{analysis['reference']} s) each: {merged}; dense layer: slabs "
        + (f"of {1e3*o['dx']:.3g} mm" if o["dx"] else
           f"of H/n, n = reference parcels/{SLAB_PARCELS} (2 to 10),")
        + f" up to the first of two in a row below {SURFACE_FRACTION} of the reference "
        f"density (included); surface height h = Q_{SURFACE_QUANTILE}/{SURFACE_QUANTILE} of "
        f"the dense grains' heights above the wall (real grains), noise sigma = "
        f"h sqrt(q(1 - q)/N_eff)/q; surface drop = H - h, H = X_s - layerTop = "
        f"{1e3*H:.3g} mm; crater depth = the largest drop among the annuli where it is "
        f"significant (count test: q N_eff over Binomial(N_eff, q h/H), z > {SIGNIFICANCE}; "
        "0 +- the median sigma if none); crater radius: where the "
        "drop falls to half of it outward; eroded fraction = 1 - dense real grains / "
        "reference real grains (axis annulus; whole layer).",
        f"- Shock: per x, the radius-weighted mean of the cells within {AXIS_BAND} "
        f"nozzleRadius of the axis (the nearest one if none; columns beyond {AXIS_FRACTION} "
        f"nozzleRadius left out), {SMOOTH_CELLS}-cell running mean of the first of "
        f"{', '.join(DENSITIES)}; stagnation peak: the maximum in the {PEAK_REGION:g} of "
        f"the gap next to the surface; shock layer: the cells ending at the peak above "
        f"{SHOCK_RISE}x the {JET_QUANTILE} quantile (dips < {SHOCK_SUSTAIN} cells; at least "
        f"{SHOCK_SUSTAIN} cells, else no shock); shock where the profile rises through "
        "the midpoint of the jet minimum and the layer's median; standoff = X_s - x_shock.",
        "- Ejecta: parcels with x < layerTop and U_x < 0; ejection angle = "
        "atan2(-U_x, sqrt(U_y^2 + U_z^2)) above the surface.",
        f"- Crossing: real grains within {1e3*o['shell']:g} mm of r = "
        f"{1e3*s['crossingRadius']:g} mm; toward the axis (flux) = sum(w |v_r|) over "
        "v_r < 0 / sum(w |v_r|) (fraction of the crossings per unit time); "
        "(grains) = real grains with v_r < 0 over those with v_r != 0.",
        "- Kn_p: Knp.grains (else lambda.gas / real-grain mean d in the cell); "
        f"stagnation region: r <= nozzleRadius, height <= shock standoff "
        f"({1e3*STAGNATION_HEIGHT:g} mm without a shock).",
        f"- Above alphaValid: real-grain fraction of the parcels in cells with alpha > "
        f"{ALPHA_VALID:g} (binary collisions not valid there); Kn_p < {KN_SWITCH:g}: "
        "real-grain fraction of the parcels in cells with 0 < Kn_p < "
        f"{KN_SWITCH:g} (not free-molecular) and their mean T.",
    ]


def write_summary(analysis, output, pngs):
    s = analysis["settings"]
    lines = [f"# Plume-surface interaction observables: {os.path.abspath(analysis['case'])}",
             "",
             f"Settings (system/observablesDict): surface X_s = {s['surface']} m, "
             f"nozzleRadius = {s['nozzleRadius']} m, layerTop = {s['layerTop']} m, "
             f"layerRadius = {s['layerRadius']} m, crossingRadius = {s['crossingRadius']} m; "
             f"crater reference time {analysis['reference']} s.",
             "", "## Key numbers", ""]
    lines += key_numbers(analysis)
    lines += ["", "## Values against time", ""]
    lines += table(analysis["rows"])
    lines += ["", "## Definitions", ""] + definitions(analysis)
    lines += ["", "## Notes", ""] + ([f"- {n}" for n in analysis["notes"]] or ["- none"])
    lines += ["", "## Figures", ""] + [f"- {p}" for p in pngs]
    path = os.path.join(output, "summary.md")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def run_case(case, output=None, wanted=None, **options):
    output = output or os.path.join(case, "observables")
    analysis = analyse(case, **options)
    pngs = plot_case(analysis, output, wanted)
    return write_summary(analysis, output, pngs), analysis


def common_times(analyses):
    """Times to compare the cases at, and whether every case wrote them:
    the times written by every case when at least two of them hold parcels
    in every case; else the first case's times with parcels, each case
    then taken at its own nearest time."""
    sets = [[r["t"] for r in a["rows"]] for a in analyses]
    first = sets[0]
    scale = max(max(abs(t) for t in first), 1e-30)
    common = [t for t in first
              if all(any(abs(t - u) <= 1e-9*scale for u in other) for other in sets[1:])]
    if len(_with_parcels(analyses, common)) >= 2 or len(analyses) == 1:
        return common, True
    return [r["t"] for r in analyses[0]["rows"] if r.get("p") is not None] or first, False


def _with_parcels(analyses, times):
    return [t for t in times
            if all((nearest_row(a, t) or {}).get("p") is not None for a in analyses)]


def compare(cases, labels, output, **options):
    """Side-by-side plots and summary of several cases at equal times."""
    plt = figures.pyplot()
    os.makedirs(output, exist_ok=True)
    analyses = [analyse(c, **options) for c in cases]
    common, exact = common_times(analyses)
    # the common times with parcels in every case, up to HISTOGRAM_TIMES of them
    shown = _with_parcels(analyses, common)
    if len(shown) > HISTOGRAM_TIMES:
        shown = [shown[i] for i in np.unique(np.round(np.linspace(
            0, len(shown) - 1, HISTOGRAM_TIMES)).astype(int))]
    pngs = []
    ncol = len(cases)

    def save(fig, name):
        figures.save(fig, os.path.join(output, name))
        pngs.append(name)

    fig, axes = plt.subplots(1, ncol, figsize=(5*ncol, 4.5), squeeze=False,
                             sharey=True, constrained_layout=True)
    for ax, a, label in zip(axes[0], analyses, labels):
        plot_crater(ax, a, [nearest_row(a, t) for t in shown], label)
    save(fig, "compare_crater.png")

    fig, axes = plt.subplots(2, 3, figsize=(13, 7), constrained_layout=True)
    for i, (a, label) in enumerate(zip(analyses, labels)):
        plot_timeseries(axes, a, label, f"C{i % 10}")
    save(fig, "compare_timeseries.png")

    for name, key, values, weights, xlabel, span, ylabel in (
            ("compare_speed.png", "speeds", "speed", "weight", "grain speed |U| [m/s]",
             None, "fraction of the real grains"),
            ("compare_ejecta_speed.png", "speeds", "ejecta_speed", "ejecta_weight",
             "ejecta speed |U| [m/s]", None, "fraction of the ejecta's real grains"),
            ("compare_ejection_angle.png", "angles", "angle", "weight",
             "ejection angle above the surface [deg]", (0, 90), "mass fraction of the ejecta"),
            ("compare_Tp.png", "T", "T", "weight", "grain temperature T_p [K]", None,
             "fraction of the real grains")):
        rows = [[nearest_row(a, t) for t in shown] for a in analyses]
        if span is None:
            data = [r[key][values] for rr in rows for r in rr
                    if r and r.get(key) and r[key].get(values) is not None
                    and len(r[key][values])]
            span = (min(d.min() for d in data), max(d.max() for d in data)) if data else None
            if span and span[1] <= span[0]:
                span = (span[0], span[0] + 1)
        fig, axes = plt.subplots(1, ncol, figsize=(5*ncol, 4), squeeze=False, sharey=True,
                                 constrained_layout=True)
        for ax, rr, label in zip(axes[0], rows, labels):
            plot_histogram(ax, rr, key, values, weights, xlabel,
                           bins=18 if key == "angles" else 40, span=span)
            ax.set_title(label)
            if values == "speed":
                ax.set_yscale("log")     # the resting layer dwarfs the ejecta
        axes[0, 0].set_ylabel(ylabel)
        save(fig, name)

    t_knp = shown[-1] if shown else (common[-1] if common else None)
    fig, axes = plt.subplots(1, ncol, figsize=(5*ncol, 4.5), squeeze=False,
                             constrained_layout=True)
    knp_rows = [nearest_row(a, t_knp) if t_knp is not None else None for a in analyses]
    positive = [r["knp"][r["knp"] > 0] for r in knp_rows
                if r and r.get("knp") is not None and (r["knp"] > 0).any()]
    span = (min(k.min() for k in positive), max(k.max() for k in positive)) if positive else None
    for ax, a, row, label in zip(axes[0], analyses, knp_rows, labels):
        plot_knp(ax, fig, a, row, f"{label}: Kn_p, t = {row['time'] if row else 'n/a'} s", span)
    save(fig, "compare_knp.png")

    lines = ["# Plume-surface interaction: comparison", ""]
    lines += [f"- {label}: {os.path.abspath(c)}" for label, c in zip(labels, cases)]
    lines += ["", ("Times written by every case: " if exact else
                   "Fewer than two times with parcels written by every case: each case "
                   f"at its time nearest to {labels[0]}'s (its own time in the table): ")
              + ", ".join(f"{t:g}" for t in common) + " s",
              "Profiles and histograms at: "
              + (", ".join(f"{t:g}" for t in shown) + " s" if shown else
                 "none (no time with parcels in every case)"),
              ""]
    columns = (("case", None, None, 1, "{}"),) + COLUMNS
    lines += ["## Values at the compared times (each case at its own t)", "",
              "| " + " | ".join(c[0] for c in columns) + " |", "|" + "---|"*len(columns)]
    for t in common:
        for a, label in zip(analyses, labels):
            r = nearest_row(a, t)
            cells = [label] + [_fmt(value(r, c[1], c[2]), c[3], c[4]) for c in COLUMNS]
            lines.append("| " + " | ".join(cells) + " |")
    for a, label in zip(analyses, labels):
        lines += ["", f"## Key numbers: {label}", ""] + key_numbers(a)
        if a["notes"]:
            lines += ["", f"Notes ({label}):"] + [f"- {n}" for n in a["notes"]]
    lines += ["", "## Definitions", ""] + definitions(analyses[0])
    lines += ["", "## Figures", ""] + [f"- {p}" for p in pngs]
    path = os.path.join(output, "summary.md")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path, analyses
