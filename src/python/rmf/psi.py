# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Plume-surface interaction observables (doc/physics.md 7.2).

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
./psiCompare).

Case (the tutorial tutorials/psi/apolloScaledPSI): a wedge about the x
axis, y radial; nozzle exit at x = 0, the plume flows in +x onto the wall
`surface` at x = X_s; height above the surface is X_s - x; the radius of a
point is sqrt(y^2 + z^2).  system/observablesDict holds `surface` (X_s),
`nozzleRadius`, `layerTop` (x of the initial dust top), `layerRadius` and
`crossingRadius` [m].  Gas fields (rhoN, UMean, lambda.gas, ...) and grain
fields (alpha.grains, Knp.grains) at the written times; parcels in
<time>/lagrangian/grains (positions, U, T, d, nParticle).  A parcel stands
for nParticle real grains: every statistic below is weighted by it
("real grains"), the ejection angle by mass (nParticle d^3).

Observables, each a function of this module:
1. Crater (surface_profile).  Annuli of width dr (default nozzleRadius/8)
   from the axis to layerRadius, merged outward until each holds 100
   parcels of the reference layer (the parcels in [layerTop, X_s] at the
   reference time, the first written time with parcels; an outer
   remainder joins the annulus inside it; a layer of fewer than 100
   parcels is not measurable).  In each annulus (its column of dust):
   - dense layer: slabs of height H/n stacked from the wall (n = the
     annulus's reference parcels / 20, 2 to 10; --dx sets the height),
     taken up to the first of two slabs in a row whose real grains are
     below 0.5 of the reference density (that slab included): dilute
     ejecta above the surface do not count;
   - surface height h = Q_0.9/0.9, Q_0.9 the real-grain-weighted 0.9
     quantile of the dense layer's heights above the wall (X_s - x):
     exact for a column of uniform density of any height, so a layer
     compacted (same grains, thinner) reads lower.  Its noise sigma =
     h sqrt(0.9 x 0.1/N_eff)/0.9 (the quantile's sampling error, N_eff =
     (sum w)^2/sum w^2 of the dense grains; 0.027 mm for 100 parcels in
     a 1 mm layer); a column with no dense grain has h = 0 (bare wall);
   - surface drop d(r) = H - h (H = X_s - layerTop: how far the surface
     is below the initial top; negative: a rim);
   - eroded fraction: 1 - the dense layer's real grains over the
     annulus's reference real grains (0 for compaction alone; grains
     moved to another annulus count too, negative when gained).
   Reported: the surface drop on the axis (the first annulus) +- its
   sigma; the crater depth, the largest d(r) among the annuli whose drop
   is significant (0 +- the median sigma when none is: a plain max over
   ~40 annuli of noise reads a few sigma, the old 0.97 mm at t = 0 of the
   5000-parcel demo), its annulus (at r) and the crater radius where d(r)
   falls to half of it outward (linear between annulus centres); the
   eroded fraction of the axis annulus and of the whole layer.
   Significant: were the surface still at H, the dense grains below the
   measured quantile would be Binomial(N_eff, p0 = 0.9 h/H); the drop
   counts when 0.9 N_eff lies 3 of its sd above its mean, z > 3.  (The
   height's error has a long tail toward low surfaces, about 6 effective
   grains lying above Q_0.9 in a 100-parcel annulus: judged as d > 3
   sigma, 30 % of untouched 5000-parcel layers show a crater, 1.5 % on
   the count; validation/psiObservables.)  Known bias: the quantile of a
   few grains reads low by about h/(2 N_eff) (0.15 sigma on an untouched
   demo layer, 0.5 sigma on a 0.4 mm crater floor, whose spread is also
   1.25 sigma).
2. Shock standoff (shock_standoff).  Gas density (the first written of
   rhoNMean, rhoN, rhoMMean, rhoM) along the axis: in each column of
   cells (equal x) the mean of the cells within nozzleRadius/8 of the axis
   weighted by radius (4 rows in the demo; the nearest cell when none is
   that close; columns whose nearest cell is beyond nozzleRadius/4 are
   left out), smoothed by a 3-cell running mean.  The tutorial's rhoNMean
   is a batch mean over the steps since the previous write (fieldAverage
   restartOnOutput; without it, a mean since the start of the run: a note
   says which); rhoN is one step's simulators.  Search region: from the
   nozzle exit (x = 0) to the stagnation peak, the largest density in the
   half of the gap next to the surface (the wall, or the top of a dust
   layer that holds the gas off it).  Shock layer: the run of cells ending
   at the peak whose density is at least 1.5 times the jet's (the 0.25
   quantile of the region, not a dip), dips shorter than 3 cells included; it must be 3 cells
   long at least (a sustained rise), else no shock.  Jet density: the
   minimum upstream of the layer; post-shock: the median over the layer.
   The shock is where the profile first rises through their midpoint in
   the layer (linear between cells); the standoff is X_s - x_shock.
   Before (one axis row, the first crossing of the midpoint after the
   global minimum) a dip of the jet's noise far upstream could be the
   minimum and a later jet wiggle the crossing: standoffs of 8-17 mm on
   the hybrid demo at some writes, against about 3 mm.  axis_density.png
   shows the profile and the shock found.
