#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Cost of an MPPIC parcel-step of rarefiedMultiphaseFoam against stock MPPICFoam.

Case: tutorials/solids/sniderSedimentation (Snider's case 7: a closed box
0.138 x 0.138 x 0.3 m, 15 x 15 x 40 cells, walls on all sides; 162 232
parcels of 749 glass beads, d = 0.3 mm, rho = 2500 kg/m^3, at rest,
uniform at alpha = 0.3; g = (0 0 -9.8) m/s^2; dt = 1 ms), meshed
(blockMesh) and initialised (rarefiedMultiphaseInitialise) once.

The set-up is rmf.mppic's (shared with bench/memory; its docstring gives
it in full): both clouds get the same MPPIC submodels from one list;
ours runs the grains alone in vacuum, the stock solver with a practically
absent carrier (air at 1e-6 of the grains' density, at rest) whose
momentum and pressure it still solves each step, by design; MPPICFoam
injects the positions our initialiser wrote, so both start from the same
parcels.

Each repetition runs, serially and one after another, each on a fresh
copy from t = 0 for --steps steps: ours (cachedDual), ours (dual),
MPPICFoam.  Nothing is written during the runs (writeInterval beyond the
run), so no run pays for writing the parcels.  The cost per parcel-step
comes from each solver's own ExecutionTime (CPU) between the end of its
first step and its last, so start-up (mesh, parcels, the stock injection)
and the first step are left out:

    c = (ExecutionTime_N - ExecutionTime_1)/((N - 1) n_parcels)

Reported: c of each run per repetition (with the run's clock/CPU ratio
over the same steps, from ClockTime in whole seconds: well above 1 means
it competed for a core), the
minimum over the repetitions, and the ratios ours/MPPICFoam of the minima
(cachedDual, dual).  Target: cachedDual/MPPICFoam <= 0.5; above,
MISSES TARGET.  A run that fails, or ends with another number of parcels
than it started with, counts as failed (exit status 1); else exit 0.

Run from the project directory:

    . etc/bashrc && bench/mppic/bench.py [--steps N] [--repeat R]

Defaults: --steps 50 --repeat 2 (about 7 minutes).  Outputs under
build/bench/mppic/.
"""

import argparse
import os
import sys

from rmf import foam
from rmf.mppic import DT, N_PARTICLE, STOCK_TUTORIAL, prepare_ours, prepare_stock

BUILD = os.path.join(foam.PROJECT_DIR, "build", "bench", "mppic")

# (label, application, averagingMethod); the first is the target's
RUNS = (("ours cachedDual", "rarefiedMultiphaseFoam", "cachedDual"),
        ("ours dual", "rarefiedMultiphaseFoam", "dual"),
        ("MPPICFoam", "MPPICFoam", "dual"))
TARGET = 0.5


def parcel_cost(init, label, app, averaging, rep, steps, parcels):
    """CPU seconds per parcel-step of one run, and its clock/CPU ratio."""
    case = foam.copy_case(init, os.path.join(BUILD, f"{label.replace(' ', '-')}-{rep}"))
    if app == "rarefiedMultiphaseFoam":
        foam.set_entry(case, "constant/grainsProperties", "solution/averagingMethod",
                       averaging)
    log = foam.run(case, app)
    et = foam.execution_times(log)
    if len(et) != steps:
        raise RuntimeError(f"{log}: {len(et)} steps timed, expected {steps}")
    counts = foam.log_values(log, "Current number of parcels")
    if len(counts) < steps or counts[-1][0] != parcels:
        raise RuntimeError(f"{log}: ends with {counts[-1][0] if len(counts) else 0:g} "
                           f"parcels, expected {parcels}")
    clock = foam.execution_times(log, clock=True)
    cpu = et[-1] - et[0]
    ratio = (clock[-1] - clock[0])/cpu if len(clock) == steps and cpu > 0 else float("nan")
    return cpu/((steps - 1)*parcels), ratio


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=50)
    parser.add_argument("--repeat", type=int, default=2)
    args = parser.parse_args()
    if args.steps < 2:
        parser.error("--steps must be at least 2")
    if not os.path.isdir(STOCK_TUTORIAL):
        parser.error(f"no MPPICFoam column tutorial at {STOCK_TUTORIAL} (. etc/bashrc first)")

    ours = prepare_ours(BUILD, args.steps)
    stock, parcels = prepare_stock(BUILD, ours, args.steps)
    inits = {"rarefiedMultiphaseFoam": ours, "MPPICFoam": stock}
    print(f"sniderSedimentation: {foam.n_cells(ours)} cells, {parcels} parcels x "
          f"{N_PARTICLE}, {args.steps} steps of {DT:g} s")

    costs = {label: [] for label, _, _ in RUNS}
    try:
        for rep in range(args.repeat):
            for label, app, averaging in RUNS:
                cost, load = parcel_cost(inits[app], label, app, averaging, rep,
                                         args.steps, parcels)
                costs[label].append(cost)
                print(f"repetition {rep}: {label:16s} {1e6*cost:8.4f} us CPU per "
                      f"parcel-step ({cost*parcels:.3f} s per step; clock/CPU "
                      f"{load:.2f})", flush=True)
    except Exception as err:            # a failed run: report it, exit 1
        print(f"FAILED: {err}")
        if getattr(err, "output", None):
            print(err.output)
        return 1

    best = {label: min(c) for label, c in costs.items()}
    stock_best = best["MPPICFoam"]
    for label, _, _ in RUNS:
        print(f"minimum {label:16s} {1e6*best[label]:8.4f} us CPU per parcel-step"
              f"  ratio to MPPICFoam {best[label]/stock_best:.3f}")
    ratio = best["ours cachedDual"]/stock_best
    ratio_dual = best["ours dual"]/stock_best
    verdict = "" if ratio <= TARGET else " MISSES TARGET"
    print(f"bench mppic: ratio ours/MPPICFoam = {ratio:.3f} (target <= {TARGET}){verdict}, "
          f"ours with dual {ratio_dual:.3f}; sniderSedimentation, {parcels} parcels, "
          f"{args.steps} steps; ours {1e6*best['ours cachedDual']:.3f}, "
          f"MPPICFoam {1e6*stock_best:.3f} us CPU per parcel-step (first step left out)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
