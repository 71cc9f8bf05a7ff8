# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Serial against 2 ranks for every decomposition method (issue 18 item 3,
first part): the dustCloudStream tutorial (argon stream, 2000 grain
parcels, cyclic in y and z) with twoWayDirect coupling, 100 steps.

Runs: four serial runs with randomSeed 1..4 of the gas and the coupling
(the noise ensemble), and one 2-rank run per method (metis, scotch,
simple, hierarchical; randomSeed 1), each decomposed, run and
reconstructed.  Checks, per method:
1. reconstructPar restores every lagrangian field the serial run writes,
   for both clouds (the same file names, the project's own included),
   each field with as many entries as the cloud has members;
2. nothing is lost: every parcel is still there (the grains do not reach
   the open patches in 100 steps) and the logs report no "lost" member;
3. the observables agree with the serial ensemble: the grains' mean
   velocity u_x and mean temperature, the gas's simulator count and its
   mean x velocity, each within 5 sigma of the ensemble mean, sigma the
   ensemble's standard deviation times sqrt(1 + 1/4) (the parallel run is
   one more independent draw: its streams differ from every serial one).
"""

import os

import numpy as np
import pytest

from rmf import foam

ROOT = foam.PROJECT_DIR
DUST = os.path.join(ROOT, "tutorials", "coupling", "dustCloudStream")
BUILD = os.path.join(ROOT, "build", "validation", "parallelEquivalence")
STEPS = 100
SEEDS = (1, 2, 3, 4)
METHODS = ("metis", "scotch", "simple", "hierarchical")
N_SIGMA = 5
COEFFS = {"simple": "simpleCoeffs { n (2 1 1); delta 0.001; }",
          "hierarchical": "hierarchicalCoeffs { n (2 1 1); delta 0.001; order xyz; }"}


def make(name, seed):
    case = foam.copy_setup(DUST, os.path.join(BUILD, name))
    with open(os.path.join(case, "constant", "couplingType"), "w") as f:
        f.write("interphaseCoupling twoWayDirect;\n")
    foam.set_entry(case, "constant/dsmcProperties", "randomSeed", seed)
    foam.set_entry(case, "constant/grainsProperties", "subModels/twoWayDirectCoeffs",
                   f"{{ randomSeed {seed}; }}")
    foam.set_steps(case, STEPS)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case


def parallel(method):
    case = make(method, SEEDS[0])
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary;"
                " object decomposeParDict; }\nnumberOfSubdomains 2;\n"
                f"method {method};\n{COEFFS.get(method, '')}\n")
    foam.run_solver(case, np_=2)
    return case


def observables(case):
    t = foam.latest_time(case)
    grains = os.path.join(case, t, "lagrangian", "grains")
    gas = os.path.join(case, t, "lagrangian", "dsmc")
    U = foam.read_list(os.path.join(grains, "U"))
    T = foam.read_list(os.path.join(grains, "T"))
    Ug = foam.read_list(os.path.join(gas, "U"))
    return {"grain u_x": U[:, 0].mean(), "grain T": T.mean(),
            "simulators": float(len(Ug)), "gas u_x": Ug[:, 0].mean()}


def cloud_fields(case, cloud):
    path = os.path.join(case, foam.latest_time(case), "lagrangian", cloud)
    return sorted(f for f in os.listdir(path) if os.path.isfile(os.path.join(path, f)))


@pytest.fixture(scope="module")
def ensemble():
    cases = [make(f"serial{seed}", seed) for seed in SEEDS]
    for case in cases:
        foam.run(case, "rarefiedMultiphaseFoam")
    values = [observables(c) for c in cases]
    return cases[0], {k: np.array([v[k] for v in values]) for k in values[0]}


@pytest.mark.parametrize("method", METHODS)
def test_two_ranks(ensemble, method):
    serial, stats = ensemble
    case = parallel(method)
    failures = []
    print()

    # 1. every lagrangian field reconstructed, with every member
    for cloud in ("grains", "dsmc"):
        want, got = cloud_fields(serial, cloud), cloud_fields(case, cloud)
        if got != want:
            failures.append(f"{cloud}: fields {sorted(set(want) ^ set(got))} differ")
        t = foam.latest_time(case)
        n = len(foam.read_list(os.path.join(case, t, "lagrangian", cloud, "U")))
        for name in got:
            if name in ("positions", "coordinates"):
                continue
            m = len(foam.read_list(os.path.join(case, t, "lagrangian", cloud, name)))
            if m != n:
                failures.append(f"{cloud}/{name}: {m} entries for {n} members")
        print(f"{method}: {cloud} {n} members, {len(got)} fields reconstructed")

    # 2. nothing lost
    n0 = len(foam.read_list(os.path.join(case, "0", "lagrangian", "grains", "U")))
    n1 = len(foam.read_list(os.path.join(case, foam.latest_time(case), "lagrangian",
                                         "grains", "U")))
    if n1 != n0:
        failures.append(f"grain parcels {n0} -> {n1}")
    with open(os.path.join(case, "log.rarefiedMultiphaseFoam")) as f:
        if " lost" in f.read().lower():
            failures.append("the log reports lost members")

    # 3. the observables against the serial ensemble
    value = observables(case)
    for key, runs in stats.items():
        sigma = runs.std(ddof=1)*np.sqrt(1 + 1/len(runs))
        z = (value[key] - runs.mean())/max(sigma, 1e-300)
        ok = abs(z) < N_SIGMA
        print(f"{'PASS' if ok else 'FAIL'} {method} {key}: {value[key]:.6g} against"
              f" {runs.mean():.6g} +- {sigma:.3g} ({z:+.2f} sigma, tol {N_SIGMA})")
        if not ok:
            failures.append(f"{key} {z:+.2f} sigma")
    assert not failures, failures
