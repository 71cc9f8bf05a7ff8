#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Memory per gas simulator, per parcel and per cell, against the stock solvers.

The figure is each run's peak resident set size: ru_maxrss of the solver
process as wait4 returns it (what `/usr/bin/time -v` prints as "Maximum
resident set size").  Every run is serial and short (--steps steps,
nothing written until the end), started from a case meshed and
initialised once.  A cost per item is the difference of the peaks of two
runs that differ only in the number of items, over the difference of the
numbers:

    gas simulators   stock dsmcFoam's freeSpacePeriodic tutorial (5120
                     cells, N2 + O2 drifting at 1950 m/s), nEquivalentParticles W and
                     W/4 (--simulators sets the smaller count);
                     stock dsmcFoam and ours (gas alone) on the same cases
    gas cells        the same case with 2 x 2 x 2 times the cells at the
                     larger count of simulators (same simulators)
    parcels          tutorials/solids/sniderSedimentation (MPPIC grains in
                     vacuum, bench/mppic's set-up) with --parcels and
                     4 x --parcels parcels; ours and stock MPPICFoam
                     (bench/mppic's practically absent carrier) on the
                     same parcels

Ratios ours/stock are printed per item.  With --full, the full-settings
PSI case (tutorials/psi/apolloScaledPSI, variant MPPIC: 1.16 million
cells, a million parcels, almost no gas yet) runs one step serially; its
peak, with the measured cost per simulator, gives the estimate per rank
for the full case at steady state (about 14 million simulators) on
--ranks ranks:

    per rank = P_0 + (P_full - P_0)/ranks + S_full b_sim/ranks

with P_0 ours without simulators or cells (the smallest gas run's peak
less its simulators' and cells' share: the libraries and run time),
P_full the full case's serial peak and b_sim
ours per simulator: an even split of cells, parcels and simulators (the
dust layer sits in few cells, so its ranks carry more: the figure is a
mean, not a maximum).  Memory has no target yet; a failed run gives
exit status 1.

Run from the project directory:

    . etc/bashrc && bench/memory/bench.py [--simulators S] [--parcels P]
        [--steps N] [--full] [--ranks R]
"""

import argparse
import os
import re
import shutil
import subprocess
import sys

from rmf import foam, mppic

BUILD = os.path.join(foam.PROJECT_DIR, "build", "bench", "memory")
PSI = os.path.join(foam.PROJECT_DIR, "tutorials", "psi", "apolloScaledPSI")
MIB = 1024.0**2
# Full PSI case at steady state: simulators (its README's estimate)
FULL_SIMULATORS = 14e6


def peak(case, app, *args):
    """Peak resident set size [bytes] of one run of app on case."""
    log = os.path.join(case, f"log.{app}")
    with open(log, "w") as out:
        proc = subprocess.Popen([app, *args], cwd=case, stdout=out,
                                stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        with open(log) as f:
            tail = "".join(f.readlines()[-20:])
        raise subprocess.CalledProcessError(proc.returncode, app, output=tail)
    return 1024.0*usage.ru_maxrss      # Linux: kilobytes


def gas_case(name, weight, refine, steps):
    """freeSpacePeriodic meshed (cells x refine^3) and initialised at weight."""
    case = foam.copy_case(foam.dsmc_tutorial("freeSpacePeriodic"),
                          os.path.join(BUILD, name))
    foam.set_steps(case, steps)
    if refine != 1:
        mesh = os.path.join(case, "system", "blockMeshDict")
        with open(mesh) as f:
            text = f.read()
        with open(mesh, "w") as f:
            f.write(text.replace("(20 16 16)",
                                 f"({20*refine} {16*refine} {16*refine})"))
    foam.set_entry(case, "constant/dsmcProperties", "nEquivalentParticles", f"{weight:.6g}")
    foam.run(case, "blockMesh")
    foam.run(case, "dsmcInitialise")
    return case, foam.n_cells(case)


def simulators_of(case):
    """Simulators dsmcInitialise put in the case (its log)."""
    with open(os.path.join(case, "log.dsmcInitialise")) as f:
        return int(re.findall(r"Total number of molecules added: (\d+)", f.read())[-1])


def parcels_of(log):
    """Parcels in the solver's cloud at its last step (its log)."""
    return int(foam.log_values(log, "Current number of parcels")[-1][0])


def per_item(label, small, large, n_small, n_large, unit):
    """Bytes per item from two peaks; prints and returns it."""
    b = (large - small)/(n_large - n_small)
    print(f"  {label}: {small/MIB:8.1f} MiB at {n_small:>9d} {unit}, "
          f"{large/MIB:8.1f} MiB at {n_large:>9d}: {b:8.1f} bytes per {unit[:-1]}")
    return b


def bench_gas(args):
    """Bytes per simulator and per cell, ours and dsmcFoam."""
    # freeSpacePeriodic at its W = 1e12 holds about 64 000 simulators
    weight = 1e12*64000/args.simulators
    cases = {"small": gas_case("gas-init-small", weight, 1, args.steps),
             "large": gas_case("gas-init-large", weight/4, 1, args.steps),
             "fine": gas_case("gas-init-fine", weight/4, 2, args.steps)}
    counts = {k: simulators_of(c[0]) for k, c in cases.items()}
    cells = {k: c[1] for k, c in cases.items()}
    result = {}
    for solver in ("dsmcFoam", "rarefiedMultiphaseFoam"):
        peaks = {}
        for key, (init, _) in cases.items():
            run = foam.copy_case(init, os.path.join(BUILD, f"gas-{key}-{solver}"))
            peaks[key] = peak(run, solver)
        print(f"{solver}, freeSpacePeriodic, {args.steps} steps:")
        b_sim = per_item("simulators", peaks["small"], peaks["large"],
                         counts["small"], counts["large"], "simulators")
        # same W: the fine mesh holds the same simulators (up to the fill's noise)
        corrected = peaks["fine"] - b_sim*(counts["fine"] - counts["large"])
        b_cell = per_item("cells     ", peaks["large"], corrected,
                          cells["large"], cells["fine"], "cells")
        # the process without simulators or cells: the libraries, the run time
        base = peaks["small"] - b_sim*counts["small"] - b_cell*cells["small"]
        result[solver] = (b_sim, b_cell, base)
    return result


def bench_parcels(args):
    """Bytes per MPPIC parcel, ours and MPPICFoam."""
    build = os.path.join(BUILD, "mppic")
    result = {}
    runs = {}
    for key, n in (("small", args.parcels), ("large", 4*args.parcels)):
        ours = mppic.prepare_ours(build, args.steps, parcels=n)
        stock, count = mppic.prepare_stock(build, ours, args.steps)
        runs[key] = (count, {"rarefiedMultiphaseFoam": ours, "MPPICFoam": stock})
        # prepare_* reuse their directories: keep this size's pair
        for app, case in runs[key][1].items():
            runs[key][1][app] = foam.copy_case(case, os.path.join(BUILD, f"parcels-{key}-{app}"))
    for app in ("MPPICFoam", "rarefiedMultiphaseFoam"):
        peaks = {key: peak(runs[key][1][app], app) for key in runs}
        print(f"{app}, sniderSedimentation (MPPIC), {args.steps} steps:")
        result[app] = per_item("parcels   ", peaks["small"], peaks["large"],
                               runs["small"][0], runs["large"][0], "parcels")
    return result


def bench_full(args, b_sim, b_parcel, p0):
    """Serial peak of the full PSI case (MPPIC, one step) and the estimate per rank."""
    case = foam.copy_setup(PSI, os.path.join(BUILD, "psi-full"))
    shutil.copytree(os.path.join(PSI, "settings"), os.path.join(case, "settings"))
    with open(os.path.join(case, "constant", "caseSettings"), "w") as f:
        f.write("settings full;\nvariant MPPIC;\n")     # as Allrun writes it
    foam.set_entry(case, "system/controlDict", "endTime", "2.5e-9")   # one step
    foam.set_entry(case, "system/controlDict", "writeInterval", "1")
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    p_full = peak(case, "rarefiedMultiphaseFoam")
    parcels = parcels_of(os.path.join(case, "log.rarefiedMultiphaseFoam"))
    per_rank = p0 + (p_full - p0)/args.ranks + FULL_SIMULATORS*b_sim/args.ranks
    cells = foam.n_cells(case)
    print(f"full PSI case (MPPIC), serial, 1 step: {cells} cells, "
          f"{parcels} parcels: peak {p_full/MIB:.0f} MiB, so "
          f"{(p_full - p0 - parcels*b_parcel)/cells:.0f} bytes per cell with its "
          f"MPPIC parcels at {b_parcel:.0f} B")
    print(f"  estimate at {FULL_SIMULATORS:.3g} simulators on {args.ranks} ranks: "
          f"{per_rank/MIB:.0f} MiB per rank (even split; base {p0/MIB:.0f} MiB)")
    return per_rank


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--simulators", type=int, default=250000,
                        help="smaller gas count (the larger is 4 times it)")
    parser.add_argument("--parcels", type=int, default=100000,
                        help="smaller parcel count (the larger is 4 times it)")
    parser.add_argument("--steps", type=int, default=3)
    parser.add_argument("--full", action="store_true",
                        help="also the full PSI case and the estimate per rank")
    parser.add_argument("--ranks", type=int, default=40)
    args = parser.parse_args()
    if "FOAM_TUTORIALS" not in os.environ:
        sys.exit("bench memory: no OpenFOAM environment (. etc/bashrc first)")

    gas = bench_gas(args)
    parcels = bench_parcels(args)
    b_sim, b_cell, p0 = gas["rarefiedMultiphaseFoam"]
    s_sim, s_cell, _ = gas["dsmcFoam"]
    summary = (f"bench memory: per simulator ours {b_sim:.0f} B, dsmcFoam {s_sim:.0f} B "
               f"(ratio {b_sim/s_sim:.2f}); per gas cell ours {b_cell:.0f} B, dsmcFoam "
               f"{s_cell:.0f} B ({b_cell/s_cell:.2f}); per MPPIC parcel ours "
               f"{parcels['rarefiedMultiphaseFoam']:.0f} B, MPPICFoam "
               f"{parcels['MPPICFoam']:.0f} B "
               f"({parcels['rarefiedMultiphaseFoam']/parcels['MPPICFoam']:.2f})")
    if args.full:
        per_rank = bench_full(args, b_sim, parcels["rarefiedMultiphaseFoam"], p0)
        summary += f"; full PSI case on {args.ranks} ranks ~{per_rank/MIB:.0f} MiB per rank"
    print(summary)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (subprocess.CalledProcessError, RuntimeError, OSError) as error:
        print(f"bench memory: FAILED: {error}", file=sys.stderr)
        if getattr(error, "output", None):
            print(error.output, file=sys.stderr)
        sys.exit(1)
