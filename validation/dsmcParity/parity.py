#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Parity of rarefiedMultiphaseFoam with stock dsmcFoam on dsmcFoam's tutorials.

For each case (copied from the OpenFOAM tutorials of the SDK), meshed with
blockMesh and initialised once by rarefiedMultiphaseInitialise:

  initial state  simulator count, mean velocity and temperature of each
                 species against dsmcInitialiseDict (analytic; 5 standard
                 errors: Bernoulli remainders per tet, Maxwellian sampling)
  stock          dsmcFoam, serial
  ours           rarefiedMultiphaseFoam, serial, no randomSeed, upstream's
                 tracking (tracking barycentric): same random stream and
                 same move as dsmcFoam, so every file of the final time
                 directory must be byte-identical to stock's (the parcel
                 files' class line aside)
  seed1..seed6   rarefiedMultiphaseFoam, randomSeed 1..6, its default
                 Cartesian move (boxWalk): the noise ensemble
  parallel       rarefiedMultiphaseFoam on 2 METIS ranks (decomposePar,
                 mpirun, reconstructPar), no randomSeed, Cartesian move

and "stock" and "parallel" must each lie within the ensemble's noise
(rmf.stats: domain-mean level and cell pattern, Student prediction
intervals, alpha = 1e-3) for rhoNMean, UMean, translationalT, overallT, p.

Reduced mode (default, for ./Alltest): fewer steps, and for supersonicCorner
a mesh twice as coarse in each direction with eight times fewer simulators
(nEquivalentParticles x 8), so as many per cell as the tutorial.  Full mode
(--full): the tutorials' dictionaries unchanged (hours for supersonicCorner).

