# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Snider sedimentation validation (doc/physics.md#snider).

    /usr/bin/python3 validate.py [--full] [--build DIR]

Runs the tutorials/solids/sniderSedimentation set-up, each to 0.6 s:
  serial    e = 0.85, one rank,
  parallel  e = 0.85, 2 METIS ranks (decomposePar/reconstructPar),
  e05       e = 0.5 (walls, collision time scale and packing correction
            limit), one rank,
then applies the checks of rmf.snider (tolerances and their origin are
stated there) and draws sniderSedimentation.png: alpha(z) at 0.1, 0.15,
0.2 and 0.6 s for the serial and the parallel run, and e = 0.85 against
e = 0.5 at 0.2 s.

With --restitution (restitution(); ./Alltest --long) it also runs the
restitution check of rmf.snider: e = 0.85 and e = 0.5, reduced, each with
the cloud's seeds 0 to RESTITUTION_SEEDS - 1 (the sharper interface of
e = 0.5 is a difference of means over seeds; the ensemble's size and its
false-alarm probability: rmf.snider).

With --variants it also runs, side by side to 0.6 s, the variants of
VARIANTS (v1912's explicit and implicit packing instead of ours; ours
with e = 0.5; stochastic NTC collisions instead of MPPIC; the NTC/MPPIC
hybrid; reduced: the last two only, REDUCED_VARIANTS), prints each run's
largest layer, raw cell and averaged cell alpha, and
draws sniderVariants.png: alpha(z) at 0.1, 0.15, 0.2 and 0.6 s of each.

Reduced (default, in ./Alltest): 4 times fewer parcels of 4 times the
weight (same alpha0); --full: the tutorial as it is (162 232 parcels).

free_fall(): the tutorial at its parcel weight to 0.15 s, serial: the
suspension's fall before the bed reaches it (rmf.snider.free_fall); the
tests run it with twoSided's predictMean.

