# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Speed-accuracy scene apolloPSI of bench/tradeoff/tradeoff.py: the
scaled Apollo plume-surface interaction (tutorials/psi/apolloScaledPSI,
demo settings, serial), one setting changed at a time from a base.

Base: the demo with the stochastic grains (NTC hard spheres; the
variant whose dilute layer, alpha 2.5e-5, craters and ejects within the
demo's time), twoWayIndirect coupling averaged over 10 steps, ended at
END_FULL = 60 us (the demo's 100 us costs 2.5-4 min of CPU per run: too
many runs for the budget).  The first ejecta leave at about 50 us; the
surface drop on the axis is not monotone (seed 1: 0.38, 0.72, 0.87,
0.76, 0.67 mm at 20-60 us, 6-9 % of the axis annulus's grains gone).
Reference: the finest affordable run, the gas weight W_g and the step
deltaT halved together (twice the simulators per cell, half the cell
transit and collision time per step: the two DSMC resolutions; 3.1
times the base's CPU time at 60 us, 3.5 at 20 us).  The mesh is not
refined in it: finer cells need a smaller step again (the demo's
transit criterion) and the dust layer is 4 cells deep already.  Its
own noise is shown by its seeds (the note of the report gives each
observable's mean and spread over them;
measured 2026-12-03, seeds 1 and 2 at 60 us: drop 0.666 +- 0.024 mm,
standoff 3.16 +- 0.07 mm, ejecta 41 +- 4 m/s from 3-5 parcels, angle
2.4 +- 0.4 degrees, max alpha 1.2e-4 +- 0.2e-4: a single-seed error
carries about 5 % of noise in the drop and 3 % in the standoff).

Settings (each one change from the base): coupling oneWay (the gas does
not see the grains), twoWayDirect, twoWayIndirect averaged over 2 steps;
grains MPPIC and hybrid on the base's dust (alpha 2.5e-5, 15 000
parcels, the layer's radius 45 mm: settings/demo's MPPICDust and
hybridDust set to stochasticDust, so the grain model is the only
change; below the hybrid's alphaSwitch 0.01 it collides by NTC
everywhere, with MPPIC's averaging); the gas weight halved and doubled;
parcels four times heavier (3750 parcels; the crater's annuli then
merge over wider radii, rmf.psi: 100 parcels each); the step halved and
doubled (doubled, simulators cross up to 0.44 mm per step against
0.25 mm cells: the DSMC transit criterion broken, part of the trade);
the mesh halved in each direction (nAxial, nRadialNozzle, nRadialOuter;
the 1 mm layer then gets 2 cells of 0.5 mm instead of 4).

Seeds: every randomSeed of the case (the gas, constant/dsmcProperties;
the grains' fill, system/grainsInitialiseDict; the grain cloud and the
coupling, constant/grainsProperties; NTC, settings/stochastic and
settings/hybrid) set to the seed; the gas starts empty, so
system/dsmcInitialiseDict draws nothing.  The base and the reference
run every seed (1..seeds); the other settings seed 1 only (the budget),
so their errors carry the noise shown by the base's spread.  Each run's
errors are taken against the reference run of the same seed (same
layer: the fill does not depend on the gas's weight or step; the gas's
streams differ, so the pairing removes only the fill's noise).

Observables (rmf.psi.observables.analyse of each run), relative errors:
  drop      the surface drop on the axis at the end time (rmf.psi's
            crater: the axis annulus's surface below the initial top;
            main error: how far the jet digs, what PSI is about);
  standoff  the shock standoff on the axis, mean over the writes in the
            last third of the run (batch means of the gas density; the
            shock has formed by 20 us and creeps outward slowly);
  ejecta    the ejecta's mean speed at the end (real-grain weighted;
            few parcels at 60 us: noisy);
  angle     their mass-weighted mean ejection angle at the end;
  alpha     the largest alpha.grains of a cell at the end.
An observable a run does not define (no ejecta, no shock found) is nan:
the report shows "-", and a setting with a nan in a judged error is not
recommended.  Judged: drop and standoff.  The ejecta are 2-17 parcels at
60 us in most settings (their mean speed spreads 10 % between the
reference's seeds, 27 +- 22 % between base and reference), and max
alpha is a one-cell maximum (18 % between seeds): reported, not judged.
(Caveat: oneWay passes the judged pair but throws 182 ejecta parcels at
twice the speed: without the gas's loss to the grains the spray is
wrong.)

Cost: the solver's CPU time (the last ExecutionTime of
log.rarefiedMultiphaseFoam), least over the seeds, over the base's
least.  Runs are serial, one at a time; blockMesh and the initialiser
(about 2 s) are not counted.  Allrun is run with RMF_PYTHON=true: its
pictures (rmf.psi's and scene.py's, not needed here) are skipped.

Full size: END_FULL, seeds 1 and 2 of base and reference: 29 min of CPU
on one core (measured 2026-12-03: 1760 s; the base 77-88 s, the
reference 237-262 s); the driver's default of 3 seeds adds about 5.5
min (`--seeds 2` keeps the budget).  --quick: QUICK settings at
END_QUICK, one seed: 3 min (182 s).  The CPU times of equal work
differed by up to 15 % between runs here (the base's seeds 77 and 88 s;
another job on the other core): cost ratios within that are not
resolved.
"""

import os
import shutil
import subprocess

import numpy as np

from rmf import foam
from rmf.bench import OUT, against_reference, cpu_time, spread

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.path.dirname(os.path.dirname(HERE))
TUTORIAL = os.path.join(PROJECT, "tutorials", "psi", "apolloScaledPSI")

END_FULL = 6e-5                 # s; the base costs about 80 s of CPU
END_QUICK = 2e-5                # s; the shock stands by then
WRITE_FULL = 1e-5               # s; batch means of the gas
WRITE_QUICK = 5e-6
AVERAGE_FROM = 2/3              # standoff: mean over the writes after this fraction
MESH_KEYS = ("nAxial", "nRadialNozzle", "nRadialOuter")

SETTINGS = [
    # name, label, changes from the base: variant, coupling, averagingSteps,
    # factors of the gas weight, the step, the parcel weight and the cells
    ("base", "stochastic, twoWayIndirect 10 steps (cost base)", {}),
    ("reference", "W_g x 1/2 and deltaT x 1/2 (reference)", {"weight": 0.5, "step": 0.5}),
    ("oneWay", "one-way coupling", {"coupling": "oneWay"}),
    ("twoWayDirect", "two-way, direct", {"coupling": "twoWayDirect"}),
    ("indirect2", "twoWayIndirect averaged over 2 steps", {"averaging": 2}),
    ("MPPIC", "MPPIC grains, same dust", {"variant": "MPPIC"}),
    ("hybrid", "hybrid grains, same dust", {"variant": "hybrid"}),
    ("weightHalf", "W_g x 1/2", {"weight": 0.5}),
    ("weight2", "W_g x 2", {"weight": 2}),
    ("parcels4", "parcel weight x 4 (3750 parcels)", {"parcels": 4}),
    ("dtHalf", "deltaT x 1/2", {"step": 0.5}),
    ("dt2", "deltaT x 2 (transit criterion broken)", {"step": 2}),
    ("meshHalf", "cells x 1/2 each way (layer 2 cells deep)", {"mesh": 0.5}),
]
QUICK = ("base", "reference", "oneWay", "MPPIC", "dt2", "meshHalf")
MULTI_SEED = ("base", "reference")      # the others run seed 1 only

ERRORS = ("drop", "standoff", "ejecta", "angle", "alpha")
MAIN_ERROR = "drop"
JUDGED = ("drop", "standoff")

# Files holding the case's randomSeed entries (every stream; see above)
SEEDED = ("constant/dsmcProperties", "constant/grainsProperties",
          "system/grainsInitialiseDict", "settings/stochastic", "settings/hybrid")


def copy_seeded(case, seed):
    """A copy of the tutorial in case (its 0, constant, system and settings
    and Allrun) with every randomSeed set to seed."""
    foam.copy_setup(TUTORIAL, case)
    shutil.copytree(os.path.join(TUTORIAL, "settings"), os.path.join(case, "settings"))
    shutil.copy(os.path.join(TUTORIAL, "Allrun"), case)
    for path in SEEDED:
        foam.substitute(os.path.join(case, path), r"(randomSeed\s+)\d+;", rf"\g<1>{seed};")
    return case


def prepare(case, changes, seed, end, write):
    """The tutorial copied and seeded (copy_seeded) with the changes of a
    setting."""
    copy_seeded(case, seed)
    demo = "settings/demo"

    def get(key):
        return float(foam.get_entry(case, demo, key))

    dt = get("deltaT")*changes.get("step", 1)
    updates = {"deltaT": f"{dt:.6g}", "endTime": f"{end:.6g}", "writeInterval": f"{write:.6g}"}
    if "weight" in changes:
        updates["gasWeight"] = f"{get('gasWeight')*changes['weight']:.6g}"
    if "mesh" in changes:
        for key in MESH_KEYS:
            updates[key] = int(round(get(key)*changes["mesh"]))
    base_parcels = get("stochasticDust/nParcels")
    parcels = int(round(base_parcels/changes.get("parcels", 1)))
    variant = changes.get("variant", "stochastic")
    # The base's dust for every variant (foamDictionary -set writes
    # hybridDust's $MPPICDust expanded: each set on its own)
    updates[f"{variant}Dust/alpha0"] = foam.get_entry(case, demo, "stochasticDust/alpha0")
    updates[f"{variant}Dust/nParcels"] = parcels
    updates[f"{variant}LayerRadius"] = foam.get_entry(case, demo, "stochasticLayerRadius")
    for key, value in updates.items():
        foam.set_entry(case, demo, key, value)
    props = os.path.join(case, "constant", "grainsProperties")
    if "averaging" in changes:
        foam.substitute(props, r"(averagingSteps\s+)\d+;", rf"\g<1>{changes['averaging']};")
    coupling = changes.get("coupling")
    if coupling:
        foam.substitute(props, r"(interphaseCoupling\s+)twoWayIndirect;", rf"\g<1>{coupling};")
    if coupling == "twoWayDirect":      # its Coeffs know no averagingSteps
        foam.substitute(props, r"twoWayIndirectCoeffs", "twoWayDirectCoeffs")
        foam.substitute(props, r"\n\s*averagingSteps\s+\d+;[^\n]*", "")
    return case


def run(case, *options):
    """Allrun with options, without its pictures (RMF_PYTHON=true)."""
    env = dict(os.environ, RMF_PYTHON=shutil.which("true"))
    subprocess.run(["./Allrun", *options], cwd=case, env=env, check=True,
                   stdout=subprocess.DEVNULL)


def observe(case, end):
    """The scene's observables of a run (module docstring) and its notes."""
    from rmf.psi import observables as obs
    a = obs.analyse(case)
    rows = a["rows"]
    final = rows[-1]
    if abs(final["t"]/end - 1) > 1e-6:
        raise RuntimeError(f"{case}: last written time {final['time']}, not {end:g}")
    late = [obs.value(r, "shock", "standoff") for r in rows if r["t"] >= AVERAGE_FROM*end]
    late = [v for v in late if v is not None]

    def at_end(key, sub):
        v = obs.value(final, key, sub)
        return float("nan") if v is None else float(v)

    return {"dropValue": at_end("crater", "surface_drop"),
            "dropSigma": at_end("crater", "surface_drop_sigma"),
            "depthValue": at_end("crater", "max_depth"),
            "standoffValue": float(np.mean(late)) if late else float("nan"),
            "standoffWrites": len(late),
            "ejectaValue": at_end("speeds", "ejecta_mean"),
            "ejectaParcels": int(obs.value(final, "speeds", "ejecta") or 0),
            "angleValue": at_end("angles", "mean"),
            "alphaValue": at_end("alpha", "max")}


def record(case, name, label, seed, cpu, end):
    """A finished run's row (setting, seed, CPU time, observables), printed;
    the gas's simulators, not needed, are removed."""
    row = {"setting": name, "label": label, "seed": seed, "cpu": cpu}
    row.update(observe(case, end))
    for t in os.listdir(case):
        shutil.rmtree(os.path.join(case, t, "lagrangian", "dsmc"), ignore_errors=True)
    print(f"seed {seed} {name}: drop {1e3*row['dropValue']:.3f} mm, standoff "
          f"{1e3*row['standoffValue']:.3f} mm, ejecta {row['ejectaValue']:.3g} m/s "
          f"({row['ejectaParcels']} parcels), CPU {row['cpu']:.1f} s", flush=True)
    return row


def study(quick, seeds, names=None):
    """Runs the scene's settings (QUICK of them at END_QUICK with --quick,
    all at END_FULL otherwise, or those named; the base and the reference
    over seeds 1..seeds, the others seed 1) and returns the arguments of
    rmf.bench.write_outputs: dict(rows=rows, errors=[...], main_error=...,
    note=..., judged=(...), cost_label=..., base=...)."""
    end = END_QUICK if quick else END_FULL
    write = WRITE_QUICK if quick else WRITE_FULL
    out = os.path.join(OUT, "apolloPSI")
    os.makedirs(out, exist_ok=True)
    names = names or (QUICK if quick else [s[0] for s in SETTINGS])
    chosen = [s for s in SETTINGS if s[0] in names]
    rows = []
    for seed in range(1, seeds + 1):
        for name, label, changes in chosen:
            if seed > 1 and name not in MULTI_SEED:
                continue
            case = prepare(os.path.join(out, f"seed{seed}", name), changes, seed, end, write)
            run(case, "-variant", changes.get("variant", "stochastic"))
            rows.append(record(case, name, label, seed,
                               cpu_time(os.path.join(case, "log.rarefiedMultiphaseFoam")), end))
    refs = against_reference(rows, ERRORS, base="base")
    noise = "; ".join(f"{e} {spread(refs, e + 'Value')}" for e in ERRORS)
    note = (f"Scaled Apollo PSI (tutorials/psi/apolloScaledPSI, demo, serial), "
            f"{1e6*end:g} us, base and reference over {seeds} seed(s), the other "
            "settings seed 1.  Base: stochastic grains, twoWayIndirect over 10 steps.  "
            "Reference: W_g and deltaT halved together; its "
            f"values over the seeds (SI units, mean ± sd): {noise}.  Errors against the "
            "reference of the same seed: drop = surface drop on the axis at the end; "
            "standoff = shock standoff, mean of the writes from "
            f"{AVERAGE_FROM*1e6*end:.3g} us; "
            "ejecta = ejecta's mean speed at the end; angle = their mean ejection angle; "
            "alpha = largest alpha.grains (– : not defined, e.g. no ejecta).  Cost: the "
            "solver's CPU time over the base's.")
    return dict(rows=rows, errors=list(ERRORS), main_error=MAIN_ERROR, note=note,
                judged=JUDGED, cost_label="the base's", base="base")


# ---------------------------------------------------------------------------
# The PSI trade on the resolved main job (scene apolloResolved)

RESOLVED_END = 6e-5             # s; the main job's 100 us cost 14-16 min a run
RESOLVED_SETTINGS = [
    # name, label, changes: settings file, blocks of settings/resolved
    # dropped, factor of its gas weight
    ("reference", "resolved settings (the main job; reference)", {}),
    ("crater", "crater settings: W_g 5e10, upstream's NTC majorant", {"settings": "crater"}),
    ("subStepsOnly", "no esBGK: NTC sub-stepped in every cell", {"drop": ("esBGK",)}),
    ("upstreamNTC", "upstream's NTC majorant, no esBGK, W_g 8e9",
     {"drop": ("esBGK", "collisionSubSteps")}),
    ("weight2", "W_g x 2 (1.6e10)", {"weight": 2}),
]
RESOLVED_QUICK = ("reference", "crater")


def _segments_cpu(case):
    """The solver's CPU time over its segments (the main job re-balances at
    writes: log.rarefiedMultiphaseFoam, log...rebalance1, ...)."""
    logs = sorted(f for f in os.listdir(case) if f.startswith("log.rarefiedMultiphaseFoam"))
    return sum(cpu_time(os.path.join(case, f)) for f in logs)


def prepare_resolved(case, changes, seed, end):
    """The tutorial copied and seeded (copy_seeded) with a resolved-scene
    setting and the end time set."""
    copy_seeded(case, seed)
    foam.substitute(os.path.join(case, "settings", "crater"), r"(\nendTime\s+)[^;]+;",
                    rf"\g<1>{end:.6g};")
    resolved = os.path.join(case, "settings", "resolved")
    for block in changes.get("drop", ()):
        foam.substitute(resolved, rf"\n{block}\s*\{{[^}}]*\}}", "\n")
    if "weight" in changes:
        w = float(foam.get_entry(case, "settings/resolved", "gasWeight"))
        foam.substitute(resolved, r"(\ngasWeight\s+)[^;]+;",
                        rf"\g<1>{w*changes['weight']:.6g};")
    return case


def resolved_study(quick, seeds):
    """The PSI trade on the resolved main job: its settings (hybrid grains,
    2 ranks) at RESOLVED_END, one change at a time (RESOLVED_SETTINGS; with
    --quick the reference and the crater settings); the reference over
    seeds 1..seeds, the others seed 1; errors against the reference of the
    same seed.  Returns the arguments of rmf.bench.write_outputs."""
    out = os.path.join(OUT, "apolloResolved")
    os.makedirs(out, exist_ok=True)
    chosen = [s for s in RESOLVED_SETTINGS if not quick or s[0] in RESOLVED_QUICK]
    rows = []
    for seed in range(1, seeds + 1):
        for name, label, changes in chosen:
            if seed > 1 and name != "reference":
                continue
            case = prepare_resolved(os.path.join(out, f"seed{seed}", name), changes, seed,
                                    RESOLVED_END)
            run(case, "-settings", changes.get("settings", "resolved"), "-parallel")
            rows.append(record(case, name, label, seed, _segments_cpu(case), RESOLVED_END))
    refs = against_reference(rows, ERRORS)
    noise = "; ".join(f"{e} {spread(refs, e + 'Value')}" for e in ERRORS)
    note = (f"Scaled Apollo PSI on the resolved main job (tutorials/psi/apolloScaledPSI, "
            f"settings/resolved, hybrid grains, 2 ranks), {1e6*RESOLVED_END:g} us, the "
            f"reference over {seeds} seed(s), the other settings seed 1.  Reference: the "
            "resolved settings (W_g 8e9, NTC sub-stepped, ES-BGK above Lambda 20); its "
            f"values over the seeds (SI units, mean ± sd): {noise}.  Errors against the "
            "reference of the same seed, as the demo's study below.  Cost: the solver's "
            "CPU time (the master rank's, summed over the re-balanced segments) over the "
            "reference's.")
    return dict(rows=rows, errors=list(ERRORS), main_error=MAIN_ERROR, note=note,
                judged=JUDGED, cost_label="the reference's", base="reference")
