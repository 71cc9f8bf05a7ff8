#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Regression checks of tutorials/gas/impingingStream (run by Allrun and by
test_impingingStream.py); prints PASS/FAIL lines with the measured figures.

1. Inflow rate (analytic).  PatchInflow inserts, per face and step, the
   one-sided number flux of a drifting Maxwellian (Bird 1994, eq. 4.22):
       Gamma = n c_mp/(2 sqrt(pi)) [exp(-s^2) + sqrt(pi) s (1 + erf(s))],
   c_mp = sqrt(2 k T/m), s = (U . n_in)/c_mp, divided by nEquivalentParticles;
   the fraction is carried over in a per-face accumulator.  So the mean
   number inserted per step must equal sum(Gamma A) dt / W within
   (number of inflow faces)/(steps): the accumulators' carry.
2. Account of simulators (exact): in every step, the simulators entering by
   the balance (present - present before + removed at patches) equal
   PatchInflow's own count of insertions.
3. Surface loads (reduced settings only, against a stored reference):
   normal force and heat load on the surface from fDMean and qMean, within
   the prediction interval of reference.json, made by make_reference.py from
   an ensemble of runs with randomSeed 1..K (Student t, alpha = 1e-3).

Usage: check.py [CASE]   (default: this directory)
"""

import json
import math
import os
import sys

import numpy as np
from scipy import stats as sstats

from rmf import foam

K_B = 1.380649e-23
HERE = os.path.dirname(os.path.abspath(__file__))

# Geometry (system/blockMeshDict): surface 0.4 m x 5 mm in 80 equal faces;
# inflow patch freeStream: top 0.4 m wide, two sides 0.2 m high, 5 mm thick
THICKNESS = 0.005
SURFACE_AREA = 0.4*THICKNESS
INFLOW = (  # (area, inward unit normal, number of faces)
    (0.4*THICKNESS, np.array([0.0, -1.0, 0.0]), 80),
    (0.2*THICKNESS, np.array([1.0, 0.0, 0.0]), 40),
    (0.2*THICKNESS, np.array([-1.0, 0.0, 0.0]), 40),
)


def one_sided_flux(n, T, U, m, normal):
    c_mp = math.sqrt(2*K_B*T/m)
    s = float(U @ normal)/c_mp
    return n*c_mp/(2*math.sqrt(math.pi))*(
        math.exp(-s*s) + math.sqrt(math.pi)*s*(1 + math.erf(s)))


def surface_loads(case, time):
    fD = foam.read_patch_field(os.path.join(case, time, "fDMean"), "surface")
    q = foam.read_patch_field(os.path.join(case, time, "qMean"), "surface")
    return {"normal force [N]": float(-fD[:, 1].mean()*SURFACE_AREA),
            "heat load [W]": float(q.mean()*SURFACE_AREA)}


def checks(case):
    results = []
    log = os.path.join(case, "log.rarefiedMultiphaseFoam")

    props = "constant/dsmcProperties"
    W = float(foam.get_entry(case, props, "nEquivalentParticles"))
    m = float(foam.get_entry(case, props, "moleculeProperties/N2/mass"))
    inflow = "PatchInflowCoeffs/freeStream/"
    n = float(foam.get_entry(case, props, inflow + "n"))
    T = float(foam.get_entry(case, props, inflow + "T"))
    U = np.array(foam.get_entry(case, props, inflow + "U").strip("()").split(), float)
    dt = float(foam.get_entry(case, "system/controlDict", "deltaT"))

    step = foam.log_values(log, "Simulators in / out this step")
    expected = sum(one_sided_flux(n, T, U, m, nrm)*A for A, nrm, _ in INFLOW)*dt/W
    measured = step[:, 0].mean()
    tol = sum(f for _, _, f in INFLOW)/len(step)
    results.append(("inflow per step", abs(measured - expected) <= tol,
                    f"{measured:.4f} vs analytic {expected:.4f} (tol {tol:.4f})"))

    # Our count of simulators entering is the balance (present now - present
    # before + removed at patches): it equals PatchInflow's own count of
    # insertions only if no simulator left uncounted
    inserted = foam.log_values(log, "Simulators inserted through freeStream")[:, 0]
    mismatch = int(np.sum(inserted != step[:, 0]))
    results.append(("account of simulators", mismatch == 0 and len(inserted) == len(step),
                    f"{mismatch} of {len(step)} steps where entered != inserted"
                    f" ({inserted.sum():.0f} inserted, {step[:, 1].sum():.0f} removed)"))

    reference = os.path.join(HERE, "reference.json")
    time = foam.latest_time(case)
    with open(reference) as f:
        ref = json.load(f)
    if time in ref:
        loads = surface_loads(case, time)
        K = len(ref[time]["runs"])
        t = sstats.t.ppf(1 - 1e-3/2, K - 1)
        for name, value in loads.items():
            runs = np.array([r[name] for r in ref[time]["runs"]])
            tol = t*runs.std(ddof=1)*math.sqrt(1 + 1/K)
            results.append((name, abs(value - runs.mean()) <= tol,
                            f"{value:.5g} vs reference {runs.mean():.5g} (tol {tol:.3g})"))
    return results


def main():
    case = sys.argv[1] if len(sys.argv) > 1 else "."
    failed = 0
    for name, ok, text in checks(case):
        print(f"{'PASS' if ok else 'FAIL'} {name}: {text}")
        failed += not ok
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