Usage: parity.py [--full] [case ...]
"""

import argparse
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "src", "python"))

from rmf import foam, stats  # noqa: E402

CASES = ("freeSpacePeriodic", "freeSpaceStream", "supersonicCorner", "wedge15Ma5")

# Reduced mode: steps run, factor on nEquivalentParticles, and cell counts
# of blockMeshDict's blocks replaced (the same simulators per cell).
# supersonicCorner: 200 steps, as over 100 the least hit of its 900 wall
# faces took about one simulator (every run, stock's too), and a face
# that none hit makes dsmcFields write nothing (its guard against a zero
# rhoNMean, patches included): one of the seven serial runs met it
REDUCED = {
    "freeSpacePeriodic": (200, 1, {}),
    "freeSpaceStream": (200, 1, {}),
    "supersonicCorner": (200, 8, {"(10 36 36)": "(5 18 18)", "(50 36 36)": "(25 18 18)"}),
    "wedge15Ma5": (400, 1, {}),
}

SEEDS = tuple(f"seed{k}" for k in range(1, 7))

FIELDS = ("rhoNMean", "UMean", "translationalT", "overallT", "p")

BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "dsmcParity")

K_B = 1.380649e-23


def prepare(case, full):
    """Meshed and initialised case directory: (root, init)."""
    root = os.path.join(BUILD, ("full" if full else "reduced"), case)
    mesh = foam.copy_case(foam.dsmc_tutorial(case), os.path.join(root, "mesh"))
    if not full:
        steps, factor, blocks = REDUCED[case]
        foam.set_steps(mesh, steps)
        if factor != 1:
            n = float(foam.get_entry(mesh, "constant/dsmcProperties", "nEquivalentParticles"))
            foam.set_entry(mesh, "constant/dsmcProperties", "nEquivalentParticles",
                           f"{n*factor:g}")
        path = os.path.join(mesh, "system", "blockMeshDict")
        with open(path) as f:
            text = f.read()
        for old, new in blocks.items():
            assert old in text, f"{case}: no block {old} in blockMeshDict"
            text = text.replace(old, new)
        with open(path, "w") as f:
            f.write(text)
    foam.run(mesh, "blockMesh")
    init = foam.copy_case(mesh, os.path.join(root, "init"))
    foam.run(init, "rarefiedMultiphaseInitialise")
    foam.run(init, "postProcess", "-func", "writeCellVolumes", "-time", "0")
    return root, init


def run_all(case, full=False):
    """Run every variant of one case; return the root directory."""
    root, init = prepare(case, full)
    runs = {name: foam.copy_case(init, os.path.join(root, name))
            for name in ("stock", "ours", "parallel") + SEEDS}
    foam.set_entry(runs["ours"], "constant/dsmcProperties", "tracking", "barycentric")
    for k, name in enumerate(SEEDS, start=1):
        foam.set_entry(runs[name], "constant/dsmcProperties", "randomSeed", k)

    serial = [("stock", "dsmcFoam")] + [(name, "rarefiedMultiphaseFoam")
                                        for name in ("ours",) + SEEDS]
    with ThreadPoolExecutor(max_workers=2) as pool:
        for job in [pool.submit(foam.run, runs[name], app) for name, app in serial]:
            job.result()

    par = runs["parallel"]
    foam.set_entry(par, "system/decomposeParDict", "numberOfSubdomains", 2)
    foam.set_entry(par, "system/decomposeParDict", "method", "metis")
    foam.run(par, "decomposePar")
    foam.run(par, "rarefiedMultiphaseFoam", np_=2)
    foam.run(par, "reconstructPar", "-latestTime")
    return root


def _strip_class(path):
    """File bytes without the header line naming the parcel class."""
    with open(path, "rb") as f:
        return b"".join(line for line in f if not line.lstrip().startswith(b"class "))


# Outputs of ours that dsmcFoam does not have: the gas's mean free path
# (gasCloud writes it at every write time, gas-only runs included) and the
# gas's restart state and its account's totals (doc/physics.md 1.4)
OURS_ONLY = {"lambda.gas", "gasCloudState", "particleAccountState"}


def _same_but_class(fa, fb, rel):
    """Parcel files that differ only in the header line naming the parcel
    class (gasParcel against upstream's DSMCParcel)."""
    return "lagrangian" in rel and _strip_class(fa) == _strip_class(fb)


def initial_state_checks(init):
    """Analytic checks of the initial state: list of (name, passed, text)."""
    cloud = os.path.join(init, "0", "lagrangian", "dsmc")
    U = foam.read_list(os.path.join(cloud, "U"))
    type_id = foam.read_list(os.path.join(cloud, "typeId")).astype(int)
    volume = foam.read_field(os.path.join(init, "0", "V")).sum()
    props = "constant/dsmcProperties"
    species = foam.get_entry(init, props, "typeIdList").strip("()").split()
    w = float(foam.get_entry(init, props, "nEquivalentParticles"))
    idict = "system/dsmcInitialiseDict"
    T0 = float(foam.get_entry(init, idict, "temperature"))
    U0 = np.array(foam.get_entry(init, idict, "velocity").strip("()").split(), float)
    n_tets = 6*foam.n_cells(init)  # at least: each cell has several tets

    checks = []
    for s, name in enumerate(species):
        c = U[type_id == s]
        try:
            n = float(foam.get_entry(init, idict, f"numberDensities/{name}"))
        except subprocess.CalledProcessError:
            # a species the fill does not name (inflow only): none placed
            checks.append((f"{name} count", len(c) == 0,
                           f"{len(c)} vs 0 (not in numberDensities)"))
            continue
        expected = n*volume/w
        # Each tet adds a Bernoulli remainder: variance at most n_tets/4
        tol = 5*np.sqrt(n_tets/4)
        checks.append((f"{name} count", abs(len(c) - expected) <= tol,
                       f"{len(c)} vs {expected:.1f} (tol {tol:.1f})"))
        m = float(foam.get_entry(init, props, f"moleculeProperties/{name}/mass"))
        sd = np.sqrt(K_B*T0/m)
        mean = c.mean(axis=0)
        tol = 5*sd/np.sqrt(len(c))
        checks.append((f"{name} mean velocity", np.all(np.abs(mean - U0) <= tol),
                       f"{mean} vs {U0} (tol {tol:.3g} per component)"))
        T = m*np.mean(np.sum((c - U0)**2, axis=1))/(3*K_B)
        # Sample temperature: relative standard error sqrt(2/(3N))
        tol = 5*T0*np.sqrt(2/(3*len(c)))
        checks.append((f"{name} temperature", abs(T - T0) <= tol,
                       f"{T:.2f} K vs {T0:g} K (tol {tol:.2f} K)"))
    return checks


def check(root):
    """(exact differences, initial-state checks, statistical checks)."""
    d = {name: os.path.join(root, name) for name in
         ("init", "stock", "ours", "parallel") + SEEDS}
    t = foam.latest_time(d["stock"])
    stock_t = os.path.join(d["stock"], t)
    exact = foam.differing_files(stock_t, os.path.join(d["ours"], t),
                                 equivalent=_same_but_class)
    # Every file dsmcFoam writes must be the same; ours may add OURS_ONLY
    exact = [f for f in exact if not (os.path.basename(f) in OURS_ONLY
                                      and not os.path.exists(os.path.join(stock_t, f)))]

    n = foam.n_cells(d["stock"])
    results = []
    for field in FIELDS:
        v = {name: foam.read_field(os.path.join(d[name], t, field), n)
             for name in ("stock", "parallel") + SEEDS}
        ensemble = [v[name] for name in SEEDS]
        for run in ("stock", "parallel"):
            results += stats.compare(f"{field} {run}", v[run], ensemble)
    return exact, initial_state_checks(d["init"]), results


def report(case, exact, initial, results):
    """Print PASS/FAIL lines; return the number of failures."""
    print(f"{case}: exact reproduction of dsmcFoam: "
          + ("PASS" if not exact else "FAIL, differing: " + ", ".join(exact)))
    for name, ok, text in initial:
        print(f"{case}: {'PASS' if ok else 'FAIL'} initial {name}: {text}")
    for r in results:
        print(f"{case}: {r}")
    return bool(exact) + sum(not ok for _, ok, _ in initial) + sum(not r.passed for r in results)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--full", action="store_true", help="tutorials unchanged")
    parser.add_argument("cases", nargs="*", default=CASES)
    args = parser.parse_args()
    failed = sum(report(case, *check(run_all(case, args.full))) for case in args.cases)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