narrow(): the over-packing bounds at the tutorial's parcel weight in
./Alltest: a column of 5 x 5 of the tutorial's cells (0.046 m square)
holding a ninth of its parcels (18 026 x 749), to 0.6 s, serial; the
tests run it also with twoSided's smoothing 1 and without its
packedCells (doc/physics.md#two-sided).
The two single-rank runs go side by side on the machine's 2 cores, then
the parallel one.

Seeds: every run sets the initialiser's randomSeed (the parcels' places)
to rmf_testing.seed(1) and the cloud's (the isotropy model's draws) to
rmf_testing.seed(k), k = 0 but in the restitution ensemble, so that
./Alltest --seed-set N (RMF_SEED_SET=N) changes every realisation.
"""

import argparse
import concurrent.futures
import os
import sys

from rmf import foam, snider
from rmf_testing import seed

TUTORIAL = os.path.join(foam.PROJECT_DIR, "tutorials", "solids", "sniderSedimentation")
BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "sniderSedimentation")
INIT = "system/grainsInitialiseDict"
PROPS = "constant/grainsProperties"
FULL_PARCELS, FULL_WEIGHT = 162232, 749
REDUCTION = 4
# Realisations of e = 0.85 and of e = 0.5 for the restitution check (cloud
# seeds 0 to RESTITUTION_SEEDS - 1; rmf.snider: why 8)
RESTITUTION_SEEDS = 8

# Variants of the tutorial (doc/physics.md#snider, #ntc, #mppic, #hybrid):
# grainsProperties entries each sets
VARIANTS = {
    # v1912's packing models instead of ours (their coefficients are in
    # the tutorial's dictionary: implicit with eps = 1e-2, as 5.3 explains)
    "explicit": {"subModels/packingModel": "explicit"},
    "implicit": {"subModels/packingModel": "implicit"},
    # ours with restitution 0.5 (walls, time scales, limiter)
    "twoSidedE05": {},
    # NTC hard-sphere collisions alone: no packing, no isotropy
    "stochastic": {"subModels/packingModel": "none",
                   "subModels/isotropyModel": "none",
                   "subModels/stochasticCollisionModel": "NTCHardSphere"},
    # NTC in cells below alphaSwitch (binary collisions valid below 0.1,
    # doc/physics.md#ntc), MPPIC as in the tutorial
    "hybrid": {"subModels/stochasticCollisionModel": "NTCHardSphere",
               "subModels/NTCHardSphereCoeffs/alphaSwitch": 0.1},
}
REDUCED_VARIANTS = ("stochastic", "hybrid")
# The reduced runs' parcels are 4 times heavier: one alone makes
# alpha = 0.067 in a cell, so below 0.1 no cell holds a pair; 0.2 admits
# up to 2 (the full-size 0.1 admits 5)
REDUCED_ALPHA_SWITCH = 0.2


def seeded(case, k=0):
    """Set the case's seeds (module docstring): the cloud's seed(k)."""
    foam.set_entry(case, INIT, "randomSeed", seed(1))
    foam.set_entry(case, PROPS, "randomSeed", seed(k))


def prepare(build, name, scale, end, e=None, entries=None, k=0):
    case = foam.copy_setup(TUTORIAL, os.path.join(build, name))
    seeded(case, k)
    for entry, value in (entries or {}).items():
        foam.set_entry(case, PROPS, entry, value)
    foam.set_entry(case, INIT, "regions/column/nParcels", round(FULL_PARCELS/scale))
    foam.set_entry(case, INIT, "regions/column/nParticle", FULL_WEIGHT*scale)
    foam.set_entry(case, "system/controlDict", "endTime", end)
    if e is not None:
        # Every restitution of the dictionary: walls (a list, which
        # foamDictionary cannot address), time scales, correction limit
        foam.substitute(os.path.join(case, PROPS), r"(?m)^(\s*e\s+)0\.85;", rf"\g<1>{e};",
                        count=5)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case


def solve(case, np_=1):
    """Run the solver."""
    if np_ > 1:
        foam.run(case, "decomposePar")
        foam.run(case, "rarefiedMultiphaseFoam", np_=np_)
        foam.run(case, "reconstructPar", *foam.RECONSTRUCT_ALL)
    else:
        foam.run(case, "rarefiedMultiphaseFoam")


def free_fall(build=BUILD, scale=1, entries=None):
    """The suspension's fall (module docstring) at scale times the
    tutorial's parcel weight, with the grainsProperties entries {entry:
    value} changed; returns rmf.snider.free_fall of the run."""
    name = f"weight{scale:g}" + "".join(f"_{k.split('/')[-1]}{v}" for k, v in (entries or {}).items())
    case = prepare(os.path.join(build, "freeFall"), name, scale,
                   float(snider.FREE_FALL_TIMES[-1]), entries=entries)
    solve(case)
    fall = snider.free_fall(case)
    for time, (error, se, n) in fall.items():
        print(f"free fall at {time} s, weight x {scale:g}: {100*error:+.2f} % "
              f"(standard error {100*se:.3f} %, {n} parcels)")
    return fall


NARROW_CELLS = 5                    # of the tutorial's 15 per side


def narrow(build=BUILD, name="narrow", entries=None, k=None):
    """The tutorial at its parcel weight in a narrow column (module
    docstring), with the grainsProperties entries {entry: value} changed;
    returns (all passed, summary) of rmf.snider.check with the averaged
    cell bound (a layer holds too few parcels for the layer bound:
    rmf.snider) and the case.  k: a member of an ensemble, the cloud's
    seed(k) and the fill's seed(k + 100) (seeded() otherwise)."""
    case, _ = snider.narrow_column(os.path.join(build, name), NARROW_CELLS)
    if k is None:
        seeded(case)
    else:
        foam.set_entry(case, INIT, "randomSeed", seed(k + 100))
        foam.set_entry(case, PROPS, "randomSeed", seed(k))
    for entry, value in (entries or {}).items():
        foam.set_entry(case, PROPS, entry, value)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    solve(case)
    print(f"-- {name}: {case}")
    return snider.check(case, "0.6", cell_bound=True, layer_bound=False) + (case,)


def variants(mppic, full=False, build=BUILD):
    """The VARIANTS run to 0.6 s beside each other; mppic: summary of the
    tutorial's serial run at the same size.  Returns {name: (passed,
    summary)} with the tutorial's run under "twoSided", and the plot's path."""
    scale = 1 if full else REDUCTION
    build = os.path.join(build, "full" if full else "reduced")

    def run(name):
        entries = dict(VARIANTS[name])
        if not full and "subModels/NTCHardSphereCoeffs/alphaSwitch" in entries:
            entries["subModels/NTCHardSphereCoeffs/alphaSwitch"] = REDUCED_ALPHA_SWITCH
        case = prepare(build, name, scale, 0.6, e=0.5 if name == "twoSidedE05" else None,
                       entries=entries)
        solve(case)
        print(f"-- {name}: {case}")
        return snider.check(case, "0.6", cell_bound=full, heated=True)

    names = list(VARIANTS) if full else list(REDUCED_VARIANTS)
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        results = dict(zip(names, pool.map(run, names)))
    runs = {"twoSided": mppic, **{name: s for name, (_, s) in results.items()}}
    print("-- largest alpha from 0.1 s: layer / raw cell / averaged cell;"
          " bed below 0.14 m at 0.6 s")
    for name, s in runs.items():
        averaged = s.get("alphaMaxAveragedAll")
        print(f"{name:12s} {max(s['alphaMaxLayer'].values()):.3f}"
              f" / {s['alphaMaxCellAll']:.3f}"
              f" / {averaged if averaged is None else round(averaged, 3)}"
              f"; {s.get('bedMean', float('nan')):.3f}")
    png = os.path.join(build, "sniderVariants.png")
    snider.plot(runs, png, title="Snider sedimentation: packing and collision"
                " models (alpha(z) at 0.1, 0.15, 0.2, 0.6 s)")
    return {"twoSided": (True, mppic), **results}, png


