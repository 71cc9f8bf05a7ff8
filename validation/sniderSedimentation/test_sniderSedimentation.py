# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Snider sedimentation: reduced in ./Alltest, full-size with
./Alltest --long; the over-packing bounds at the tutorial's parcel
weight in a narrow column always.  Checks and tolerances: rmf.snider;
runs: validate.py."""

import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(__file__))

import validate  # noqa: E402
from rmf import snider  # noqa: E402


@pytest.fixture(scope="module")
def results(request):
    _, figures = validate.validate(full=request.config.getoption("--long"))
    return figures


def test_pictures(results):
    for path in results["pngs"]:
        assert os.path.getsize(path) > 0


def test_snider_checks(results):
    """Every check but the over-packing bounds (next test)."""
    failed = [name for name, ok in results["checks"].items()
              if not ok and not name.endswith(snider.OVERPACKING)]
    assert not failed, failed


def test_paraview(results):
    """The serial run opened in ParaView as users do (rmf.pvcheck: a .foam
    file, the last time, alpha.grains with the range of its file, the
    averaged alpha and parcel counts, every parcel of the cloud with the
    project's own fields, a picture that is not blank)."""
    from rmf import pvcheck
    failures, _ = pvcheck.check(results["cases"]["serial"], "alpha.grains", "grains",
                                extra_cells=("alphaAverage.grains", "nParcels.grains"))
    assert not failures, failures


def test_overpacking_bounds(results):
    """Full size (--long): the layer and averaged cell bounds of
    doc/physics.md 5.3; the reduced runs' heavier parcels are checked
    by neither (rmf.snider)."""
    failed = [name for name, ok in results["checks"].items()
              if not ok and name.endswith(snider.OVERPACKING)]
    assert not failed, failed


@pytest.fixture(scope="module")
def narrow_results():
    return validate.narrow()


def test_narrow_averaged_cell_bound(narrow_results):
    """The averaged alpha the twoSided packing model acts on stays at or
    below alphaPacked + 0.08 in every cell from 0.1 s to 0.6 s, at the
    tutorial's parcel weight (doc/physics.md 5.3)."""
    _, s, _ = narrow_results
    assert s["checks"]["averaged cell bound"], s["alphaMaxAveraged"]


def test_narrow_bed(narrow_results):
    """Bed 0.6 +- 0.02 below 0.14 m, clear above 0.16 m, a sharp
    interface, parcels conserved, at the tutorial's parcel weight."""
    _, s, _ = narrow_results
    failed = [name for name in ("parcels", "properties", "bed", "clear", "sharp")
              if not s["checks"][name]]
    assert not failed, failed


# Largest ratio of the four quarter-layer slabs' alpha in the settled
# bed (rmf.snider.quarter_layers, 0.6 s) with the continuous stress
# gradient.  Measured 1.07 serially and 1.10 on 2 ranks (2026-12-05),
# where the slabs' parcel counts alone (about 2 700 each) scatter by 2 %
# and the bed's layering doubles that; the tetrahedra's gradient gives
# 1.75 (parcels gathered under the faces).  The bound lies between.
QUARTERS_FLAT = 1.25


def test_narrow_continuous_gradient_spreads_parcels(narrow_results):
    """twoSided with smoothing 1 (doc/physics.md 5.3.1): the parcels of
    the settled bed spread evenly through each cell, where the
    tetrahedra's gradient (the tutorial, smoothing 0) gathers them under
    the faces."""
    _, _, tutorial = narrow_results
    _, _, smooth = validate.narrow(name="narrowSmoothing",
                                   entries={"subModels/twoSidedCoeffs/smoothing": 1})
    ratio = {}
    for name, case in (("tutorial", tutorial), ("smoothing 1", smooth)):
        quarters = snider.quarter_layers(case, "0.6")
        ratio[name] = quarters.max()/quarters.min()
    assert ratio["smoothing 1"] <= QUARTERS_FLAT < ratio["tutorial"], ratio


# The largest layer alpha of the narrow column at 0.6 s, where the layer
# above the floor layer creeps without packedCells (doc/physics.md
# 5.3.1).  Measured serially, seeds 0, 1, 2 (2026-12-05): with it 0.618,
# 0.621, 0.615; without it 0.639, 0.640, 0.646.  The layer bound of the
# full column (rmf.snider LAYER_MAX_BOUND, 0.63) lies between, 0.009
# from either side, where the seeds scatter each side by 0.003.
CREEP_SPLIT = snider.LAYER_MAX_BOUND


def test_narrow_packed_cells_stop_creep(narrow_results):
    """twoSided with packedCells (the tutorial's) holds the settled bed's
    layers at 0.6 s below the layer bound; without it the layer above the
    floor layer creeps above it."""
    _, with_it, _ = narrow_results
    _, without, _ = validate.narrow(name="narrowNoPackedCells",
                                    entries={"subModels/twoSidedCoeffs/packedCells": "false"})
    layer = {"packedCells": with_it["alphaMaxLayer"]["0.6"],
             "without": without["alphaMaxLayer"]["0.6"]}
    assert layer["packedCells"] <= CREEP_SPLIT < layer["without"], layer


@pytest.fixture(scope="module")
def variant_results(request, results):
    variants, png = validate.variants(results["serial"],
                                      full=request.config.getoption("--long"))
    return variants, png


def test_variants_picture(variant_results):
    assert os.path.getsize(variant_results[1]) > 0


def test_stochastic_overpacks(variant_results):
    """doc/physics.md 7.1: NTC collisions alone know only binary collisions and
    let the bed pack beyond what MPPIC's stress allows: its bottom layer
    exceeds the layer bound that the MPPIC run keeps, parcels conserved."""
    passed, s = variant_results[0]["stochastic"]
    checks = s["checks"]
    assert checks["parcels"] and checks["properties"] and checks["heated"]
    layer = max(s["alphaMaxLayer"].values())
    assert layer > snider.LAYER_MAX_BOUND, layer


def test_hybrid_checks(variant_results):
    """The hybrid keeps MPPIC in the bed: every check of the MPPIC run
    but the over-packing bounds (those: next test)."""
    passed, s = variant_results[0]["hybrid"]
    failed = [name for name, ok in s["checks"].items()
              if not ok and name not in snider.OVERPACKING]
    assert not failed, failed


def test_hybrid_overpacking_bounds(variant_results):
    passed, s = variant_results[0]["hybrid"]
    failed = [name for name, ok in s["checks"].items()
              if not ok and name in snider.OVERPACKING]
    assert not failed, failed
