# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The model families of the restart and parallel tests: per family a
small case made, meshed and initialised in dst on np_ ranks with a seed,
and its steps N (FAMILIES).  validation/exactRestart runs each whole and
split, validation/parallelEquivalence on ranks against serial runs,
validation/badKeywords tries their set-up's keywords."""

import os
import re
import shutil

import numpy as np

from rmf import dem as dem_box
from rmf import foam

ROOT = foam.PROJECT_DIR
CONTROL = "system/controlDict"
GRAINS = "constant/grainsProperties"
SNIDER = os.path.join(ROOT, "tutorials", "solids", "sniderSedimentation")
DUST = os.path.join(ROOT, "tutorials", "coupling", "dustCloudStream")
GAS_WEDGE = os.path.join(ROOT, "validation", "axisymmetricGas", "wedge")
GRAIN_WEDGE = os.path.join(ROOT, "validation", "axisymmetricGrains", "wedge")
GRANULAR = os.path.join(ROOT, "validation", "grainCollisions", "granularGas")
DEM_BOX = os.path.join(ROOT, "validation", "demContacts", "box")


def set_entries(case, entries):
    for path, entry, value in entries:
        foam.set_entry(case, path, entry, value)


def _seed(case, seed):
    """Seed every stream the case has: the gas and its fill, the grain
    fill, the grain cloud's own stream, NTC hard spheres and the two-way
    coupling (seed None: the case's own seeds)."""
    if seed is None:
        return
    for path in ("constant/dsmcProperties", "system/dsmcInitialiseDict",
                 "system/grainsInitialiseDict", GRAINS):
        if os.path.exists(os.path.join(case, path)):
            foam.set_entry(case, path, "randomSeed", seed)
    if not os.path.exists(os.path.join(case, GRAINS)):
        return
    models = foam.dict_text(os.path.join(case, GRAINS))
    if re.search(r"stochasticCollisionModel\s+NTCHardSphere\s*;", models):
        foam.set_entry(case, GRAINS, "subModels/NTCHardSphereCoeffs/randomSeed", seed)
    coupling = os.path.join(case, "constant", "couplingType")
    if os.path.exists(coupling):
        models += foam.dict_text(coupling)
    for kind in ("twoWayDirect", "twoWayIndirect"):
        if re.search(rf"interphaseCoupling\s+{kind}\s*;", models):
            foam.set_entry(case, GRAINS, f"subModels/{kind}Coeffs", f"{{ randomSeed {seed}; }}")


def _mesh_and_fill(case, np_=1, seed=None):
    _seed(case, seed)
    foam.set_entry(case, CONTROL, "writeFormat", "binary")
    foam.set_entry(case, CONTROL, "functions", "{}")
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    if np_ > 1:
        with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class dictionary;"
                    f" object decomposeParDict; }}\nnumberOfSubdomains {np_};\n"
                    "method metis;\n")
        foam.run(case, "decomposePar")
    return case


# Model families: name -> (make the case in dst on np_ ranks with seed,
# steps N)

def gas(dst, np_, seed=None):
    """Gas alone: dsmcFoam's freeSpacePeriodic, own stream (randomSeed)."""
    case = foam.copy_case(foam.dsmc_tutorial("freeSpacePeriodic"), dst)
    foam.set_entry(case, "constant/dsmcProperties", "randomSeed", 1)
    return _mesh_and_fill(case, np_, seed)


def snider(dst, np_, seed=None, hybrid=False):
    """Grains, MPPIC: the Snider tutorial's models (twoSided packing,
    relaxation damping, cachedDual), 20 000 parcels (every model acts on
    every parcel each step), isotropy restartableStochastic.  Upstream's
    stochastic isotropy keeps the second of its Gaussian pair in
    function-static variables, not in the cloud's stream: every run starts
    with a cached sample of 0, so a restart draws differently
    (doc/physics.md#restart, test_stochastic_isotropy_not_exact)."""
    case = foam.copy_setup(SNIDER, dst)
    set_entries(case, [("system/grainsInitialiseDict", "regions/column/nParcels", 20000)])
    _isotropy(case, "restartableStochastic")
    if hybrid:
        set_entries(case, [(GRAINS, "subModels/stochasticCollisionModel", "NTCHardSphere"),
                    (GRAINS, "subModels/NTCHardSphereCoeffs/alphaSwitch", 0.1),
                    (GRAINS, "subModels/NTCHardSphereCoeffs/randomSeed", 2)])
    return _mesh_and_fill(case, np_, seed)


