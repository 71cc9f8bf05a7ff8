#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""What a model costs when it is switched on, against the same scene with
it off (doc/speed-accuracy.md, "What each model costs"): the grain-
collision models on a settling column, and the axisymmetric mode and its
radial weighting on a gas wedge.  The coupling models and the dormant
phases are bench/couplingCost's; the gas against stock dsmcFoam is
bench/dsmcParity's.

Scenes (each serially on one rank, on a fresh copy; CPU time user+sys of
the solver process):
  column   the Snider tutorial's set-up (glass beads of 0.3 mm, parcels
           of 749 beads, cachedDual averaging, dt = 1 ms) in a column of
           5 x 5 of its cells (0.046 m square, 40 layers), 18 026 parcels
           (the tutorial's alpha_0), --steps steps of the sedimentation
           from the start.  Settings:
             none     no packing, damping, isotropy or grain collisions
             NTC      NTC hard spheres alone
             MPPIC    the tutorial's: twoSided packing, relaxation
                      damping, stochastic isotropy
             explicit the same with v1912's explicit packing
             hybrid   MPPIC + NTC below alpha 0.1
  wedge    validation/axisymmetricGas/wedge: argon at rest, 1e20 m^-3,
           300 K, in a 2.5 degree wedge of 10 x 10 cells, --steps steps
           (after its fill).  Settings:
             planar      axisymmetric false on a 2-D planar mesh of the
                         same 10 x 10 cells (the meridional rectangle, one
                         cell of the wedge's volume thick, empty front and
                         back, the axis a symmetry plane): as many
                         simulators, moved in the plane
             axisymmetric  the axisymmetric move (rotated back into the
                           meridional plane), no radial weighting
             weighted    and radial weighting, maxRadialWeight 10
           The weighting changes the number of simulators (a sixth of
           them here), so the wedge's costs are per simulator-step (the
           simulators of each step from the log); the total CPU times
           are printed per repetition.
A repetition runs every setting of both scenes once, one after another;
the repetitions alternate so that the machine's load falls on all alike.
Printed per setting: the minimum over the repetitions and, as the ratio
to the scene's "off" setting (none; planar), the ratio of the minima and
the standard deviation of the repetitions' own ratios (the noise).

    . etc/bashrc && bench/modelCost/bench.py [--steps N] [--repeat R]

Defaults: 200 steps, 3 repetitions (about 6 minutes).
"""

import argparse
import math
import os
import re
import resource
import statistics
import sys

from rmf import foam, snider

BUILD = os.path.join(foam.PROJECT_DIR, "build", "bench", "modelCost")
WEDGE = os.path.join(foam.PROJECT_DIR, "validation", "axisymmetricGas", "wedge")
PROPS = "constant/grainsProperties"
GAS = "constant/dsmcProperties"
CELLS = 5                               # the column: 5 x 5 of the tutorial's 15 x 15
OFF = {"subModels/packingModel": "none", "subModels/dampingModel": "none",
       "subModels/isotropyModel": "none", "subModels/stochasticCollisionModel": "none"}
NTC = {"subModels/stochasticCollisionModel": "NTCHardSphere"}
COLUMN = {
    "none": OFF,
    "NTC": {**OFF, **NTC},
    "MPPIC": {},
    "explicit": {"subModels/packingModel": "explicit"},
    "hybrid": {**NTC, "subModels/NTCHardSphereCoeffs/alphaSwitch": 0.1},
}
WEDGE_SETTINGS = {
    "planar": {"axisymmetric": "false"},
    "axisymmetric": {"maxRadialWeight": 1},
    "weighted": {},
}


def column_init():
    case, _ = snider.narrow_column(os.path.join(BUILD, "column_init"), CELLS)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case


PLANAR_MESH = """FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
// The wedge's meridional rectangle as a 2-D planar mesh: the same 10 x 10
// cells, one cell thick, of the wedge's volume (thickness R tan(1.25 deg))
scale 1;
vertices ((0 0 -{h}) (0.05 0 -{h}) (0.05 0.05 -{h}) (0 0.05 -{h})
          (0 0 {h}) (0.05 0 {h}) (0.05 0.05 {h}) (0 0.05 {h}));
