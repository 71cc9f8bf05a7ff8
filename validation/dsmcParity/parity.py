#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Parity of rarefiedMultiphaseFoam with stock dsmcFoam on dsmcFoam's tutorials.

For each case (copied from the OpenFOAM tutorials of the SDK), meshed with
blockMesh and initialised once by rarefiedMultiphaseInitialise (the fill's
randomSeed seed(0)):

  initial state  simulator count, mean velocity (each component) and
                 temperature of each species against dsmcInitialiseDict
                 (analytic: Bernoulli remainders per tet, Maxwellian
                 sampling; normal quantile z)
  stock          dsmcFoam, serial
  ours           rarefiedMultiphaseFoam, serial, no randomSeed, upstream's
                 tracking (tracking barycentric): same random stream and
                 same move as dsmcFoam, so every file of the final time
                 directory must be byte-identical to stock's (the parcel
                 files' class line aside)
  seed1..seedK   rarefiedMultiphaseFoam, randomSeed seed(1..K), its default
                 Cartesian move (boxWalk): the noise ensemble
  parallel       rarefiedMultiphaseFoam on 2 METIS ranks (decomposePar,
                 mpirun, reconstructPar), randomSeed seed(K + 1) (outside
                 the ensemble), Cartesian move

(seed(k) is rmf_testing.seed: ./Alltest --seed-set N changes every seed
but dsmcFoam's, which is fixed), and "stock" and "parallel" must each lie
within the ensemble's noise (rmf.stats: domain-mean level and cell
pattern, Student prediction intervals with K - 1 degrees of freedom) for
rhoNMean, UMean, translationalT, overallT, p.