3. Ejection angle (ejection_angles).  Ejecta: parcels above the initial
   layer top (x < layerTop) moving away from the surface (U_x < 0).  Angle
   above the surface: atan2(-U_x, sqrt(U_y^2 + U_z^2)), 0 along the
   surface, 90 degrees normal to it; mass-weighted mean, median and
   histogram.
4. Speeds (speeds): |U| of all parcels and of the ejecta, real-grain
   weighted histogram; ejecta mean (real-grain weighted) and max speed.
5. Crossing r = crossingRadius (crossing): real grains in the shell
   |r - r_c| < shell (0.5 mm) with radial velocity v_r < 0 (toward the
   axis) or > 0 (away).  The fraction toward the axis is flux-weighted:
   sum(w |v_r|) over v_r < 0 over sum(w |v_r|), which is the fraction of
   the crossings of r_c per unit time in the limit of a thin shell (a
   resting grain crosses nothing).  The plain real-grain fraction is
   reported too.  Crossings are not matched between writes (parcels carry
   no identity across writes).
6. Max alpha (max_alpha): largest alpha.grains over the cells.
7. Kn_p (knp_cells): Knp.grains per cell (lambda/d_p); when absent, the
   cell's lambda.gas over the real-grain mean d of the parcels in it.
   Map on the (r, height) plane, log colour scale.  Near the stagnation
   region (min_knp_stagnation): cells with r <= nozzleRadius between the
   shock and the surface (height <= standoff; 5 mm when no shock is
   found).
8. Grain temperature (temperatures): real-grain weighted histogram of T,
   min, max and mean.