blocks (hex (0 1 2 3 4 5 6 7) (10 10 1) simpleGrading (1 1 1));
boundary
(
    outer {{ type wall; faces ((3 7 6 2)); }}
    ends {{ type wall; faces ((0 4 7 3) (1 2 6 5)); }}
    front {{ type empty; faces ((0 3 2 1)); }}
    back {{ type empty; faces ((4 5 6 7)); }}
    axis {{ type symmetryPlane; faces ((0 1 5 4)); }}
);
"""


def wedge_init(name, entries):
    """The wedge meshed and filled for one setting (the fill depends on
    the weighting); planar: PLANAR_MESH, its axis a symmetry plane."""
    case = foam.copy_setup(WEDGE, os.path.join(BUILD, f"{name}_init"))
    if name == "planar":
        with open(os.path.join(case, "system", "blockMeshDict"), "w") as f:
            f.write(PLANAR_MESH.format(h=0.5*0.05*math.tan(math.radians(1.25))))
        for field in os.listdir(os.path.join(case, "0")):
            path = os.path.join(case, "0", field)
            with open(path) as f:
                text = f.read()
            text = re.sub(r"(axis\s*\{\s*type\s+)empty;", r"\1symmetryPlane;", text)
            with open(path, "w") as f:
                f.write(re.sub(r"type\s+wedge;", "type empty;", text))
        for key in ("radialExtent", "maxRadialWeight"):
            foam.remove_entry(case, GAS, key)
    for entry, value in entries.items():
        foam.set_entry(case, GAS, entry, value)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case


def variant(init, name, steps, entries, props):
    case = foam.copy_case(init, os.path.join(BUILD, name))
    foam.set_steps(case, steps)
    for entry, value in entries.items():
        foam.set_entry(case, props, entry, value)
    return case


def timed(case):
    """CPU time [s] of one solver run, and its log."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    log = foam.run(case, "rarefiedMultiphaseFoam")
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime, log


def simulator_steps(log):
    """Sum over the steps of the gas simulators moved (the log's count)."""
    with open(log) as f:
        counts = re.findall(r"Number of dsmc particles\s*=\s*(\d+)", f.read())
    return sum(int(c) for c in counts)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    if "FOAM_TUTORIALS" not in os.environ:
        sys.exit("bench modelCost: no OpenFOAM environment (. etc/bashrc first)")
    column = column_init()
    wedges = {name: wedge_init(name, entries) for name, entries in WEDGE_SETTINGS.items()}
    print(f"bench modelCost: {args.steps} steps, {args.repeat} repetitions, serial, in "
          f"{BUILD}; load average {os.getloadavg()[0]:.2f}", flush=True)

    cost = {("column", n): [] for n in COLUMN}
    cost.update({("wedge", n): [] for n in WEDGE_SETTINGS})
    for rep in range(1, args.repeat + 1):
        line = []
        for name, entries in COLUMN.items():
            cpu, _ = timed(variant(column, f"column_{name}{rep}", args.steps, entries, PROPS))
            cost["column", name].append(cpu)
            line.append(f"{name} {cpu:.2f} s")
        for name, init in wedges.items():
            cpu, log = timed(variant(init, f"wedge_{name}{rep}", args.steps, {}, GAS))
            moved = simulator_steps(log)
            cost["wedge", name].append(1e6*cpu/moved)
            line.append(f"{name} {cpu:.2f} s, {1e6*cpu/moved:.3f} us/simulator-step "
                        f"({moved/args.steps:.0f} simulators)")
        print(f"  repetition {rep} (CPU): " + ", ".join(line), flush=True)

    summary = []
    for scene, off, unit in (("column", "none", "s"), ("wedge", "planar", "us/simulator-step")):
        base = cost[scene, off]
        for (s, name), values in cost.items():
            if s != scene:
                continue
            ratios = [v/b for v, b in zip(values, base)]
            sd = statistics.stdev(ratios) if len(ratios) > 1 else float("nan")
            ratio = min(values)/min(base)
            print(f"  {scene} {name}: {min(values):.4g} {unit} (minimum), ratio to {off} "
                  f"{ratio:.3f} (repetitions' sd {sd:.3f})")
            if name != off:
                summary.append(f"{scene} {name} {ratio:.3f} +- {sd:.3f}")
    print("bench modelCost (CPU, ratio to the scene with the model off): " + ", ".join(summary))


if __name__ == "__main__":
    main()