Family-wise error: rmf_testing.MODULE_ALPHA (2.5e-4) over the four cases
of one mode, MODULE_ALPHA/4 per case shared equally (Bonferroni) by its
m comparisons: 24 ensemble checks (2 runs x (7 levels + 5 patterns)) and
5 initial-state checks per filled species, m = 34 (29 for supersonicCorner,
one species), so 1.8e-6 each (2.2e-6): Student t_9 10.8 (level, two-sided;
K = 10), 10.0 (pattern, one-sided), normal z 4.8 (initial state); the
figures are printed.  The full mode (--long) spends MODULE_ALPHA again on
its own four cases.  K was 6 with 1e-3 per check (t_5 6.87: 96 checks,
a false alarm in about 9 % of the module's runs with the seeds changed);
at the Bonferroni share t_5 would be 25.2, so K = 10 (t_9 10.8, for four
more runs per case).

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

import rmf_testing
from rmf import foam, stats


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

# Ensemble size, fixed before its results were seen (module docstring)
K = 10
SEEDS = tuple(f"seed{k}" for k in range(1, K + 1))

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
    foam.set_entry(init, "system/dsmcInitialiseDict", "randomSeed", rmf_testing.seed(0))
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
        foam.set_entry(runs[name], "constant/dsmcProperties", "randomSeed",
                       rmf_testing.seed(k))
    foam.set_entry(runs["parallel"], "constant/dsmcProperties", "randomSeed",
                   rmf_testing.seed(K + 1))

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
# gas's restart state and its account's totals (doc/physics.md#restart)
OURS_ONLY = {"lambda.gas", "gasCloudState", "particleAccountState"}


def _same_but_class(fa, fb, rel):
    """Parcel files that differ only in the header line naming the parcel
    class (gasParcel against upstream's DSMCParcel)."""
    return "lagrangian" in rel and _strip_class(fa) == _strip_class(fb)


def number_density(init, name):
    """Number density dsmcInitialiseDict fills species name with (None:
    not in numberDensities, an inflow species)."""
    try:
        return float(foam.get_entry(init, "system/dsmcInitialiseDict",
                                    f"numberDensities/{name}"))
    except subprocess.CalledProcessError:
        return None


def species(init):
    """The gas species, in typeId order."""
    return foam.get_entry(init, "constant/dsmcProperties", "typeIdList").strip("()").split()


def n_tets(case):
    """Number of tets the fill visits (polyMeshTetDecomposition::
    cellTetIndices): nPoints - 2 per face of each cell, an internal face
    counting for both its cells."""
    per_face = np.array([len(face) - 2 for face in foam.read_faces(case)])
    internal = len(foam.read_labels(case, "neighbour"))
    return int(per_face.sum() + per_face[:internal].sum())


def initial_state_checks(init, alpha):
    """Analytic checks of the initial state, each at false-alarm probability
    alpha (5 per filled species): list of (name, passed, text)."""
    cloud = os.path.join(init, "0", "lagrangian", "dsmc")
    U = foam.read_list(os.path.join(cloud, "U"))
    type_id = foam.read_list(os.path.join(cloud, "typeId")).astype(int)
    volume = foam.read_field(os.path.join(init, "0", "V")).sum()
    props = "constant/dsmcProperties"
    w = float(foam.get_entry(init, props, "nEquivalentParticles"))
    idict = "system/dsmcInitialiseDict"
    T0 = float(foam.get_entry(init, idict, "temperature"))
    U0 = np.array(foam.get_entry(init, idict, "velocity").strip("()").split(), float)
    z = rmf_testing.z_limit(1, alpha)
    tets = n_tets(init)

    checks = []
    for s, name in enumerate(species(init)):
        c = U[type_id == s]
        n = number_density(init, name)
        if n is None:
            # a species the fill does not name (inflow only): none placed
            checks.append((f"{name} count", len(c) == 0,
                           f"{len(c)} vs 0 (not in numberDensities)"))
            continue
        expected = n*volume/w
        # Each tet adds a Bernoulli remainder (its expected count's
        # fraction), variance p(1 - p) <= 1/4: the count's variance is at
        # most tets/4, tets the exact number of tets (an upper bound on
        # the variance, so the false-alarm probability is at most alpha)
        tol = z*np.sqrt(tets/4)
        checks.append((f"{name} count", abs(len(c) - expected) <= tol,
                       f"{len(c)} vs {expected:.1f} (tol {tol:.1f}: z {z:.2f},"
                       f" {tets} tets)"))
        m = float(foam.get_entry(init, props, f"moleculeProperties/{name}/mass"))
        sd = np.sqrt(K_B*T0/m)
        mean = c.mean(axis=0)
        tol = z*sd/np.sqrt(len(c))
        for i, x in enumerate("xyz"):
            checks.append((f"{name} mean velocity u_{x}", abs(mean[i] - U0[i]) <= tol,
                           f"{mean[i]:.4g} vs {U0[i]:g} (tol {tol:.3g})"))
        T = m*np.mean(np.sum((c - U0)**2, axis=1))/(3*K_B)
        # Sample temperature: relative standard error sqrt(2/(3N))
        tol = z*T0*np.sqrt(2/(3*len(c)))
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
    values = {field: {name: foam.read_field(os.path.join(d[name], t, field), n)
                      for name in ("stock", "parallel") + SEEDS}
              for field in FIELDS}
    # The case's share of the family-wise error, equally among its checks
    m = (5*sum(number_density(d["init"], name) is not None for name in species(d["init"]))
         + 2*sum(stats.n_checks(v["stock"]) for v in values.values()))
    alpha = rmf_testing.MODULE_ALPHA/len(CASES)/m
    print(f"{os.path.basename(root)}: {m} comparisons at alpha {alpha:.3g} each:"
          f" Student t_{K - 1} {rmf_testing.t_limit(K - 1, 1, alpha):.2f} (level),"
          f" {rmf_testing.t_limit(K - 1, 1, alpha, two_sided=False):.2f} (pattern),"
          f" normal {rmf_testing.z_limit(1, alpha):.2f} (initial state)")
    results = []
    for field, v in values.items():
        ensemble = [v[name] for name in SEEDS]
        for run in ("stock", "parallel"):
            results += stats.compare(f"{field} {run}", v[run], ensemble, alpha)
    return exact, initial_state_checks(d["init"], alpha), results


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
