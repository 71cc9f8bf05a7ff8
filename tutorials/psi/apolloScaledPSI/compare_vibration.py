# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Rotation-only against vibration on (Allrun-vibration): what water's
vibrational modes change in the scene, from two runs of the same variant,
settings and seeds.

    /usr/bin/python3 compare_vibration.py ROTATION_CASE VIBRATION_CASE OUTPUT_DIR

Per written time from FROM on (the shock layer formed) and, in the last
column, their mean (the batch means of consecutive writes are independent
samples of the steady layer, so their spread gives a standard error):
- the shock standoff on the axis (rmf.psi);
- the gas in the stagnation region, the cells within GAP of the surface
  under the nozzle (r < nozzle radius), weighted by their number density
  (rhoNMean): the translational and overall temperature (computed as
  dsmcFields does, from the batch means; with vibration on the overall
  one includes the vibrational energy) and vibrationalT.gas;
- the heat flux into the surface under the nozzle (qMean on the wall,
  area-weighted);
- the grains' heating: their mean temperature rise from the initial 200 K
  (real-grain weighted), and the hottest parcel; these grow with time, so
  their last column is the value at the last time (the change between
  the runs there), not a mean.
Writes OUTPUT_DIR/summary.md and prints it.
"""

import os
import sys

import numpy as np

from rmf import foam
from rmf.psi import observables as obs

FROM = 40e-6            # [s]: the layer has formed (README.md)
GAP = 1e-3              # [m]: the cells next to the surface
T_GRAIN0 = 200.0        # [K]: the grains' initial temperature
K = 1.380649e-23        # Boltzmann [J/K]
GROWING = ("grains' mean heating [K]", "hottest grain [K]")


def weighted(values, weights):
    return float(np.average(values, weights=weights)) if weights.sum() > 0 else float("nan")


def gas_temperatures(case, time, n):
    """Translational, overall (with the internal energy and degrees of
    freedom, which include the vibration when it is on) and vibrational
    temperature per cell from the batch means, as dsmcFields computes the
    first two (it writes nothing while any cell is empty, as here)."""
    def mean(name):
        return obs.field(case, time, name + "Mean", n)
    rhoN, rhoM, mom = mean("rhoN"), mean("rhoM"), mean("momentum")
    thermal = mean("linearKE") - 0.5*(mom**2).sum(axis=1)/np.maximum(rhoM, 1e-300)
    occupied = rhoN > 1
    with np.errstate(divide="ignore", invalid="ignore"):
        T_tr = np.where(occupied, 2*thermal/(3*K*rhoN), 0)
        T_all = np.where(occupied, 2*(thermal + mean("internalE"))
                         / (K*(3*rhoN + mean("iDof"))), 0)
    T_vib = obs.field(case, time, "vibrationalT.gas", n)
    return {"translational T": T_tr, "overall T": T_all,
            "vibrational T": T_vib if T_vib is not None else np.full(n, np.nan)}


def surface_flux(case, time, radius):
    """Area-weighted wall heat flux [W/m^2] on the surface under the nozzle."""
    path = os.path.join(case, time, "qMean")
    if not os.path.exists(path):
        return float("nan")
    q = foam.read_patch_field(path, "surface")
    boundary = foam.read_boundary(case)["surface"]
    start, n = int(boundary["startFace"]), int(boundary["nFaces"])
    points = foam.read_points(case)
    faces = foam.read_faces(case, start, n)
    centres = np.array([points[f].mean(axis=0) for f in faces])
    # Planar polygons: half the norm of sum p_i x p_(i+1)
    areas = np.array([np.linalg.norm(np.cross(points[f], np.roll(points[f], -1, axis=0))
                                     .sum(axis=0))/2 for f in faces])
    inside = np.hypot(centres[:, 1], centres[:, 2]) < radius
    q = np.broadcast_to(q, (n,)) if np.ndim(q) == 0 else q
    return weighted(q[inside], areas[inside])


def observe(case):
    """Per time >= FROM: dict of the observables."""
    settings = obs.read_settings(case)
    cells = obs.mesh(case)
    near = (cells["x"] > settings["surface"] - GAP) & (cells["r"] < settings["nozzleRadius"])
    out = {}
    for t in foam.times(case):
        if float(t) < FROM - 1e-12:
            continue
        row = {}
        rho = obs.field(case, t, "rhoNMean", cells["n"])
        x, values = obs.axis_density(cells["x"], cells["r"], rho, settings)
        row["standoff [mm]"] = 1e3*(obs.shock_standoff(x, values, settings["surface"])
                                    ["standoff"] or float("nan"))
        for name, f in gas_temperatures(case, t, cells["n"]).items():
            row[f"{name} near the surface [K]"] = weighted(f[near], rho[near])
        row["surface heat flux under the nozzle [kW/m^2]"] = (
            1e-3*surface_flux(case, t, settings["nozzleRadius"]))
        p = obs.parcels(case, t)
        T = obs.temperatures(p)
        row[GROWING[0]] = T["mean"] - T_GRAIN0
        row[GROWING[1]] = T["max"]
        out[float(t)] = row
    return out


def main(rotation, vibration, output):
    runs = {"rotation only": observe(rotation), "vibration on": observe(vibration)}
    times = sorted(set(runs["rotation only"]) & set(runs["vibration on"]))
    names = list(runs["rotation only"][times[0]])
    lines = ["# apolloScaledPSI: rotation only against vibration on", "",
             f"Cases: `{rotation}` and `{vibration}`. Columns: the written times "
             f"(batch means since the previous write), then the mean over them "
             f"with its standard error (for the grains: the value at the last "
             f"time).", ""]
    head = "| observable | run | " + " | ".join(f"{1e6*t:g} us" for t in times) + " | mean |"
    lines += [head, "|" + "---|"*(len(times) + 3)]
    for name in names:
        means = {}
        growing = name in GROWING
        for label, rows in runs.items():
            v = np.array([rows[t][name] for t in times])
            ok = np.isfinite(v)
            if growing:
                m, se = v[-1], float("nan")
            else:
                m = v[ok].mean() if ok.any() else float("nan")
                se = (v[ok].std(ddof=1)/np.sqrt(ok.sum()) if ok.sum() > 1
                      else float("nan"))
            means[label] = (m, se)
            last = f"{m:.4g}" if growing else f"{m:.4g} ± {se:.2g}"
            lines.append(f"| {name} | {label} | " + " | ".join(f"{x:.4g}" for x in v)
                         + f" | {last} |")
        (a, sa), (b, sb) = means["rotation only"], means["vibration on"]
        error = "" if growing else f" ± {np.hypot(sa, sb):.2g}"
        lines.append(f"| {name} | change |" + " |"*len(times)
                     + f" {b - a:+.4g}{error} ({100*(b/a - 1):+.1f} %) |")
    text = "\n".join(lines) + "\n"
    os.makedirs(output, exist_ok=True)
    with open(os.path.join(output, "summary.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