Missing data (no parcels at a time, no gas fields at time 0, no Knp.grains)
gives None for that observable and a note saying why; summary.md lists
the notes and writes "n/a" in the tables, never NaN.
"""

import argparse
import math
import os
import re
import subprocess
import sys

import numpy as np

from rmf import foam

CLOUD = "grains"
SETTINGS = ("surface", "nozzleRadius", "layerTop", "layerRadius", "crossingRadius")
SURFACE_QUANTILE = 0.9          # surface height: this real-grain quantile / itself
SURFACE_FRACTION = 0.5          # dense layer: ends at two slabs below 0.5 x initial
MIN_PARCELS = 100               # reference parcels an annulus needs (merged out to it)
SLAB_PARCELS = 20               # reference parcels per slab (2 to 10 slabs)
SIGNIFICANCE = 3                # crater depth: annuli whose drop has z > 3
SHOCK_RISE = 1.5                # post-shock over jet density needed for a shock
AXIS_FRACTION = 0.25            # axis columns: first row within 0.25 nozzleRadius
AXIS_BAND = 0.125               # rows within 0.125 nozzleRadius averaged
SMOOTH_CELLS = 3                # running mean along the axis
SHOCK_SUSTAIN = 3               # cells: the shock layer's length and longest dip
JET_QUANTILE = 0.25             # jet level of the shock layer's threshold
PEAK_REGION = 0.5               # stagnation peak sought in this fraction of the
                                # nozzle-surface gap next to the surface
SHELL = 0.5e-3                  # half width of the crossing shell [m]
STAGNATION_HEIGHT = 5e-3        # stagnation region height without a shock [m]
HISTOGRAM_TIMES = 4             # default number of times in the histograms
MAX_POLYGONS = 200000           # Kn_p map cell by cell up to this many cells,
                                # interpolated between centres beyond
# Gas density for the shock, first found: time averages before the
# instantaneous sample (one step's simulators: noisier)
DENSITIES = ("rhoNMean", "rhoN", "rhoMMean", "rhoM")


# --------------------------------------------------------------- input ----

def read_settings(case):
    """The floats of system/observablesDict (a flat dictionary)."""
    path = os.path.join(case, "system", "observablesDict")
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path}: missing (needs {', '.join(SETTINGS)})")
    entries = foam.read_dict(path)
    missing = [k for k in SETTINGS if k not in entries]
    if missing:
        raise KeyError(f"{path}: missing {', '.join(missing)}")
    return {k: float(entries[k]) for k in SETTINGS}


def parcels(case, time, cloud=CLOUD, radial_weight=None):
    """Parcels at time as a dict (pos, cell, U, n, and d, T when written),
    or None when the time has no parcel of the cloud.  n: real grains per
    parcel, nParticle; times RWF(r) = 1 + (W - 1) r/R when radial_weight =
    (W, R) is given (parcels weighted by radius implicitly, as the gas's
    simulators: doc/physics.md 6)."""
    base = os.path.join(case, time, "lagrangian", cloud)
    if not os.path.exists(os.path.join(base, "positions")):
        return None
    pos, cell = foam.read_positions(os.path.join(base, "positions"), cells=True)
    if len(pos) == 0:
        return None
    p = dict(pos=pos, cell=cell)
    for name, key, required in (("U", "U", True), ("nParticle", "n", True),
                                ("d", "d", False), ("T", "T", False)):
        path = os.path.join(base, name)
        if not os.path.exists(path):
            if required:
                raise FileNotFoundError(f"{path}: missing ({len(pos)} parcels)")
            p[key] = None
            continue
        values = foam.read_list(path)
        if name == "U":
            values = values.reshape(-1, 3)
        if len(values) != len(pos):
            raise ValueError(f"{path}: {len(values)} values for {len(pos)} parcels")
        p[key] = values
    if radial_weight is not None:
        W, R = radial_weight
        p["n"] = p["n"]*(1 + (W - 1)*radius(pos)/R)
    return p


def radius(pos):
    """Distance from the x axis."""
    return np.hypot(pos[:, 1], pos[:, 2])


def radial_velocity(pos, U):
    """Velocity component along the radius (away from the axis > 0)."""
    r = radius(pos)
    safe = np.where(r > 0, r, 1.0)
    return np.where(r > 0, (pos[:, 1]*U[:, 1] + pos[:, 2]*U[:, 2])/safe, 0.0)


def mesh(case):
    """Cell centres of the case: dict(C, x, r, n); uses a written C field
    or runs postProcess -func writeCellCentres on the first time."""
    names = foam.times(case)
    if not names:
        raise FileNotFoundError(f"{case}: no time directories")
    written = [t for t in names if os.path.exists(os.path.join(case, t, "C"))]
    try:
        C = foam.cell_centres(case, written[0] if written else names[0])
    except (FileNotFoundError, subprocess.CalledProcessError) as error:
        raise RuntimeError(f"{case}: no cell centres (a C field) and postProcess "
                           f"could not write them (source etc/bashrc): {error}")
    return dict(C=C, x=C[:, 0], r=radius(C), n=len(C))


def meridian_cells(case):
    """Outline of every cell on the meridian plane, (x, r) polygons, from
    the faces of the mesh's first wedge patch (one per cell), or None when
    the mesh has no wedge patch or is not written in ASCII."""
    try:
        wedges = [p for p in foam.read_boundary(case).values() if p.get("type") == "wedge"]
        if not wedges:
            return None
        n_faces, start = int(wedges[0]["nFaces"]), int(wedges[0]["startFace"])
        points = foam.read_points(case)
        faces = foam.read_faces(case, start, n_faces)
        owner = foam.read_labels(case, "owner")[start:start + n_faces]
    except (OSError, ValueError, KeyError, IndexError):
        return None
    polygons = [None]*(owner.max() + 1 if len(owner) else 0)
    for cell, face in zip(owner, faces):
        pts = points[face]
        polygons[cell] = np.stack([pts[:, 0], np.hypot(pts[:, 1], pts[:, 2])], -1)
    return polygons


def field(case, time, name, ncells):
    """Internal field at time, or None when not written."""
    path = os.path.join(case, time, name)
    if not os.path.exists(path):
        return None
    return foam.read_field(path, ncells)


# ------------------------------------------------------- observables ----

def annuli(reference, settings, dr=None, min_parcels=MIN_PARCELS):
    """Annulus edges of the crater: annuli of width dr (default
    nozzleRadius/8) from the axis to layerRadius, merged outward until each
    holds min_parcels parcels of the reference layer (a remainder below it
    joins the annulus inside it).  Returns (edges, reference parcels per
    annulus); a single annulus below min_parcels is not measurable."""
    R = settings["layerRadius"]
    dr = dr or settings["nozzleRadius"]/8
    fine = np.linspace(0, R, max(1, int(round(R/dr))) + 1)
    counts, _ = np.histogram(radius(reference["pos"]), fine)
    edges, held = [0.0], []
    total = 0
    for j, c in enumerate(counts):
        total += c
        if total >= min_parcels:
            edges.append(fine[j + 1])
            held.append(total)
            total = 0
    if total or len(edges) == 1:
        if len(edges) > 1:
            edges[-1] = fine[-1]
            held[-1] += total
        else:
            edges.append(fine[-1])
            held.append(total)
    return np.array(edges), np.array(held)


def weighted_quantile(values, weights, q):
    """Quantile q of values with weights: linear between the midpoints of
    the sorted values' cumulative weights (exact for a lattice)."""
    order = np.argsort(values)
    v, w = values[order], weights[order]
    c = (np.cumsum(w) - 0.5*w)/w.sum()
    return float(np.interp(q, c, v))