def _isotropy(case, model):
    """Set the isotropy model, with the tutorial's coefficients (those of
    its restartableStochastic, the same keywords as upstream's stochastic)."""
    coeffs = foam.get_entry(case, GRAINS, "subModels/restartableStochasticCoeffs")
    set_entries(case, [(GRAINS, "subModels/isotropyModel", model),
                (GRAINS, f"subModels/{model}Coeffs", coeffs)])


def ntc(dst, np_, seed=None):
    """Grains, NTC hard spheres alone: the homogeneous cooling dem_box."""
    case = foam.copy_setup(GRANULAR, dst)
    return _mesh_and_fill(case, np_, seed)


def dem(dst, np_, seed=None):
    """Grains, soft-sphere DEM (pairCollision, contact springs in the
    parcels' collision records): 108 grains in a box of 1 cm under
    gravity, random velocities of 0.1 m/s, so that contacts last across
    the restart.  DEM draws nothing: seed (default 1) sets the grains'
    initial positions and velocities, so two runs of one seed are the same
    run (validation/parallelEquivalence compares its 2-rank run with the
    serial run of the same seed directly, not with a seed ensemble)."""
    seed = 1 if seed is None else seed
    case = foam.copy_setup(DEM_BOX, dst)
    rng = np.random.default_rng(seed + 2)
    side = dem_box.L
    n = 6
    grid = (np.arange(n) + 0.5)*side/n
    xs = np.array([(x, y, z) for x in grid for y in grid[:3] for z in grid])
    xs = xs + rng.uniform(-0.2, 0.2, xs.shape)*dem_box.D
    dem_box.write_grains(case, {"grains": (xs, (0, 0, 0), 0.1)}, seed=seed + 3)
    dt = dem_box.contact_time(0.8, dem_box.MASS/2)/20
    set_entries(case, [(CONTROL, "deltaT", f"{dt:.17g}")])
    return _mesh_and_fill(case, np_)


def coupled(dst, np_, coupling, seed=None):
    """Gas and grains: the dustCloudStream tutorial (PatchInflow, whose
    carried fractions are written) with one interphaseCoupling type.  The two-way types weigh each parcel 1e6 grains: with
    the tutorial's single grains the expected gas-grain collisions are
    1e-7 per step and the gas is left as oneWay leaves it; at 1e6 some 90
    collide per step and some cells are sub-cycled (up to 3 sub-steps)."""
    case = foam.copy_setup(DUST, dst)
    with open(os.path.join(case, "constant", "couplingType"), "w") as f:
        f.write(f"interphaseCoupling {coupling};\n")
    if coupling.startswith("twoWay"):
        set_entries(case, [("system/grainsInitialiseDict", "regions/cloud/nParticle", 1e6)])
    set_entries(case, [("constant/dsmcProperties", "randomSeed", 1)])
    return _mesh_and_fill(case, np_, seed)


