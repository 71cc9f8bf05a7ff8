# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Bad solid-phase input stops the initialiser and the
solver with a FatalIOError naming the file, the keyword, the bad value and
the valid range or choices (end to end, on a copy of the Snider tutorial's
set-up, with a small parcel count so that the good case starts at once).

Each expected text is matched whole (expect): keywords as the message
quotes them ('e'), the bad value on the message's "value:" line
(value: 0), the valid range or choice on its "valid:" line, and a text
that begins or ends with a letter or digit only where no letter, digit
or '-' continues it (nor a '.' that continues a number), so that an
expected e, d, 0 or 1 is not found inside another word or number.

Deterministic: no statistical comparison."""

import os
import re
import subprocess

import pytest

from rmf import foam
from rmf_testing import run_failing, set_in_list

TUTORIAL = os.path.join(foam.PROJECT_DIR, "tutorials", "solids", "sniderSedimentation")
BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "solidInputErrors")
PROPS = "constant/grainsProperties"
INIT = "system/grainsInitialiseDict"
REGION = "regions/column/"
BOTH = ["rarefiedMultiphaseInitialise", "rarefiedMultiphaseFoam"]


@pytest.fixture(scope="module")
def meshed():
    case = foam.copy_setup(TUTORIAL, os.path.join(BUILD, "meshed"))
    foam.set_entry(case, INIT, REGION + "nParcels", 2000)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case


def with_entry(meshed, name, dict_path, entry, value, remove=None):
    case = foam.copy_case(meshed, os.path.join(BUILD, name))
    if "/patches/" in entry:
        # A dictionary of a list, which foamDictionary cannot address
        *_, block, keyword = entry.split("/")
        set_in_list(os.path.join(case, dict_path), "patches", block, keyword, value)
    else:
        foam.set_entry(case, dict_path, entry, value)
    if remove:
        subprocess.run(["foamDictionary", "-entry", remove, "-remove", dict_path],
                       cwd=case, check=True, stdout=subprocess.DEVNULL)
    return case


def whole(text, out):
    """text in out, not inside another word or number (module docstring)."""
    before = r"(?<![\w-])(?<!\d\.)" if re.match(r"\w", text) else ""
    after = r"(?!\w|\.\d)" if re.search(r"\w$", text) else ""
    return re.search(before + re.escape(text) + after, out) is not None


def expect(out, *texts, valid=None):
    """Each of texts in out whole, and valid on a "valid:" line."""
    for text in ("FOAM FATAL IO ERROR",) + texts:
        assert whole(text, out), text
    if valid is not None:
        lines = re.findall(r"(?m)^\s*valid: (.*)$", out)
        assert any(whole(valid, line) for line in lines), f"valid: ... {valid}"


def quoted(keyword):
    return f"'{keyword}'"


def named(keyword, value):
    """The keyword and the bad value as a FatalIOError of inputChecks
    names them."""
    return quoted(keyword), f"value: {value}"


# Cloud dictionary: both programs check it before anything is read.
# (entry, bad value, texts of the message beyond file, keyword and value)
CLOUD_CASES = [
    ("alphaPacked", "subModels/twoSidedCoeffs/particleStressModel/alphaPacked",
     "1", "(0, 1)"),
    ("pSolid", "subModels/twoSidedCoeffs/particleStressModel/pSolid", "0", "(0, inf)"),
    ("wallRestitution", "subModels/localInteractionCoeffs/patches/sides/e", "1.2",
     "[0, 1]"),
    ("collisionRestitution", "subModels/restartableStochasticCoeffs/timeScaleModel/e", "-0.1",
     "[0, 1]"),
    ("density", "constantProperties/rho0", "-2500", "(0, inf)"),
    ("specularFraction", "constantProperties/specularFraction", "1.5", "[0, 1]"),
    ("thermalAccommodation", "constantProperties/thermalAccommodation", "-0.1",
     "[0, 1]"),
    ("specularFractionNegative", "constantProperties/specularFraction", "-0.2",
     "[0, 1]"),
    ("thermalAccommodationHigh", "constantProperties/thermalAccommodation", "1.01",
     "[0, 1]"),
    ("packingModel", "subModels/packingModel", "explicitX", "implicit"),
    ("stressModel", "subModels/twoSidedCoeffs/particleStressModel/type", "Harris",
     "HarrisCrighton"),
    ("averaging", "solution/averagingMethod", "triple", "dual"),
    ("packingRestitution", "subModels/twoSidedCoeffs/e", "1.5", "[0, 1]"),
    ("packingRelief", "subModels/twoSidedCoeffs/relief", "2", "[0, 1]"),
    ("packingSmoothing", "subModels/twoSidedCoeffs/smoothing", "-0.5", "[0, 1]"),
    ("packingPackedCells", "subModels/twoSidedCoeffs/packedCells", "maybe", "true or false"),
    ("packingPredictMean", "subModels/twoSidedCoeffs/predictMean", "maybe", "true or false"),
    ("packingAlphaMin", "subModels/twoSidedCoeffs/alphaMin", "0", "(0, 1)"),
    ("tracking", "tracking", "straight", "cartesian"),
]


@pytest.mark.parametrize("app", BOTH)
@pytest.mark.parametrize("name, entry, value, valid", CLOUD_CASES,
                         ids=[c[0] for c in CLOUD_CASES])
def test_bad_cloud_entry(meshed, app, name, entry, value, valid):
    case = with_entry(meshed, name, PROPS, entry, value)
    keyword = entry.split("/")[-1]
    out = run_failing(case, app)
    expect(out, PROPS, *named(keyword, value), valid=valid)


# NTCHardSphere collisions (selected first): both programs check the
# coefficients.  (name, entry, bad value, valid range)
COLLISION_CASES = [
    ("ntcRestitutionHigh", "e", "1.5", "[0, 1]"),
    ("ntcRestitutionNegative", "e", "-0.2", "[0, 1]"),
    ("ntcAlphaValid", "alphaValid", "-0.1", "(0, 1]"),
    ("ntcAlphaSwitch", "alphaSwitch", "-0.05", "(0, 1]"),
    ("ntcAlphaSwitchZero", "alphaSwitch", "0", "(0, 1]"),
]


@pytest.mark.parametrize("app", BOTH)
@pytest.mark.parametrize("name, keyword, value, valid", COLLISION_CASES,
                         ids=[c[0] for c in COLLISION_CASES])
def test_bad_collision_entry(meshed, app, name, keyword, value, valid):
    case = with_entry(meshed, name, PROPS, "subModels/NTCHardSphereCoeffs/"
                      + keyword, value)
    foam.set_entry(case, PROPS, "subModels/stochasticCollisionModel",
                   "NTCHardSphere")
    out = run_failing(case, app)
    expect(out, PROPS, "NTCHardSphereCoeffs", *named(keyword, value), valid=valid)


def test_collision_model_name(meshed):
    case = with_entry(meshed, "ntcName", PROPS,
                      "subModels/stochasticCollisionModel", "NTCHardSpheres")
    out = run_failing(case, "rarefiedMultiphaseFoam")
    expect(out, PROPS, *named("stochasticCollisionModel", "NTCHardSpheres"),
           valid="NTCHardSphere")


def test_collisionless_needs_cartesian_contacts(meshed):
    """erosionPlanes' collisionless is honoured only by cartesianContacts:
    with any other collision model (here none, the MPPIC cloud's) it
    stops the solver rather than being ignored."""
    case = foam.copy_case(meshed, os.path.join(BUILD, "collisionless"))
    path = os.path.join(case, PROPS)
    with open(path) as f:
        text = f.read()
    with open(path, "w") as f:
        f.write(text.replace(
            "cloudFunctions\n{\n}",
            "cloudFunctions\n{\n    erosionPlanes\n    {\n        type erosionPlanes;\n"
            "        startTime 0; anchoringDepth 4; erosionHeight 1;\n"
            "        collisionless true;\n    }\n}", 1))
    out = run_failing(case, "rarefiedMultiphaseFoam")
    expect(out, PROPS, *named("collisionless", "true"), valid="cartesianContacts")


def test_drag_force_beside_coupling(meshed):
    """An upstream drag force in particleForces beside an interphase
    coupling would drag the grains twice: refused, naming both."""
    case = with_entry(meshed, "dragTwice", PROPS, "subModels/interphaseCoupling",
                      "oneWay")
    foam.set_entry(case, PROPS, "subModels/particleForces/sphereDrag", "")
    out = run_failing(case, "rarefiedMultiphaseFoam")
    expect(out, PROPS, "particleForces", "sphereDrag", "interphaseCoupling", "oneWay")


# Initialisation dictionary (initialiser only)
INIT_CASES = [
    ("alpha0High", "alpha0", "0.6", "(0, alphaPacked = 0.6)", "nParcels"),
    ("alpha0Zero", "alpha0", "0", "(0, alphaPacked = 0.6)", "nParcels"),
    ("diameter", "d", "-0.0003", "(0, the mesh's diagonal = ", None),
    ("weight", "nParticle", "-749", "(0, inf)", None),
    ("spread", "sigmaU", "-0.5", "[0, inf)", None),
]


@pytest.mark.parametrize("name, entry, value, valid, remove", INIT_CASES,
                         ids=[c[0] for c in INIT_CASES])
def test_bad_initialisation(meshed, name, entry, value, valid, remove):
    case = with_entry(meshed, name, INIT, REGION + entry, value,
                      remove=REGION + remove if remove else None)
    out = run_failing(case, "rarefiedMultiphaseInitialise")
    expect(out, INIT, *named(entry, value), valid=valid)


def test_region_outside_mesh(meshed):
    case = with_entry(meshed, "outside", INIT, REGION + "max", "(0.2 0.138 0.3)")
    out = run_failing(case, "rarefiedMultiphaseInitialise")
    expect(out, INIT, "positions outside the mesh")


def test_positions_file_missing(meshed):
    """A positionsFile region naming a file that constant/ does not hold
    (upstream's reader stops with a plain FatalError, "cannot find
    file", without the dictionary or the keyword; the fuzz found it)."""
    case = with_entry(meshed, "positionsMissing", INIT, REGION + "type", "positionsFile")
    for key in ("min", "max", "nParcels"):
        subprocess.run(["foamDictionary", "-entry", REGION + key, "-remove", INIT],
                       cwd=case, check=True, stdout=subprocess.DEVNULL)
    foam.set_entry(case, INIT, REGION + "file", "noSuchPoints")
    out = run_failing(case, "rarefiedMultiphaseInitialise")
    expect(out, INIT, *named("file", "noSuchPoints"), valid="a file of points in constant/")


# Unknown and misspelt keywords (inputChecks::rejectUnknown where the
# project defines every keyword, rejectMisspelt where upstream's readers
# share the dictionary or users keep variables): the message names the
# file, the keyword, the keyword meant and the valid ones.
# (name, dictionary, entry, value, apps, texts beyond file and keyword)
KEYWORD_CASES = [
    ("topMisspelt", PROPS, "axisymetric", "false", BOTH,
     ("did you mean 'axisymmetric'", "radialExtent")),
    ("constPropsMisspelt", PROPS, "constantProperties/thermalAcommodation",
     "0.5", BOTH, ("did you mean 'thermalAccommodation'", "specularFraction")),
    ("selectorMisspelt", PROPS, "subModels/dampingModels", "none", BOTH,
     ("did you mean 'dampingModel'", "isotropyModel")),
    ("ntcUnknown", PROPS, "subModels/NTCHardSphereCoeffs/alphaSwich", "0.1",
     BOTH, ("did you mean 'alphaSwitch'", "alphaValid", "randomSeed")),
    ("packingUnknown", PROPS, "subModels/twoSidedCoeffs/releif", "0.25", BOTH,
     ("did you mean 'relief'", "alphaMin", "particleStressModel")),
    ("regionUnknown", INIT, REGION + "sigmaV", "0.1",
     ["rarefiedMultiphaseInitialise"], ("did you mean 'sigmaU'", "nParcels", "max")),
    ("regionForeign", INIT, REGION + "radius", "0.1",
     ["rarefiedMultiphaseInitialise"], ("valid keywords", "min", "max")),
    ("initTopMisspelt", INIT, "randomseed", "3",
     ["rarefiedMultiphaseInitialise"], ("did you mean 'randomSeed'", "regions")),
]


@pytest.mark.parametrize("name, path, entry, value, apps, texts", KEYWORD_CASES,
                         ids=[c[0] for c in KEYWORD_CASES])
def test_unknown_keyword(meshed, name, path, entry, value, apps, texts):
    case = with_entry(meshed, name, path, entry, value)
    if entry.startswith("subModels/NTCHardSphereCoeffs/"):
        foam.set_entry(case, PROPS, "subModels/stochasticCollisionModel",
                       "NTCHardSphere")
    for app in apps:
        out = run_failing(case, app)
        expect(out, "Unknown keyword '" + entry.split("/")[-1] + "'", path, *texts)


def test_user_variable_accepted(meshed):
    """A top-level entry that is no misspelling (an OpenFOAM user's $variable)
    is accepted: the initialiser and two solver steps run."""
    case = with_entry(meshed, "userVariable", PROPS, "myLayerTop", "0.25")
    foam.set_entry(case, INIT, "myOtherSetting", "1")
    foam.set_entry(case, "system/controlDict", "endTime", "0.002")
    foam.set_entry(case, "system/controlDict", "writeInterval", "0.002")
    foam.run(case, "rarefiedMultiphaseInitialise")
    foam.run(case, "rarefiedMultiphaseFoam")
    assert "0.002" in foam.times(case)


def test_cloud_random_seed_range(meshed):
    """The cloud's own stream (radial-weight clone and delete draws) takes
    randomSeed in [0, 2000] like every stream of the project
    (randomStreams.H)."""
    case = with_entry(meshed, "cloudSeed", PROPS, "randomSeed", "5000")
    out = run_failing(case, "rarefiedMultiphaseFoam")
    expect(out, PROPS, *named("randomSeed", "5000"), valid="[0, 2000]")
