# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Plume-surface interaction observables: the computations
(doc/physics.md#apollo-psi), on a case or on arrays; rmf.psi re-exports them.

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
9. Validity of binary collisions (binary_validity): the real-grain
   fraction of the parcels in cells whose alpha.grains exceeds alphaValid
   (0.1, NTCHardSphere's default: above it a grain is no longer free
   between binary collisions, doc/physics.md#ntc), over all parcels.
10. Grains out of the free-molecular regime (transitional): the parcels in
   cells with 0 < Kn_p < KnSwitch (10, the adaptive coupling's default):
   their real-grain fraction and mean temperature.

Missing data (no parcels at a time, no gas fields at time 0, no Knp.grains)
gives None for that observable and a note saying why; summary.md lists
the notes and writes "n/a" in the tables, never NaN.
"""

import math
import os
import re
import subprocess

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
ALPHA_VALID = 0.1               # binary collisions valid below (NTCHardSphere)
KN_SWITCH = 10                  # Kn_p below which a grain is not free-molecular
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
    simulators: doc/physics.md#axisymmetric)."""
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


def binary_validity(p, alpha, alpha_valid=ALPHA_VALID):
    """Real-grain fraction of the parcels in cells above alpha_valid
    (module docstring, item 9): dict(fraction, parcels), None without
    parcels or alpha."""
    if p is None or alpha is None:
        return None
    above = alpha[p["cell"]] > alpha_valid
    return dict(fraction=float(p["n"][above].sum()/p["n"].sum()),
                parcels=int(above.sum()))


def transitional(p, knp, kn_switch=KN_SWITCH):
    """The grains in cells with 0 < Kn_p < kn_switch (module docstring,
    item 10): dict(fraction [real grains], parcels, T [their real-grain
    mean temperature, None when none or T not written]), None without
    parcels or Kn_p."""
    if p is None or knp is None:
        return None
    k = knp[p["cell"]]
    sel = (k > 0) & (k < kn_switch)
    T = None
    if sel.any() and p["T"] is not None:
        T = float(np.average(p["T"][sel], weights=p["n"][sel]))
    return dict(fraction=float(p["n"][sel].sum()/p["n"].sum()),
                parcels=int(sel.sum()), T=T)


# ----------------------------------------------------------- analysis ----

#: Number density above which a cell holds gas (gas_resolution) [1/m^3]
GAS_CELL = 1e21


def gas_resolution(simulators, n):
    """The gas's resolution in simulators per cell: over the cells whose
    number density n (rhoNMean) exceeds GAS_CELL, the median of the
    simulators per cell (dsmcRhoNMean, the same batch mean) and the shares
    below 10 and below 1; None without the fields."""
    if simulators is None or n is None:
        return None
    held = simulators[n > GAS_CELL]
    if not len(held):
        return None
    return dict(cells=int(len(held)), of=int(len(n)), median=float(np.median(held)),
                below10=float(np.mean(held < 10)), below1=float(np.mean(held < 1)))


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
        row["resolution"] = gas_resolution(field(case, t, "dsmcRhoNMean", cells["n"]),
                                           field(case, t, "rhoNMean", cells["n"]))
        alpha = field(case, t, "alpha." + CLOUD, cells["n"])
        row["alpha"] = max_alpha(alpha)
        row["validity"] = binary_validity(p, alpha)
        if row["alpha"] is None:
            notes.append(f"t = {t}: no alpha.{CLOUD}")
        knp, source = knp_cells(case, t, cells["n"], p)
        row["knp"] = knp
        row["knp_source"] = source
        row["transitional"] = transitional(p, knp)
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


# ------------------------------------------------ reading an analysis ----

def _get(row, key, sub):
    item = row.get(key)
    return None if item is None else item.get(sub)


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


def nearest_row(analysis, t):
    """The row of the time nearest to t, or None when there is none."""
    rows = analysis["rows"]
    if not rows:
        return None
    return min(rows, key=lambda r: abs(r["t"] - t))