def wedge(dst, np_, seed=None, extra=()):
    """Axisymmetric, radially weighted gas (maxRadialWeight 10) and grains
    (weighted parcels, their clone/delete stream), two-way direct coupling:
    the argon wedge of validation/axisymmetricGas at rest inside a wall,
    with the grains of validation/axisymmetricGrains (extra: more entries
    (file, entry, value))."""
    case = foam.copy_setup(GAS_WEDGE, dst)
    for sub in (GRAINS, "constant/g", "system/grainsInitialiseDict"):
        shutil.copy(os.path.join(GRAIN_WEDGE, sub), os.path.join(case, sub))
    foam.run(case, "foamDictionary", "-entry", "subModels/interphaseCoupling", "-add",
             "twoWayDirect", GRAINS, log="log.foamDictionary")
    set_entries(case, [("constant/dsmcProperties", "randomSeed", 1),
                ("system/grainsInitialiseDict", "regions/cloud/d", 1e-5),
                ("system/grainsInitialiseDict", "regions/cloud/alpha0", 1e-6),
                ("system/grainsInitialiseDict", "regions/cloud/nParcels", 2000)]
         + list(extra))
    return _mesh_and_fill(case, np_, seed)


def sub_stepped(dst, np_, seed=None):
    """The wedge with the gas's bound majorants sub-stepped per cell
    (collisionSubSteps), a sub-step per 0.01 collisions so that its cells
    take several and the cap (4) is met: the sub-steps' per-cell state
    goes through a restart."""
    return wedge(dst, np_, seed, extra=[
        ("constant/dsmcProperties", "collisionSubSteps",
         "{ collisionsPerSubStep 0.01; maxSubSteps 4; }")])


def bgk(dst, np_, seed=None):
    """The wedge with the particle ES-BGK model in its cells of collision
    number above 0.17 (back to DSMC below 0.13; the gas's mean is 0.15): some cells are BGK, some
    DSMC, and some switch; the cells' model goes through a restart."""
    return wedge(dst, np_, seed, extra=[
        ("constant/dsmcProperties", "esBGK", "{ switchAbove 0.17; switchBelow 0.13; }")])


def vibrating(dst, np_, seed=None):
    """The wedge with vibrational levels (doc/physics.md#vibration): the argon
    given two fictitious oscillators (400 K, degeneracy 2; Z_v 2) that
    the fill, FreeStream's inflow, the diffuse walls, the grains'
    re-emission and the collisions all draw, exchanged by the
    Larsen-Borgnakke form."""
    gas, coeffs = "constant/dsmcProperties", "LarsenBorgnakkeVariableSoftSphereCoeffs"
    ar = "moleculeProperties/Ar"
    return wedge(dst, np_, seed, [
        (gas, "BinaryCollisionModel", "LarsenBorgnakkeVariableSoftSphere"),
        (gas, coeffs, "{ Tref 273; alpha { Ar 1; } relaxationCollisionNumber 5; }"),
        (gas, f"{ar}/vibrationalModes", "{ mode { temperature 400; degeneracy 2; } }"),
        (gas, f"{ar}/vibrationalRelaxationCollisionNumber", 2)])


FAMILIES = {
    "gas": (gas, 10),
    "mppic": (snider, 5),
    "hybrid": (lambda d, n, seed=None: snider(d, n, seed, hybrid=True), 5),
    "ntc": (ntc, 5),
    "dem": (dem, 10),
    "oneWay": (lambda d, n, seed=None: coupled(d, n, "oneWay", seed), 5),
    "twoWayDirect": (lambda d, n, seed=None: coupled(d, n, "twoWayDirect", seed), 5),
    "twoWayIndirect": (lambda d, n, seed=None: coupled(d, n, "twoWayIndirect", seed), 5),
    "Loth": (lambda d, n, seed=None: coupled(d, n, "Loth", seed), 5),
    "adaptive": (lambda d, n, seed=None: coupled(d, n, "adaptive", seed), 5),
    "axisymmetric": (wedge, 5),
    "subSteps": (lambda d, n, seed=None: sub_stepped(d, n, seed), 5),
    "esBGK": (lambda d, n, seed=None: bgk(d, n, seed), 5),
    "vibration": (vibrating, 5),
    "upstreamIsotropy": (lambda d, n: _upstream_isotropy(d, n), 5),
}


def _upstream_isotropy(dst, np_):
    """MPPIC with upstream's stochastic isotropy."""
    case = snider(dst, np_)
    _isotropy(case, "stochastic")
    return case
