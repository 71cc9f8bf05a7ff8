#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Speed-accuracy study of a scene (doc/speed-accuracy.md): runs the scene
over a grid of settings, measures each run's CPU time and observables,
computes their errors against the scene's reference run, and writes a
CSV, a Pareto picture (error against cost, the front marked) and a
markdown report.

    . etc/bashrc && bench/tradeoff/tradeoff.py SCENE|all [--quick] [--seeds N] [--doc]

Output in build/bench/tradeoff/<scene>/: tradeoff.csv, tradeoff.png,
tradeoff.md; --doc also puts the report and the picture
(doc/speed-accuracy-<scene>.png) into doc/speed-accuracy.md, between the
scene's markers.  Scenes so far:

erosionBox (tutorials/psi/regolithErosionBox, doc/physics.md#erosion-box)
    Reference: DEM with contacts resolved in t_c/50 steps (Berger's
    setting; the contacts' restitution and duration are within 0.02 % of
    the analytic ones there, validation/demContacts).  Settings: DEM at
    t_c/20 and t_c/10, springs 10 and 100 times softer, collisionless DEM,
    NTC hard spheres, MPPIC, the hybrid.  Each seed is its own settled
    bed (rmf.erosion bed --seed N), shared by its settings; the errors
    are taken against the reference of the same seed, and the spread over
    the seeds is the error bar.  Observables over the plume's T seconds:
      rate   overall erosion rate N_e(T)/T, relative error;
      curve  the cumulative erosion N_e(t) against the reference's on a
             1 ms grid: RMS difference over N_e,ref(T);
      fcn    the fractional collision number's plateau, relative error
             (DEM settings only: the parcel models resolve no contacts).
    Cost: the least CPU time over the seeds of the plume's run (the
    solver's ExecutionTime), over the reference's least; the settle is
    shared and not counted.  A run that stops with a FatalError (a
    setting past its stability limit) is reported as failed, with the
    time and the error's first line, and has no errors; the setting's
    cost is that of its finished runs.
    Full size: 0.2 s of plume, 3 seeds (15 minutes); --quick: 0.05 s of
    plume, 1 seed (2.5 minutes).

dustCloudStream (tutorials/coupling/dustCloudStream)
    Reference: analytic.  The grains are 0.5 um in an argon stream whose
    mean free path is 3800 grain diameters, so the free-molecular drag and
    heat of a fully accommodating sphere (doc/physics.md#one-way) are the
    physics; integrated by RK4 in the nominal stream from rest at T_0
    (rmf.kinetic.analytic_grain).  Settings: each interphaseCoupling type
    (none, oneWay, twoWayDirect, twoWayIndirect, adaptive, Loth) at the
    tutorial's gas weight and step; oneWay with the gas weight halved,
    doubled and quadrupled, and the step doubled and quintupled.  The
    seed is the gas's (both DSMC dictionaries); the grains start in the
    same places.  Observables at the end:
      U        the parcels' mean velocity along the stream, relative error;
      heating  their mean temperature rise T_p - T_0, relative error.
    Cost: least CPU time over the seeds, over the oneWay runs' least.
    Full size: 0.5 ms, 3 seeds (12 minutes); --quick: 0.1 ms, 1 seed
    (2 minutes).

snider (tutorials/solids/sniderSedimentation, doc/physics.md#snider)
    The narrow column (rmf.snider.narrow_column: 4 x 4 of the tutorial's
    cells, its fill and parcel weight).  Reference: analytic, the ideal
    settling (rmf.snider.free_fall_bed: free fall onto a bed that packs
    at alpha_cp on arrival).  Settings, one change at a time from the
    tutorial's: twoSided's predictMean, explicit and implicit packing,
    basic and dual averaging, parcel weight x 4 and x 16, deltaT x 1/2
    and x 2, cells x 1/2 and x 2 in each direction.  The seed is the initial positions'.  Errors:
    alpha(z) of the parcels on the tutorial's 40 slabs (the same for
    every mesh), RMS of the difference from the ideal's over alpha_cp,
    at each of 0.1, 0.15, 0.2 and 0.6 s (t0.1 ...) and over all
    (profile); the kinematics: fall, RMS over 0.05, 0.1 and 0.15 s of
    the suspension's mean U_z against -g t (rmf.snider.free_fall),
    relative; front, RMS over 0.1 and 0.15 s of the bed surface's height
    (where alpha(z) falls through (alpha0 + alpha_cp)/2) against the ideal
    front, relative.  Cost: least CPU time over the seeds over the tutorial
    setting's least.  Full size: 0.6 s, 3 seeds (10 minutes); --quick:
    0.2 s, 1 seed (1.5 minutes).

apolloPSI (tutorials/psi/apolloScaledPSI, demo, serial): bench/tradeoff/apollo.py
    Reference: the finest affordable run, W_g and deltaT halved.
    Settings: the coupling types, the grain models on the same dust, the
    gas and parcel weights, the step, the mesh.  Errors: surface drop on
    the axis, shock standoff, ejecta speed and angle, max alpha.  Full
    size: 60 us, --seeds 2 (30 minutes); --quick: 20 us, 6 settings, 1
    seed (3 minutes).

apolloResolved (tutorials/psi/apolloScaledPSI, resolved settings, hybrid,
    2 ranks): bench/tradeoff/apollo.py
    Reference: the main job's resolved settings.  Settings: the crater
    settings, no esBGK, upstream's NTC majorant, the gas weight doubled.
    Errors as apolloPSI's.  Full size: 60 us, --seeds 2 (about an hour);
    --quick: the reference and the crater settings, 1 seed.

denseGas (a nitrogen layer between a cold surface and a hot, moving
    wall: rmf.channel): bench/tradeoff/denseGas.py
    Reference: NTC at a step of a tenth of the mean collision time.
    Settings: ES-BGK at that step; NTC with upstream's majorant, NTC
    sub-stepped and ES-BGK at steps of 1 to 45 mean collision times.
    Errors: the surface's shear, heat flux and pressure, the gas's
    temperature and slip on it.  Full size: Kn 0.02, --seeds 2;
    --quick: Kn 0.05, steps 1 and 20, 1 seed.
"""

import argparse
import math
import os
import re
import shutil
import subprocess
import time

import numpy as np

from rmf import erosion, foam, grainseries, kinetic, snider
from rmf.bench import OUT, TARGET, cpu_time, curve_error, relative_error, write_outputs

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.path.dirname(os.path.dirname(HERE))


# ---------------------------------------------------------------------------
# Scene: the regolith erosion box

EROSION_SETTINGS = [
    ("base", "DEM, t_c/50 (reference)"),
    ("steps20", "DEM, t_c/20"),
    ("steps10", "DEM, t_c/10"),
    ("soft10", "DEM, k/10"),
    ("soft100", "DEM, k/100"),
    ("collisionless", "DEM, collisionless"),
    ("ntc", "NTC hard spheres"),
    ("mppic", "MPPIC"),
    ("hybrid", "MPPIC + NTC"),
]


def fatal_error(log):
    """'t = T s: first line' (80 characters at most) of the FatalError
    that stopped a solver's run, or None."""
    with open(log) as f:
        text = f.read()
    m = re.search(r"--> FOAM FATAL (?:IO )?ERROR[^\n]*\n\s*([^\n]+)", text)
    if not m:
        return None
    times = re.findall(r"^Time = (\S+)", text[:m.start()], re.M)
    first = m.group(1).strip().split(" at (")[0]
    first = first if len(first) <= 80 else first[:77] + "..."
    return f"t = {times[-1] if times else '?'} s: {first}"


def erosion_box(quick, seeds):
    plume = 0.05 if quick else 0.2
    tutorial = os.path.join(PROJECT, "tutorials", "psi", "regolithErosionBox")
    out = os.path.join(OUT, "erosionBox")
    os.makedirs(out, exist_ok=True)
    grid = np.linspace(0, plume, int(round(plume/1e-3)) + 1)
    rows = []
    for seed in range(1, seeds + 1):
        case = os.path.join(out, f"seed{seed}")
        if os.path.exists(case):
            shutil.rmtree(case)
        shutil.copytree(tutorial, case,
                        ignore=shutil.ignore_patterns("runs", "__pycache__", "*.py"))
        if seed != 1:
            erosion.write_bed(case, seed)
        series = {}
        for name, label in EROSION_SETTINGS:
            start = time.time()
            done = subprocess.run(["./Allrun", "-variant", name, "-plume", str(plume)],
                                  cwd=case, stdout=subprocess.DEVNULL).returncode == 0
            wall = time.time() - start
            run = os.path.join(case, "runs", name)
            log = os.path.join(run, "log.rarefiedMultiphaseFoam")
            failed = None if done else fatal_error(log)
            if failed is None and not done:
                raise RuntimeError(f"{case}: Allrun -variant {name} failed")
            row = {"setting": name, "label": label, "seed": seed, "cpu": cpu_time(log),
                   "wall": round(wall, 2), "failed": failed or ""}
            if failed:
                row.update({"Ne": float("nan"), "rateValue": float("nan"),
                            "fcnValue": float("nan")})
                print(f"seed {seed} {name}: failed, {failed}", flush=True)
            else:
                s = erosion.read(run)
                series[name] = s
                row.update({"Ne": float(s["erosionNumber"][-1]),
                            "rateValue": float(s["erosionNumber"][-1])/plume,
                            "fcnValue": erosion.figures(s)["fcnPlateau"]})
                print(f"seed {seed} {name}: N_e {row['Ne']:.0f}, CPU {row['cpu']:.1f} s",
                      flush=True)
            rows.append(row)
        ref = next(r for r in rows if r["seed"] == seed and r["setting"] == "base")
        sr = series["base"]
        for r in rows:
            if r["seed"] != seed:
                continue
            r["cost"] = r["cpu"]/ref["cpu"]
            if r["failed"]:
                r["rate"] = r["curve"] = r["fcn"] = float("nan")
                continue
            s = series[r["setting"]]
            r["rate"] = relative_error(r["rateValue"], ref["rateValue"])
            r["curve"] = curve_error(s["time"] - s["time"][0], s["erosionNumber"],
                                     sr["time"] - sr["time"][0], sr["erosionNumber"], grid)
            r["fcn"] = relative_error(r["fcnValue"], ref["fcnValue"])

    refs = np.array([r["rateValue"] for r in rows if r["setting"] == "base"])
    noise = (f"the reference's rate over the {seeds} seeds: "
             f"{refs.mean():.0f} ± {refs.std(ddof=1):.0f} grains/s"
             if seeds > 1 else "one seed: no noise estimate (use --seeds 3)")
    note = (f"Regolith erosion box, {plume} s of plume, {seeds} seed(s) ({noise}). "
            "Reference: DEM with contact steps of t_c/50.  Errors: rate = overall "
            "erosion rate N_e(T)/T; curve = RMS of N_e(t) minus the reference's over "
            "N_e,ref(T); fcn = fractional collision number's plateau (DEM only).  "
            "Cost: CPU time of the plume's run over the reference's.")
    return write_outputs("erosionBox", rows, ["curve", "rate", "fcn"], "curve", note)


# ---------------------------------------------------------------------------
# Scene: dustCloudStream, the coupling types against the analytic
# free-molecular drag and heat

STREAM_SETTINGS = [
    # name, label, interphaseCoupling, gas weight factor, time step factor
    ("oneWay", "one-way, free-molecular (cost base)", "oneWay", 1, 1),
    ("none", "no coupling", "none", 1, 1),
    ("twoWayDirect", "two-way, direct", "twoWayDirect", 1, 1),
    ("twoWayIndirect", "two-way, indirect", "twoWayIndirect", 1, 1),
    ("adaptive", "adaptive (free-molecular here)", "adaptive", 1, 1),
    ("Loth", "Loth drag, Nusselt heat", "Loth", 1, 1),
    ("weightHalf", "one-way, W_g x 1/2 (40 per cell)", "oneWay", 0.5, 1),
    ("weight2", "one-way, W_g x 2 (10 per cell)", "oneWay", 2, 1),
    ("weight4", "one-way, W_g x 4 (5 per cell)", "oneWay", 4, 1),
    ("dt2", "one-way, deltaT x 2", "oneWay", 1, 2),
    ("dt5", "one-way, deltaT x 5 (about 2 mean collision times)", "oneWay", 1, 5),
]


def dust_cloud_stream(quick, seeds):
    steps = 100 if quick else 500
    tutorial = os.path.join(PROJECT, "tutorials", "coupling", "dustCloudStream")
    out = os.path.join(OUT, "dustCloudStream")
    os.makedirs(out, exist_ok=True)
    # The reference at the end, the same for every run (the stream and the
    # grains are the tutorial's in every setting)
    t_end = steps*float(foam.get_entry(tutorial, "system/controlDict", "deltaT"))
    gas, grain = kinetic.stream_case_data(tutorial)
    v_ref, T_ref = kinetic.analytic_grain(gas, grain, t_end)
    rows = []
    for seed in range(1, seeds + 1):
        for name, label, coupling, weight, step in STREAM_SETTINGS:
            case = os.path.join(out, f"seed{seed}", name)
            foam.copy_setup(tutorial, case)
            shutil.copy(os.path.join(tutorial, "Allrun"), case)
            dt = float(foam.get_entry(case, "system/controlDict", "deltaT"))*step
            w = float(foam.get_entry(case, "constant/dsmcProperties",
                                     "nEquivalentParticles"))*weight
            foam.set_entry(case, "system/controlDict", "deltaT", f"{dt:.6g}")
            foam.set_entry(case, "system/controlDict", "endTime", f"{t_end:.6g}")
            foam.set_entry(case, "system/controlDict", "writeInterval",
                           int(round(t_end/dt)))
            foam.set_entry(case, "constant/dsmcProperties", "nEquivalentParticles",
                           f"{w:.6g}")
            for d in ("constant/dsmcProperties", "system/dsmcInitialiseDict"):
                foam.set_entry(case, d, "randomSeed", seed)
            subprocess.run(["./Allrun", coupling], cwd=case, check=True,
                           stdout=subprocess.DEVNULL)
            series = grainseries.series(case)
            t, n, ux, speed, T = series[-1]
            if abs(t/t_end - 1) > 1e-9:
                raise RuntimeError(f"{case}: last written time {t}, not {t_end}")
            rows.append({"setting": name, "label": label, "seed": seed,
                         "cpu": cpu_time(os.path.join(case, "log.rarefiedMultiphaseFoam")),
                         "time": t, "parcels": int(n), "Ux": ux, "Tp": T,
                         "UxRef": v_ref, "TpRef": T_ref,
                         "U": relative_error(ux, v_ref),
                         "heating": relative_error(T - grain["T0"], T_ref - grain["T0"])})
            print(f"seed {seed} {name}: U_x {ux:.4f} (analytic {v_ref:.4f}) m/s, T_p {T:.3f}"
                  f" ({T_ref:.3f}) K, CPU {rows[-1]['cpu']:.1f} s", flush=True)
        base = next(r for r in rows if r["seed"] == seed and r["setting"] == "oneWay")
        for r in rows:
            if r["seed"] == seed:
                r["cost"] = r["cpu"]/base["cpu"]

    note = (f"dustCloudStream, {1e3*t_end:g} ms of the argon stream, {seeds} seed(s) of "
            f"the gas. Reference: the analytic free-molecular drag and heat of a grain "
            f"from rest in the nominal stream (U_x {v_ref:.3f} m/s, T_p "
            f"{T_ref:.2f} K at {1e3*t_end:g} ms).  Errors: U = the parcels' "
            "mean velocity along the stream; heating = their mean temperature rise "
            "T_p - T_0.  Cost: least CPU time over the seeds over the oneWay runs' "
            "least (the base, not a reference: the reference is analytic).")
    return write_outputs("dustCloudStream", rows, ["U", "heating"], "U", note,
                         judged=("U", "heating"), cost_label="oneWay's", base="oneWay")


# ---------------------------------------------------------------------------
# Scene: Snider sedimentation against the ideal settling's kinematics

SNIDER_CELLS = 4            # the narrow column: 4 x 4 of the tutorial's cells
SNIDER_SLABS = 40           # alpha(z) on the tutorial's 7.5 mm layers
SNIDER_SETTINGS = [
    # name, label, {packing, averaging, weight, dt, mesh}: factors of the
    # tutorial's parcel weight, step and cells per direction
    ("base", "twoSided, cachedDual, W, 1 ms, 4 x 4 x 40 cells (the tutorial's)", {}),
    ("predicted", "twoSided with predictMean", {"predictMean": True}),
    ("explicit", "v1912's explicit packing", {"packing": "explicit"}),
    ("implicit", "v1912's implicit packing (eps 1e-2)", {"packing": "implicit"}),
    ("basic", "basic averaging", {"averaging": "basic"}),
    ("dual", "dual averaging (volumes recomputed)", {"averaging": "dual"}),
    ("weight4", "parcel weight W x 4", {"weight": 4}),
    ("weight16", "parcel weight W x 16", {"weight": 16}),
    ("dtHalf", "deltaT x 1/2", {"dt": 0.5}),
    ("dt2", "deltaT x 2", {"dt": 2}),
    ("meshHalf", "mesh x 1/2 (2 x 2 x 20 cells)", {"mesh": 0.5}),
    ("mesh2", "mesh x 2 (8 x 8 x 80 cells)", {"mesh": 2}),
]


def snider_case(dst, change, seed, end):
    """The narrow Snider column with one setting changed; returns (case,
    side)."""
    case, side = snider.narrow_column(dst, SNIDER_CELLS, change.get("mesh", 1))
    init, props, control = ("system/grainsInitialiseDict", "constant/grainsProperties",
                            "system/controlDict")
    foam.set_entry(case, init, "randomSeed", seed)
    foam.set_entry(case, control, "endTime", end)
    if "packing" in change:
        foam.set_entry(case, props, "subModels/packingModel", change["packing"])
    if "predictMean" in change:
        foam.set_entry(case, props, "subModels/twoSidedCoeffs/predictMean", "true")
    if "averaging" in change:
        foam.set_entry(case, props, "solution/averagingMethod", change["averaging"])
    if "weight" in change:
        k = change["weight"]
        n = int(foam.get_entry(case, init, "regions/column/nParcels"))
        w = float(foam.get_entry(case, init, "regions/column/nParticle"))
        foam.set_entry(case, init, "regions/column/nParcels", round(n/k))
        foam.set_entry(case, init, "regions/column/nParticle", f"{w*k:g}")
    if "dt" in change:
        dt = float(foam.get_entry(case, control, "deltaT"))*change["dt"]
        foam.set_entry(case, control, "deltaT", f"{dt:g}")
    return case, side


def snider_scene(quick, seeds):
    end = 0.2 if quick else 0.6
    times = [t for t in snider.TIMES if float(t) <= end + 1e-9]
    out = os.path.join(OUT, "snider")
    os.makedirs(out, exist_ok=True)
    rows, floors = [], {}
    for seed in range(1, seeds + 1):
        for name, label, change in SNIDER_SETTINGS:
            case, side = snider_case(os.path.join(out, f"seed{seed}", name), change, seed, end)
            for app in ("blockMesh", "rarefiedMultiphaseInitialise", "rarefiedMultiphaseFoam"):
                foam.run(case, app)
            height = float(foam.get_entry(case, "system/grainsInitialiseDict",
                                          "regions/column/max").strip("()").split()[2])
            edges = np.linspace(0, height, SNIDER_SLABS + 1)
            area = side*side
            alpha0 = float(snider.parcel_profile(case, "0", edges, area).mean())
            row = {"setting": name, "label": label, "seed": seed,
                   "cpu": cpu_time(os.path.join(case, "log.rarefiedMultiphaseFoam")),
                   "alpha0": alpha0, "parcels": snider.n_parcels(case, "0")}
            squares = []
            for t in times:
                a = snider.parcel_profile(case, t, edges, area)
                ideal, _ = snider.free_fall_bed(float(t), edges, alpha0, height)
                squares.append(np.mean((a - ideal)**2))
                row["t" + t] = float(np.sqrt(squares[-1]))/snider.ALPHA_PACKED
            row["profile"] = float(np.sqrt(np.mean(squares)))/snider.ALPHA_PACKED
            # The kinematics: the suspension's fall and the bed front
            fall = snider.free_fall(case, alpha0=alpha0, height=height)
            row["fall"] = float(np.sqrt(np.mean([e*e for e, _, _ in fall.values()])))
            centres = 0.5*(edges[:-1] + edges[1:])
            fronts = []
            for t in ("0.1", "0.15"):
                _, ideal_front = snider.free_fall_bed(float(t), edges, alpha0, height)
                # (through the mean of alpha0 and alpha_cp: alpha_cp/2 is
                # the suspension's own alpha)
                surface = snider.falls_through(
                    centres, snider.parcel_profile(case, t, edges, area),
                    0.5*(alpha0 + snider.ALPHA_PACKED))
                fronts.append((surface - ideal_front)/ideal_front)
            row["front"] = float(np.sqrt(np.mean(np.square(fronts))))
            # The noise floor of the measure in a packed slab: the Poisson
            # scatter of its parcel count (independent of the model)
            v_parcel = float(np.mean(snider.parcel_volumes(case, "0")))
            slab = snider.ALPHA_PACKED*area*(edges[1] - edges[0])/v_parcel
            floors[name] = 1/math.sqrt(slab)
            rows.append(row)
            print(f"seed {seed} {name}: alpha(z) error {100*row['profile']:.1f} % ("
                  + ", ".join(f"{t} s {100*row['t' + t]:.1f} %" for t in times)
                  + f"), fall {100*row['fall']:.1f} %, front {100*row['front']:.1f} %"
                  + f", CPU {row['cpu']:.1f} s", flush=True)
        base = next(r for r in rows if r["seed"] == seed and r["setting"] == "base")
        for r in rows:
            if r["seed"] == seed:
                r["cost"] = r["cpu"]/base["cpu"]

    errors = ["profile"] + ["t" + t for t in times] + ["fall", "front"]
    note = (f"Snider sedimentation, the narrow column ({SNIDER_CELLS} x {SNIDER_CELLS} of "
            f"the tutorial's cells, its fill and parcel weight), {end:g} s, {seeds} seed(s) of "
            "the initial positions. Reference: the ideal settling (free fall onto a bed "
            "that packs at alpha_cp on arrival; rmf.snider.free_fall_bed).  Errors: RMS over "
            f"the {SNIDER_SLABS} slabs of 7.5 mm of the parcels' alpha(z) minus the "
            "ideal's, over alpha_cp, at each time (t0.1 ...) and over all (profile); "
            "fall: RMS over 0.05, 0.1 and 0.15 s of the suspension's mean U_z (two "
            "layers clear of the ideal front and top) against -g t, relative; front: "
            "RMS over 0.1 and 0.15 s of the bed surface (alpha through (alpha0 + "
            "alpha_cp)/2) against the ideal front, relative.  "
            "Noise floor: a packed slab's Poisson scatter 1/sqrt(N) is "
            f"{100*floors['base']:.1f} % at the tutorial's weight, "
            f"{100*floors['weight16']:.1f} % at W x 16.  "
            "Cost: least CPU time over the seeds over the base's least.")
    return write_outputs("snider", rows, errors, "profile", note,
                         judged=tuple(errors), cost_label="the tutorial setting's")


def dense_gas(quick, seeds):
    """The gas models at long steps on a dense layer: bench/tradeoff/denseGas.py."""
    import denseGas
    return write_outputs("denseGas", **denseGas.study(quick, seeds))


def apollo_psi(quick, seeds):
    """The scaled Apollo PSI scene: bench/tradeoff/apollo.py."""
    import apollo
    return write_outputs("apolloPSI", **apollo.study(quick, seeds))


def apollo_resolved(quick, seeds):
    """The scaled Apollo PSI on the resolved main job: bench/tradeoff/apollo.py."""
    import apollo
    return write_outputs("apolloResolved", **apollo.resolved_study(quick, seeds))


SCENES = {"erosionBox": erosion_box, "dustCloudStream": dust_cloud_stream,
          "snider": snider_scene, "apolloPSI": apollo_psi, "denseGas": dense_gas,
          "apolloResolved": apollo_resolved}


def to_doc(scene):
    """The scene's report and picture into doc/speed-accuracy.md, between
    <!-- tradeoff:SCENE --> and <!-- /tradeoff:SCENE -->."""
    doc = os.path.join(PROJECT, "doc")
    png = f"speed-accuracy-{scene}.png"
    shutil.copy(os.path.join(OUT, scene, "tradeoff.png"), os.path.join(doc, png))
    with open(os.path.join(OUT, scene, "tradeoff.md")) as f:
        body = f.read().split("\n", 2)[2]       # without the report's title
    path = os.path.join(doc, "speed-accuracy.md")
    with open(path) as f:
        text = f.read()
    begin, end = f"<!-- tradeoff:{scene} -->", f"<!-- /tradeoff:{scene} -->"
    i, j = text.index(begin) + len(begin), text.index(end)
    text = text[:i] + f"\n{body.strip()}\n\n![{scene}]({png})\n" + text[j:]
    with open(path, "w") as f:
        f.write(text)
    print(path)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene", choices=sorted(SCENES) + ["all"],
                        help="a scene, or all of them one after another")
    parser.add_argument("--quick", action="store_true", help="the CI size")
    parser.add_argument("--seeds", type=int, help="seeds per setting (default 3, quick 1)")
    parser.add_argument("--doc", action="store_true",
                        help="write the result into doc/speed-accuracy.md")
    args = parser.parse_args(argv)
    seeds = args.seeds or (1 if args.quick else 3)
    for scene in SCENES if args.scene == "all" else [args.scene]:
        summary, best = SCENES[scene](args.quick, seeds)
        if args.doc:
            to_doc(scene)
        print(f"bench tradeoff {scene}: cheapest within {100*TARGET:.0f} %: "
              + (f"{best['setting']} at {best['cost']:.3f} of the base setting's CPU time"
                 if best else "none"))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