def validate(full=False, build=BUILD, parallel_case=None):
    """All runs and checks; returns (all passed, figures with "checks":
    each check's result by name).  parallel_case:
    a finished 2-rank run of the same set-up to use instead of a new one
    (e.g. the tutorial's ./Allrun -parallel)."""
    scale = 1 if full else REDUCTION
    build = os.path.join(build, "full" if full else "reduced")

    def serial_run(name, end, e=None):
        case = prepare(build, name, scale, end, e)
        solve(case)
        return case

    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        serial, e05 = pool.map(serial_run, ("serial", "e05"), (0.6, 0.6), (None, 0.5))

    if parallel_case:
        parallel = parallel_case
    else:
        parallel = prepare(build, "parallel", scale, 0.6)
        solve(parallel, np_=2)

    print(f"Parcels {round(FULL_PARCELS/scale)} x {FULL_WEIGHT*scale}")

    checks = {}
    runs = {}
    for name, case, end in (("serial", serial, "0.6"), ("parallel", parallel, "0.6"),
                            ("e05", e05, "0.6")):
        print(f"-- {name}: {case}")
        _, runs[name] = snider.check(case, end, cell_bound=full)
        checks.update({f"{name}: {k}": v for k, v in runs[name]["checks"].items()})
    s, p, e = runs["serial"], runs["parallel"], runs["e05"]
    print("-- serial against parallel")
    checks["compare"] = snider.compare(s, p)

    png = os.path.join(build, "sniderSedimentation.png")
    snider.plot({"serial, e = 0.85": s, "2 METIS ranks, e = 0.85": p}, png,
                title=f"Snider sedimentation, {round(FULL_PARCELS/scale)} parcels")
    compare_png = os.path.join(build, "sniderRestitution.png")
    snider.plot({"e = 0.85": {"z": s["z"], "profiles": {"0.2": s["profiles"]["0.2"]}},
                 "e = 0.5": {"z": e["z"], "profiles": {"0.2": e["profiles"]["0.2"]}}},
                compare_png, times=("0.2",), title="bed surface at 0.2 s")

    ok = all(checks.values())
    print("PASS" if ok else "FAIL")
    return ok, {"checks": checks, "serial": s, "parallel": p, "e05": e,
                "cases": {"serial": serial, "parallel": parallel, "e05": e05},
                "pngs": (png, compare_png)}


def restitution(build=BUILD, n=RESTITUTION_SEEDS):
    """The restitution check (module docstring): reduced runs of e = 0.85
    and e = 0.5 with the cloud's seeds 0 to n - 1, two at a time; returns
    {name: passed}: each run's rmf.snider checks (no over-packing bounds:
    reduced) and "sharper"."""
    build = os.path.join(build, "reduced", "restitution")

    def run(job):
        e, k = job
        case = prepare(build, f"e{e}-seed{k}", REDUCTION, 0.6, None if e == 0.85 else e, k=k)
        solve(case)
        print(f"-- e = {e}, cloud seed {seed(k)}: {case}")
        return snider.check(case, "0.6", cell_bound=False)

    jobs = [(e, k) for k in range(n) for e in (0.85, 0.5)]
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        results = dict(zip(jobs, pool.map(run, jobs)))
    checks = {f"e = {e}, seed {k}": ok for (e, k), (ok, _) in results.items()}
    checks["sharper"], _, _ = snider.sharper(
        [s for (e, _), (_, s) in results.items() if e == 0.5],
        [s for (e, _), (_, s) in results.items() if e == 0.85])
    return checks


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--full", action="store_true")
    parser.add_argument("--build", default=BUILD)
    parser.add_argument("--parallel-case", help="finished 2-rank run to reuse")
    parser.add_argument("--variants", action="store_true",
                        help="also the grain-collision variants")
    parser.add_argument("--restitution", action="store_true",
                        help="also the restitution check (reduced runs over seeds)")
    args = parser.parse_args(argv)
    ok, figures = validate(args.full, args.build, args.parallel_case)
    if args.restitution:
        ok &= all(restitution(args.build).values())
    if args.variants:
        results, _ = variants(figures["serial"], args.full, args.build)
        ok &= all(passed for name, (passed, _) in results.items()
                  if name != "stochastic")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