def _in_layer(p, settings):
    X_s, top = settings["surface"], settings["layerTop"]
    x = p["pos"][:, 0]
    keep = (x >= top - 1e-9*X_s) & (x <= X_s + 1e-9*X_s) & \
        (radius(p["pos"]) <= settings["layerRadius"])
    return dict(pos=p["pos"][keep], n=p["n"][keep])


def surface_profile(p, reference, settings, dr=None, dx=None, quantile=SURFACE_QUANTILE,
                    fraction=SURFACE_FRACTION, min_parcels=MIN_PARCELS,
                    significance=SIGNIFICANCE):
    """Dust surface, surface drop, crater depth and eroded fraction against
    r (module docstring, item 1).

    p, reference: parcels now and at the reference time (dicts of
    `parcels`).  dr: width of the annuli before merging (`annuli`); dx:
    slab height of the density criterion (default: the layer over
    reference parcels / SLAB_PARCELS slabs, 2 to 10).  Returns dict(r_edges,
    r [annulus centres], parcels [reference parcels per annulus], height
    [surface height above the wall], sigma [its noise], depth [H - height],
    eroded [fraction of the annulus's reference real grains not in its
    dense layer], surface_drop, surface_drop_sigma [the axis annulus],
    max_depth, max_depth_sigma, r_max [the deepest annulus whose drop is
    significant, z > `significance`; 0, the median sigma and None when
    none is],
    radius [half-depth radius, or None], eroded_axis, eroded_layer, layer
    [H], z [significance of the drop, see below]); annuli not measurable (fewer than min_parcels reference parcels)
    hold NaN.
    """
    X_s, H = settings["surface"], settings["surface"] - settings["layerTop"]
    ref = _in_layer(reference, settings)
    if len(ref["n"]) == 0:
        raise ValueError("surface_profile: no reference grain in the layer "
                         f"[{settings['layerTop']}, {X_s}] within r <= "
                         f"{settings['layerRadius']}")
    edges, held = annuli(ref, settings, dr, min_parcels)
    m = len(held)
    j_ref = np.searchsorted(edges, radius(ref["pos"]), side="right") - 1
    ref_grains = np.bincount(np.clip(j_ref, 0, m - 1), weights=ref["n"], minlength=m)
    h_all = X_s - p["pos"][:, 0]
    j_all = np.searchsorted(edges, radius(p["pos"]), side="right") - 1
    height, sigma, dense_grains, n_eff = (np.full(m, np.nan) for _ in range(4))
    for j in range(m):
        if held[j] < min_parcels:
            continue
        slabs = int(min(10, max(2, held[j]//SLAB_PARCELS)))
        step = dx or H/slabs
        sel = (j_all == j) & (h_all >= -1e-9*X_s) & (h_all <= X_s)
        h, w = np.maximum(h_all[sel], 0.0), p["n"][sel]
        k = np.minimum((h/step).astype(int), int(X_s/step))
        per_slab = ref_grains[j]*step/H
        counts = np.bincount(k, weights=w, minlength=int(X_s/step) + 2)
        low = counts < fraction*per_slab
        run = np.nonzero(low[:-1] & low[1:])[0]          # two slabs in a row
        top = run[0] if len(run) else len(counts) - 1    # first of them included
        dense = k <= top
        dense_grains[j] = w[dense].sum()
        if not dense.any():
            height[j], sigma[j] = 0.0, 0.0               # bare wall
            continue
        hq = weighted_quantile(h[dense], w[dense], quantile)
        n_eff[j] = w[dense].sum()**2/np.sum(w[dense]**2)
        height[j] = hq/quantile
        sigma[j] = height[j]*math.sqrt(quantile*(1 - quantile)/n_eff[j])/quantile
    depth = H - height
    # significance of a drop: were the surface still at H, the dense grains
    # below the measured quantile would be Binomial(N_eff, p0 = q h/H);
    # z = how many of its sd q N_eff lies above its mean
    with np.errstate(invalid="ignore", divide="ignore"):
        p0 = np.clip(quantile*height/H, 1e-12, 1 - 1e-12)
        z = np.where(height == 0, np.inf,
                     (quantile - p0)*np.sqrt(n_eff/(p0*(1 - p0))))
    eroded = 1 - dense_grains/ref_grains
    centres = 0.5*(edges[1:] + edges[:-1])
    ok = np.isfinite(depth)
    out = dict(r_edges=edges, r=centres, parcels=held, height=height, sigma=sigma,
               depth=depth, z=z, eroded=eroded, layer=H, surface_drop=None,
               surface_drop_sigma=None, max_depth=None, max_depth_sigma=None,
               r_max=None, radius=None, eroded_axis=None, eroded_layer=None)
    if not ok.any():
        return out
    out.update(surface_drop=float(depth[0]) if ok[0] else None,
               surface_drop_sigma=float(sigma[0]) if ok[0] else None,
               eroded_axis=float(eroded[0]) if ok[0] else None,
               eroded_layer=float(1 - np.nansum(dense_grains)/ref_grains[ok].sum()))
    significant = ok & (np.where(ok, z, -np.inf) > significance)
    if not significant.any():
        out.update(max_depth=0.0, max_depth_sigma=float(np.median(sigma[ok])))
        return out
    i = int(np.nonzero(significant)[0][np.argmax(depth[significant])])
    out.update(max_depth=float(depth[i]), max_depth_sigma=float(sigma[i]),
               r_max=float(centres[i]))
    half = 0.5*depth[i]
    for k in range(i + 1, m):                        # out to half the depth
        if not ok[k]:
            break
        if depth[k] <= half:
            f = (depth[k - 1] - half)/(depth[k - 1] - depth[k])
            out["radius"] = float(centres[k - 1] + f*(centres[k] - centres[k - 1]))
            break
    return out


def axis_profile(x, r, values, cap, band=0.0):
    """Values along the axis: in each column of cell centres (equal x to
    1 nm) the mean of the cells within `band` of the axis, weighted by
    their radius (a wedge cell's volume on a uniform radial spacing), or of
    the cell(s) nearest the axis when none is within band; columns whose
    nearest cell is beyond cap are left out (graded or multi-block meshes
    keep their own first rows): (x, values) sorted by x."""
    xs = np.round(x, 9)
    unique, index = np.unique(xs, return_inverse=True)
    first = np.full(len(unique), np.inf)
    np.minimum.at(first, index, r)
    near = ((r <= first[index] + 1e-9) | (r <= band)) & (first[index] <= cap)
    keep, index = np.unique(index[near], return_inverse=True)
    w = np.maximum(r[near], 1e-300)
    mean = np.bincount(index, weights=w*values[near])/np.bincount(index, weights=w)
    return unique[keep], mean


def axis_density(x, r, rho, settings):
    """The axis profile of the shock (module docstring, item 2): rows
    within AXIS_BAND nozzleRadius, columns within AXIS_FRACTION of it."""
    return axis_profile(x, r, rho, AXIS_FRACTION*settings["nozzleRadius"],
                        AXIS_BAND*settings["nozzleRadius"])


def _running_mean(v, cells):
    kernel = np.ones(cells)
    return np.convolve(v, kernel, "same")/np.convolve(np.ones_like(v), kernel, "same")


def _layer_start(s, level, sustain):
    """First index of the run of cells ending at the last one where
    s >= level, dips below level shorter than `sustain` cells included;
    len(s) when the last cell is below level."""
    k, below = len(s), 0
    for i in range(len(s) - 1, -1, -1):
        if s[i] >= level:
            k, below = i, 0
        else:
            below += 1
            if below >= sustain or k == len(s):
                break
    return k


def shock_standoff(x, rho, surface, smooth=SMOOTH_CELLS, rise=SHOCK_RISE,
                   sustain=SHOCK_SUSTAIN):
    """Normal-shock standoff on the axis (module docstring, item 2).

    x, rho: the axis profile (sorted by x; the cells between the nozzle
    exit x = 0 and the surface are searched).  Returns dict(standoff,
    x_shock, rho_jet, rho_post, x_peak, smooth [the smoothed profile], x)
    or, when no shock is found, dict(standoff=None, note=why).
    """
    inside = (x >= 0) & (x < surface)
    x, rho = x[inside], rho[inside]
    if len(x) < 2*sustain:
        return dict(standoff=None, note=f"{len(x)} axis cells: too few for a shock")
    s = _running_mean(rho, smooth)
    # stagnation peak (the wall or the dust top): the largest density in the
    # part of the gap next to the surface (the exit may be denser)
    near = np.nonzero(x >= (1 - PEAK_REGION)*surface)[0]
    if len(near) == 0 or near[0] < sustain:
        return dict(standoff=None, note=f"{len(near)} axis cells near the surface")
    peak = int(near[np.argmax(s[near])])
    jet = float(np.quantile(s[:peak + 1], JET_QUANTILE))  # typical jet, not a dip
    k = _layer_start(s[:peak + 1], rise*jet, sustain)
    if not jet > 0 or peak + 1 - k < sustain or k == 0:
        return dict(standoff=None,
                    note=f"no rise to {rise} x the jet density ({jet:.3g}) sustained "
                         f"over {sustain} cells up to the stagnation peak at "
                         f"x = {1e3*x[peak]:.3g} mm")
    jet, post = float(s[:k].min()), float(np.median(s[k:peak + 1]))
    mid = 0.5*(jet + post)
    j = k + int(np.nonzero(s[k:peak + 1] >= mid)[0][0])
    f = (mid - s[j - 1])/(s[j] - s[j - 1]) if s[j] != s[j - 1] else 0.5
    x_shock = x[j - 1] + min(max(f, 0.0), 1.0)*(x[j] - x[j - 1])
    return dict(standoff=float(surface - x_shock), x_shock=float(x_shock),
                rho_jet=jet, rho_post=post, x_peak=float(x[peak]), smooth=s, x=x)


def ejecta(p, settings):
    """Mask of ejecta: above the initial layer top, moving off the surface."""
    return (p["pos"][:, 0] < settings["layerTop"]) & (p["U"][:, 0] < 0)


def weighted_median(values, weights):
    order = np.argsort(values)
    cum = np.cumsum(weights[order])
    return float(values[order][np.searchsorted(cum, 0.5*cum[-1])])


def ejection_angles(p, settings):
    """Angles [deg] above the surface of the ejecta's velocities, mass
    weights (nParticle d^3, nParticle when d is not written), mean and
    median; None when there are no ejecta."""
    sel = ejecta(p, settings)
    if not sel.any():
        return None
    U = p["U"][sel]
    angle = np.degrees(np.arctan2(-U[:, 0], np.hypot(U[:, 1], U[:, 2])))
    w = p["n"][sel]*(p["d"][sel]**3 if p["d"] is not None else 1.0)
    return dict(angle=angle, weight=w, mean=float(np.average(angle, weights=w)),
                median=weighted_median(angle, w), parcels=int(sel.sum()),
                mass_weighted=p["d"] is not None)


def speeds(p, settings):
    """Speeds of all parcels and of the ejecta (real-grain weights)."""
    speed = np.linalg.norm(p["U"], axis=1)
    sel = ejecta(p, settings)
    out = dict(speed=speed, weight=p["n"], mean=float(np.average(speed, weights=p["n"])),
               max=float(speed.max()), ejecta=int(sel.sum()),
               ejecta_speed=speed[sel], ejecta_weight=p["n"][sel],
               ejecta_mean=None, ejecta_max=None)
    if sel.any():
        out["ejecta_mean"] = float(np.average(speed[sel], weights=p["n"][sel]))
        out["ejecta_max"] = float(speed[sel].max())
    return out


def crossing(p, settings, shell=SHELL):
    """Real grains crossing r = crossingRadius toward / away from the axis
    (module docstring, item 5): dict(toward_flux, away_flux,
    fraction_toward [flux-weighted], toward, away [real grains],
    fraction_toward_grains, parcels); None when the shell holds no moving
    grain."""
    rc = settings["crossingRadius"]
    sel = np.abs(radius(p["pos"]) - rc) < shell
    vr = radial_velocity(p["pos"][sel], p["U"][sel])
    w = p["n"][sel]
    inward, outward = vr < 0, vr > 0
    flux_in = float(np.sum(w[inward]*-vr[inward]))
    flux_out = float(np.sum(w[outward]*vr[outward]))
    if flux_in + flux_out == 0:
        return None
    n_in, n_out = float(w[inward].sum()), float(w[outward].sum())
    return dict(toward_flux=flux_in, away_flux=flux_out,
                fraction_toward=flux_in/(flux_in + flux_out),
                toward=n_in, away=n_out, fraction_toward_grains=n_in/(n_in + n_out),
                parcels=int(sel.sum()))


def max_alpha(alpha):
    """Largest solid volume fraction and its cell, or None."""
    if alpha is None:
        return None
    i = int(np.argmax(alpha))
    return dict(max=float(alpha[i]), cell=i)


def knp_cells(case, time, ncells, p=None):
    """Kn_p per cell (0 where no grain) and its source, or (None, why)."""
    knp = field(case, time, "Knp." + CLOUD, ncells)
    if knp is not None:
        return knp, "Knp." + CLOUD
    lam = field(case, time, "lambda.gas", ncells)
    if lam is None:
        return None, "neither Knp.grains nor lambda.gas written"
    if p is None or p["d"] is None:
        return None, "no Knp.grains, and no parcel diameters for lambda.gas/d"
    wd = np.bincount(p["cell"], weights=p["n"]*p["d"], minlength=ncells)
    w = np.bincount(p["cell"], weights=p["n"], minlength=ncells)
    knp = np.zeros(ncells)
    has = w > 0
    knp[has] = lam[has]/(wd[has]/w[has])
    return knp, "lambda.gas / mean parcel d"


def min_knp_stagnation(knp, cells, settings, standoff=None):
    """Smallest positive Kn_p in the stagnation region (r <= nozzleRadius,
    height above the surface <= standoff, or STAGNATION_HEIGHT when none):
    dict(min, r, height, region) or None when no cell there holds grains."""
    height = settings["surface"] - cells["x"]
    top = standoff if standoff is not None else STAGNATION_HEIGHT
    region = (cells["r"] <= settings["nozzleRadius"]) & (height >= 0) & \
        (height <= top) & (knp > 0)
    if not region.any():
        return None
    i = np.nonzero(region)[0][np.argmin(knp[region])]
    return dict(min=float(knp[i]), r=float(cells["r"][i]), height=float(height[i]),
                region=float(top))


def temperatures(p):
    """Grain temperatures with real-grain weights, min, max, mean; None when
    T is not written."""
    if p["T"] is None:
        return None
    T, w = p["T"], p["n"]
    return dict(T=T, weight=w, min=float(T.min()), max=float(T.max()),
                mean=float(np.average(T, weights=w)))


# ----------------------------------------------------------- analysis ----

def analyse(case, dr=None, dx=None, shell=SHELL, radial_weight=None):
    """Every observable at every written time: dict(case, settings, cells,
    times [rows], notes, reference time)."""
    settings = read_settings(case)
    cells = mesh(case)
    rows, notes, reference, averaged = [], [], None, set()
    for t in foam.times(case):
        row = dict(time=t, t=float(t))
        p = parcels(case, t, radial_weight=radial_weight)
        row["p"] = p
        if p is None:
            notes.append(f"t = {t}: no {CLOUD} parcels written: grain observables n/a")
        else:
            if reference is None:
                reference = (t, p)
            row["grains"] = float(p["n"].sum())
            row["crater"] = surface_profile(p, reference[1], settings, dr, dx)
            row["angles"] = ejection_angles(p, settings)
            if row["angles"] is None:
                notes.append(f"t = {t}: no ejecta (x < layerTop, U_x < 0)")
            row["speeds"] = speeds(p, settings)
            row["crossing"] = crossing(p, settings, shell)
            if row["crossing"] is None:
                notes.append(f"t = {t}: no moving grain within {shell*1e3:g} mm "
                             f"of r = {settings['crossingRadius']*1e3:g} mm")
            row["T"] = temperatures(p)
            if row["T"] is None:
                notes.append(f"t = {t}: no parcel temperature T written")
        rho, name = None, None
        for name in DENSITIES:
            rho = field(case, t, name, cells["n"])
            if rho is not None:
                break
        if rho is None:
            notes.append(f"t = {t}: no gas density ({', '.join(DENSITIES)}): shock n/a")
            row["shock"] = None
        else:
            x, values = axis_density(cells["x"], cells["r"], rho, settings)
            row["axis"] = (x, values)
            row["shock"] = shock_standoff(x, values, settings["surface"])
            row["shock"]["field"] = name
            if name not in averaged and (values > 0).any():
                averaged.add(name)
                notes.append(density_note(case, name))
            if row["shock"]["standoff"] is None:
                notes.append(f"t = {t}: no shock on the axis ({row['shock']['note']})")
        row["alpha"] = max_alpha(field(case, t, "alpha." + CLOUD, cells["n"]))
        if row["alpha"] is None:
            notes.append(f"t = {t}: no alpha.{CLOUD}")
        knp, source = knp_cells(case, t, cells["n"], p)
        row["knp"] = knp
        row["knp_source"] = source
        if knp is None:
            notes.append(f"t = {t}: no Kn_p ({source})")
            row["knp_min"] = None
        else:
            standoff = row["shock"]["standoff"] if row["shock"] else None
            row["knp_min"] = min_knp_stagnation(knp, cells, settings, standoff)
            if row["knp_min"] is None:
                notes.append(f"t = {t}: no grain in the stagnation region (Kn_p n/a)")
        rows.append(row)
    if reference is None:
        notes.append(f"no {CLOUD} parcels at any time: grain observables n/a")
    return dict(case=case, settings=settings, cells=cells, rows=rows, notes=notes,
                reference=reference[0] if reference else None,
                options=dict(dr=dr, dx=dx, shell=shell, radial_weight=radial_weight),
                polygons=meridian_cells(case) if cells["n"] <= MAX_POLYGONS else None)


def density_note(case, name):
    """What the density field of the shock is: a fieldAverage mean is over
    the steps since the previous write when system/controlDict sets
    restartOnOutput (the tutorial's batch means), else since the start of
    the run (a cumulative mean: the standoff of the time-averaged flow)."""
    if not name.endswith("Mean"):
        return (f"shock from {name}: one step's simulators (no time average "
                "written: noisy)")
    try:
        text = foam.dict_text(os.path.join(case, "system", "controlDict"))
    except OSError:
        text = ""
    if re.search(r"restartOnOutput\s+(true|on|yes)\s*;", text):
        return (f"shock from {name}: batch mean over the steps since the previous "
                "write (fieldAverage restartOnOutput)")
    return (f"shock from {name}: mean since the start of the run (fieldAverage "
            "without restartOnOutput: the standoff of the time-averaged flow)")


def _get(row, key, sub):
    item = row.get(key)
    return None if item is None else item.get(sub)


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
    ("min Kn_p stagnation", "knp_min", "min", 1, "{:.3g}"),
    ("T_p min [K]", "T", "min", 1, "{:.1f}"),
    ("T_p max [K]", "T", "max", 1, "{:.1f}"),
)


def value(row, key, sub):
    """One number of a row (None when not available)."""
    if key is None:
        return row["t"]
    v = row.get(key) if sub is None else _get(row, key, sub)
    if isinstance(v, float) and not math.isfinite(v):
        return None         # never reported as a number (see the notes)
    return v


def series(analysis, key, sub):
    """(t, value) arrays over the times where the value is available."""
    pts = [(r["t"], value(r, key, sub)) for r in analysis["rows"]]
    pts = [(t, v) for t, v in pts if v is not None]
    return np.array(pts).reshape(-1, 2)


def last(analysis, key, sub):
    """(time, value) at the last time where it is available, or None."""
    for r in reversed(analysis["rows"]):
        v = value(r, key, sub)
        if v is not None:
            return r["time"], v
    return None


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
    ]


# -------------------------------------------------------------- plots ----

def _plt():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


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


def nearest_row(analysis, t):
    rows = analysis["rows"]
    if not rows:
        return None
    return min(rows, key=lambda r: abs(r["t"] - t))


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
    plt = _plt()
    os.makedirs(output, exist_ok=True)
    rows = pick_times(analysis, wanted)
    s = analysis["settings"]
    written = []

    def save(fig, name):
        fig.savefig(os.path.join(output, name), dpi=110)
        plt.close(fig)
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


# ------------------------------------------------------------ reports ----

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
    plt = _plt()
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
        fig.savefig(os.path.join(output, name), dpi=110)
        plt.close(fig)
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


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
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
        report(args)
    except (OSError, KeyError, ValueError, RuntimeError) as error:
        sys.exit(f"psi: {error}")


def report(args):
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
