# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Bad input stops the programs with a FatalIOError that names the file, the
keyword, the bad value and the valid range or choices (end to end, on a copy
of tutorials/gas/impingingStream)."""

import os

import pytest

from rmf import foam
from rmf_testing import run_failing

TUTORIAL = os.path.join(foam.PROJECT_DIR, "tutorials", "gas", "impingingStream")
BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "gasInputErrors")


@pytest.fixture(scope="module")
def meshed():
    case = foam.copy_setup(TUTORIAL, os.path.join(BUILD, "meshed"))
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case


def with_entry(meshed, name, dict_path, entry, value):
    case = foam.copy_case(meshed, os.path.join(BUILD, name))
    foam.set_entry(case, dict_path, entry, value)
    return case


@pytest.mark.parametrize("app", ["rarefiedMultiphaseInitialise", "rarefiedMultiphaseFoam"])
def test_unknown_collision_model(meshed, app):
    case = with_entry(meshed, "unknownModel", "constant/dsmcProperties",
                      "BinaryCollisionModel", "HardSphereX")
    out = run_failing(case, app)
    for text in ("FOAM FATAL IO ERROR", "constant/dsmcProperties", "BinaryCollisionModel",
                 "HardSphereX", "VariableHardSphere", "LarsenBorgnakkeVariableHardSphere"):
        assert text in out, text


def test_negative_initial_density(meshed):
    case = with_entry(meshed, "negativeDensity", "system/dsmcInitialiseDict",
                      "numberDensities/N2", "-5e19")
    out = run_failing(case, "rarefiedMultiphaseInitialise")
    for text in ("FOAM FATAL IO ERROR", "system/dsmcInitialiseDict", "'N2'",
                 "-5e+19", "[0, inf)"):
        assert text in out, text


def test_negative_free_stream_density(meshed):
    """Upstream's FreeStream inflow (the tutorial's PatchInflow replaced)."""
    case = with_entry(meshed, "negativeFreeStream", "constant/dsmcProperties",
                      "InflowBoundaryModel", "FreeStream")
    foam.set_entry(case, "constant/dsmcProperties", "FreeStreamCoeffs",
                   "{ numberDensities { N2 -5e19; } }")
    out = run_failing(case, "rarefiedMultiphaseFoam")
    for text in ("FOAM FATAL IO ERROR", "constant/dsmcProperties", "'N2'", "-5e+19",
                 "[0, inf)"):
        assert text in out, text


def test_negative_weight(meshed):
    case = with_entry(meshed, "negativeWeight", "constant/dsmcProperties",
                      "nEquivalentParticles", "-6e11")
    out = run_failing(case, "rarefiedMultiphaseFoam")
    for text in ("FOAM FATAL IO ERROR", "constant/dsmcProperties",
                 "nEquivalentParticles", "-6e+11", "(0, inf)"):
        assert text in out, text


def test_no_phase(meshed):
    case = foam.copy_case(meshed, os.path.join(BUILD, "noPhase"))
    os.remove(os.path.join(case, "constant", "dsmcProperties"))
    out = run_failing(case, "rarefiedMultiphaseFoam")
    assert "Nothing to solve" in out and "dsmcProperties" in out


@pytest.mark.parametrize("app", ["rarefiedMultiphaseInitialise", "rarefiedMultiphaseFoam"])
def test_unknown_tracking(meshed, app):
    case = with_entry(meshed, "unknownTracking", GAS, "tracking", "straight")
    out = run_failing(case, app)
    for text in ("FOAM FATAL IO ERROR", GAS, "tracking", "straight", "cartesian",
                 "barycentric"):
        assert text in out, text


# Unknown and misspelt keywords: the message names the file, the keyword,
# the keyword meant and the valid ones.
# (name, dictionary, entry, value, apps, texts beyond the file and keyword)
GAS = "constant/dsmcProperties"
BOTH = ["rarefiedMultiphaseInitialise", "rarefiedMultiphaseFoam"]
KEYWORD_CASES = [
    ("topMisspelt", GAS, "randomEntrytime", "true", BOTH,
     ("did you mean 'randomEntryTime'", "maxRadialWeight")),
    ("speciesUnknown", GAS, "moleculeProperties/N2/omgea", "0.74", BOTH,
     ("did you mean 'omega'", "internalDegreesOfFreedom")),
    ("collisionCoeffsUnknown", GAS,
     "LarsenBorgnakkeVariableHardSphereCoeffs/relaxationNumber", "5", BOTH,
     ("valid keywords", "relaxationCollisionNumber")),
    ("initialiseMisspelt", "system/dsmcInitialiseDict", "temperatures", "300",
     ["rarefiedMultiphaseInitialise"], ("did you mean 'temperature'",)),
]


@pytest.mark.parametrize("name, path, entry, value, apps, texts", KEYWORD_CASES,
                         ids=[c[0] for c in KEYWORD_CASES])
def test_unknown_keyword(meshed, name, path, entry, value, apps, texts):
    case = with_entry(meshed, name, path, entry, value)
    for app in apps:
        out = run_failing(case, app)
        for text in ("FOAM FATAL IO ERROR", path,
                     "Unknown keyword '" + entry.split("/")[-1] + "'") + texts:
            assert text in out, (app, text)


# collisionSubSteps (the gas's bound majorants, sub-stepped per cell) and
# esBGK (the particle ES-BGK model in near-continuum cells), each added to
# the case: (name, dictionary added, entries set, texts beyond the file and
# the error's heading)
SUB_STEPS = ("collisionSubSteps", "{ collisionsPerSubStep 1; maxSubSteps 64; }")
BGK = ("esBGK", "{ switchAbove 20; switchBelow 10; }")
GAS_MODEL_CASES = [
    ("subStepsPerStepZero", SUB_STEPS, (("collisionSubSteps/collisionsPerSubStep", "0"),),
     ("collisionsPerSubStep", "value: 0", "(0, inf)")),
    ("subStepsCapZero", SUB_STEPS, (("collisionSubSteps/maxSubSteps", "0"),),
     ("maxSubSteps", "value: 0", "[1, 100000]")),
    ("subStepsUnknown", SUB_STEPS, (("collisionSubSteps/maxSubStep", "5"),),
     ("Unknown keyword 'maxSubStep'", "maxSubSteps")),
    ("subStepsBarycentric", SUB_STEPS, (("tracking", "barycentric"),),
     ("tracking", "barycentric", "cartesian (the default) with collisionSubSteps")),
    ("subStepsNoCollisions", SUB_STEPS, (("BinaryCollisionModel", "NoBinaryCollision"),),
     ("BinaryCollisionModel", "NoBinaryCollision", "LarsenBorgnakkeVariableSoftSphere")),
    ("bgkAboveZero", BGK, (("esBGK/switchAbove", "0"),),
     ("switchAbove", "value: 0", "(0, inf)")),
    ("bgkBelowAbove", BGK, (("esBGK/switchBelow", "20"),),
     ("switchBelow", "value: 20", "(0, switchAbove = 20)")),
    ("bgkUnknown", BGK, (("esBGK/switchBelw", "5"),),
     ("Unknown keyword 'switchBelw'", "switchBelow")),
    ("bgkBarycentric", BGK, (("tracking", "barycentric"),),
     ("tracking", "barycentric", "cartesian (the default) with esBGK")),
    ("bgkMixture", BGK, (("moleculeProperties/O2", "{ mass 53.12e-27; diameter 4.07e-10; "
                          "internalDegreesOfFreedom 2; omega 0.77; }"),
                         ("typeIdList", "(N2 O2)")),
     ("typeIdList", "one species with esBGK")),
    ("bgkVibration", BGK, (("moleculeProperties/N2/vibrationalModes",
                            "{ stretch { temperature 3371; } }"),
                           ("moleculeProperties/N2/vibrationalRelaxationCollisionNumber", "20"),
                           ("BinaryCollisionModel", "LarsenBorgnakkeVariableSoftSphere"),
                           ("LarsenBorgnakkeVariableSoftSphereCoeffs",
                            "{ Tref 273; alpha { N2 1; } relaxationCollisionNumber 5; }")),
     ("vibrationalModes", "none with esBGK")),
]


@pytest.mark.parametrize("name, added, entries, texts", GAS_MODEL_CASES,
                         ids=[c[0] for c in GAS_MODEL_CASES])
def test_gas_collision_options(meshed, name, added, entries, texts):
    case = with_entry(meshed, name, GAS, *added)
    for entry, value in entries:
        foam.set_entry(case, GAS, entry, value)
    out = run_failing(case, "rarefiedMultiphaseFoam")
    for text in ("FOAM FATAL IO ERROR", GAS) + texts:
        assert text in out, text
