# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Solid parcels survive a restart with every property,
and zonalGravity switches gravity off inside a cellZone.

A dilute copy of the Snider set-up (2000 parcels, alpha ~ 0.004) falls
freely in vacuum with every MPPIC model off: run to 2 ms, stop, restart
from the written state to 4 ms.  Expected exactly (Euler integration of a
constant acceleration is exact):
- every parcel that has not reached the floor moves at U_z = -g t =
  -0.0392 m/s (velocity read back at the restart),
- every parcel keeps the initial temperature 350 K given by the
  initialisation dictionary, which differs from constantProperties/T0 =
  300 K (temperature read back, not reset), and Cp, specular fraction and
  accommodation of constantProperties,
- no parcel is gained or lost.

Family-wise error: the module's two counts of randomly placed parcels
(the initialiser's randomSeed, rmf_testing.seed(1)) are bounded by their
distributions: at most 5 of the 2000 parcels off free fall at 4 ms,
where a Poisson count of mean 0.65 (the parcels within the 98 um the
explicit steps fall of the floor) exceeds 5 with probability 6.2e-5;
the resting share of test_zonal_gravity within 0.05 of 0.5, 4.5
binomial sd (two-sided 7.7e-6).  Together 7e-5, within
rmf_testing.MODULE_ALPHA (2.5e-4).  Everything else is exact."""

import os

import numpy as np

from rmf import foam
from rmf_testing import seed

TUTORIAL = os.path.join(foam.PROJECT_DIR, "tutorials", "solids", "sniderSedimentation")
BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "solidRestart")
INIT = "system/grainsInitialiseDict"
PROPS = "constant/grainsProperties"
G = 9.8
N = 2000


def parcel(case, time, name):
    return foam.read_list(os.path.join(case, time, "lagrangian", "grains", name))


def test_restart_keeps_parcel_state():
    case = foam.copy_setup(TUTORIAL, BUILD)
    foam.set_entry(case, INIT, "randomSeed", seed(1))
    foam.set_entry(case, INIT, "regions/column/nParcels", N)
    foam.set_entry(case, INIT, "regions/column/T0", 350)
    for model in ("packingModel", "dampingModel", "isotropyModel"):
        foam.set_entry(case, PROPS, "subModels/" + model, "none")
    foam.set_entry(case, "system/controlDict", "writeInterval", 0.001)
    foam.set_entry(case, "system/controlDict", "endTime", 0.002)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    foam.run(case, "rarefiedMultiphaseFoam", log="log.first")
    foam.set_entry(case, "system/controlDict", "endTime", 0.004)
    foam.run(case, "rarefiedMultiphaseFoam", log="log.restart")

    with open(os.path.join(case, "log.restart")) as f:
        assert "Time = 0.003" in f.read()      # it did restart at 2 ms

    Uz = parcel(case, "0.004", "U")[:, 2]
    assert len(Uz) == N
    falling = np.abs(Uz + G*0.004) < 1e-12
    # Within 4 ms a parcel falls at most 98 um: a Poisson count of mean 0.65
    # touches the floor (module docstring)
    assert falling.sum() >= N - 5, f"{N - falling.sum()} parcels off free fall"
    assert np.all(parcel(case, "0.004", "T") == 350)
    assert np.all(parcel(case, "0.004", "Cp") == 840)
    assert np.all(parcel(case, "0.004", "specularFraction") == 0)
    assert np.all(parcel(case, "0.004", "thermalAccommodation") == 1)


def test_zonal_gravity():
    """zonalGravity: parcels inside the cellZone (upper half of the column)
    stay at rest; the others fall at U_z = -g t exactly (3 steps)."""
    case = foam.copy_setup(TUTORIAL, BUILD + "Zonal")
    foam.set_entry(case, INIT, "randomSeed", seed(1))
    foam.set_entry(case, INIT, "regions/column/nParcels", N)
    for model in ("packingModel", "dampingModel", "isotropyModel"):
        foam.set_entry(case, PROPS, "subModels/" + model, "none")
    foam.set_entry(case, PROPS, "subModels/particleForces",
                   "{ zonalGravity { zeroGravityZone upper; } }")
    with open(os.path.join(case, "system", "topoSetDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary;"
                " object topoSetDict; }\n"
                "actions ( { name upper; type cellZoneSet; action new;"
                " source boxToCell; box (-1 -1 0.15) (1 1 1); } );\n")
    foam.set_steps(case, 3)
    foam.run(case, "blockMesh")
    foam.run(case, "topoSet")
    foam.run(case, "rarefiedMultiphaseInitialise")
    foam.run(case, "rarefiedMultiphaseFoam")

    t = foam.latest_time(case)
    Uz = parcel(case, t, "U")[:, 2]
    assert len(Uz) == N
    resting = Uz == 0
    falling = np.abs(Uz + G*0.003) < 1e-12
    assert np.all(resting | falling)
    # The zone is half the column (20 of 40 layers): resting fraction 0.5,
    # binomial sd 0.011 for 2000 parcels; tolerance 0.05 (4.5 sd)
    assert abs(resting.mean() - 0.5) < 0.05, resting.mean()
