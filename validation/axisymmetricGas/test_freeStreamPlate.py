# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Axisymmetric gas against a 3-D sector, and on 2 MPI ranks
(doc/physics.md#axisymmetric and #verification).

Case freeStreamPlate: an argon free stream (1e20 m^-3, 300 K, 1000 m/s
along +x: Mach 3.1) enters through the inlet x = 0 and through the outer
radius r = 0.05 m (FreeStream there too: the stream flows along it), and
stops on a Maxwellian wall at 300 K at x = 0.05 m (the plate).  The gas
piles up against the plate (density 1.1 to 9.4 times the free stream,
temperature 500 to 1100 K, radial velocity up to 290 m/s): structure in x
and r.  x, r in [0, 0.05] m in 16 x 12 cells.  Three runs:

  wedge      axisymmetric, a 5 degree wedge, maxRadialWeight 5, serial;
  sector30   full 3-D, a 30 degree sector about the x axis made of six
             copies of the wedge turned about the axis (every cell a copy
             of a wedge cell), its sides specular symmetry planes, no
             weighting, serial, with randomEntryTime true: inserted
             simulators start at a random time within their first step as
             in the axisymmetric mode (upstream's full first step, the 3-D
             default, leaves the inlet cells with 25 % less density, 60
             standard errors: that is a difference of the inflow models,
             not of the axisymmetric move);
  parallel   the wedge on 2 METIS ranks (decomposePar, mpirun -np 2
             -parallel, reconstructPar).

Each runs 1100 steps of 2 us written every 50 (fieldAverage batch means).
After 250 steps the batch means are steady (their mean offset over the
bins from the later batches' is at most 0.25 of a batch's standard
deviation), so the first 5 batches are dropped and 17 kept.

Comparisons (meridional.py): number density, x and radial velocity and
translational temperature in the 16 x 12 (x, r) bins (the 3-D cells by x
and sqrt(y^2 + z^2)), the difference of the two runs' batch means in
combined standard errors sqrt(se_a^2 + se_b^2).  Batches of 50 steps are
independent in time: the lag-1 correlation of the batch means is -0.08 to
0.00 (median over bins, per field and run), the flow crossing the domain
in 25 steps.  Per field a run fails
  - if any bin is beyond t_limit(dof, M) (Welch's t, its dof from the two
    runs' standard errors, 17-32: 6.7-8.4), or
  - if the mean of dev^2 over the bins exceeds its limit under the null
    (meridional.chi2_null/chi2_limit, at MODULE_ALPHA/M).  The bins are
    not independent in space: the batches' covariance gives correlated
    neighbours and a mode common to the domain (mean correlation
    0.02-0.07), so the mean over the 192 bins has a standard deviation of
    0.17-0.27, not the 0.12 of independent bins that the former fixed
    limit 2.0 assumed (measured means 0.88-1.54 against a null mean of
    1.07-1.09: within 1.8 of those standard deviations).  The limit is
    the scaled chi^2 quantile matched to that mean and variance: 2.2-3.1,
    computed per run from its batches; or
  - for n and T (positive everywhere), if the mean over the bins of the
    relative difference (a - b)/b is beyond t_limit(dof, M) of its
    standard error: an offset common to the bins, which no single bin
    resolves.  The standard error is the batch spread of each run's mean
    over the bins (relative to b's means), Welch's dof, so that it carries
    the bins' correlation; the former sqrt(sum (se/b)^2)/192 took the bins
    as independent and was 2.8-3.1 times too small (measured offsets
    -0.06 to +0.10 % against standard errors of 0.19-0.28 %: an offset
    of 1.3-1.8 % now fails, e.g. n or T of the sector raised by 0.5 %
    passes; the figures of the sector's sample-size offset below, in
    standard errors, are in the former, too small units).

Family-wise error: 2.5e-4 (rmf_testing.MODULE_ALPHA) over M = 1548
comparisons, Bonferroni (1.6e-7 each): 1536 bins (192 bins x 4 fields x 2
comparisons), 8 means of dev^2, 4 offsets (t with 25-32 d.o.f.).  The accounts are
exact or bounded by the faces' carried remainders, not statistical.
Seeds: rmf_testing.seed(1) for the fill and the runs.

The 3-D sector needs more simulators than the wedge (WEIGHT): its cells
at the axis are as thin as the wedge's but not weighted, so at the
wedge's count (4.5e11: 0.6 simulators per cell in the row at the axis,
a third of the wedge's there) it ran 0.73 +- 0.08 % cooler than the wedge
averaged over the bins (2.7 % in the row at the axis; mean dev +0.59,
mean dev^2 1.84), the offset once admitted here as "unexplained".  It is
the sector's own sample-size error: tripling the sector's simulators
(1.5e11) moves its T by +0.78 +- 0.07 % and n by -0.48 +- 0.07 %,
tripling the wedge's moves its T by only +0.10 +- 0.07 % (n +0.09 +-
0.07 %), and the wedge against the sector at 1.5e11 differs by -0.06 +-
0.07 % in T and +0.07 +- 0.07 % in n (mean dev^2 0.89-1.65 over the four
fields; 1.10-1.38 with the wedge's simulators tripled too).  Measured
on this weight, the offset check reads 9 standard errors for the old
sector.  The parallel run against the serial one: 0.88-1.36, T offset
+0.03 +- 0.08 %.

Broken by hand (not committed), the checks fail: with the cloning of
the radial weighting off the wedge has 25 % less gas (n 68, Ux 33, Ur 31,
T 26 standard errors against the sector); sampled without the weights its
density is off by up to 294 standard errors; with the weighting skipped
where a move stops at a processor boundary the 2-rank run is off by 8.8
(n), 7.2 (Ux) and 10.2 (Ur); with the weighting's deletions left
uncounted every step's inflow misses what FreeStream inserted; and the
sector with upstream's full first step (randomEntryTime false) is off
by 62 (n) in the inlet cells.

Cost: about 32 s of CPU per wedge run (20000 simulators, 1100 steps),
about 125 s for the sector (60000); the wedge and the sector run side by
side, then the 2-rank run.

Account: every step the simulators that came in (the account's balance)
equal those the FreeStream model reports inserted, nothing is lost away
from patches, and the inserted total equals the analytic free-stream flux
(Bird 1994 eq. 4.22) through the inlet and outer faces to within the
number of those faces (FreeStream carries each face's fractional
remainder to the next step).
"""

import math
import os

import numpy as np
import pytest

from rmf import foam
from rmf_testing import MODULE_ALPHA, seed, t_limit

import meridional as md

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, "freeStreamPlate")
BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "axisymmetricGas")

LENGTH = 0.05                               # x extent [m]
ROWS_RADIUS = 0.05 * math.cos(math.radians(2.5))   # outer faces' distance
NX, NR = 16, 12                             # (x, r) cells
SKIP = 5                                    # batches dropped (250 steps)
MASS = 66.3e-27
N0, T0, U0 = 1e20, 300.0, 1000.0            # free stream
K_B = 1.380649e-23

M = NX * NR * 4 * 2 + 8 + 4                 # comparisons (docstring): 1548
ALPHA = MODULE_ALPHA / M                    # each comparison's share

# nEquivalentParticles: the sector has 6 times the wedge's volume and no
# weighting; 1.5e11 gives it about 3 times the wedge's simulators (60000
# against 20000 once steady), as many as the wedge's in the bins at the
# axis (1.9 per sector cell in the row at the axis) and 5 times in those
# at the outer radius.  At 4.5e11 (the wedge's total) the sector's own
# sample-size error was a -0.7 % offset in T (docstring)
WEIGHT = {"wedge": 2.4e10, "sector30": 1.5e11, "parallel": 2.4e10}

def _setup(name):
    case = foam.copy_setup(CASE, os.path.join(BUILD, "freeStreamPlate", name))
    props = "constant/dsmcProperties"
    if name == "sector30":
        foam.run(case, "blockMesh", "-dict", "system/blockMeshDict.sector30")
        for key in ("axisymmetric", "radialExtent", "maxRadialWeight"):
            foam.remove_entry(case, props, key)
        foam.set_entry(case, props, "randomEntryTime", "true")
    else:
        foam.run(case, "blockMesh")
    foam.set_entry(case, props, "nEquivalentParticles", WEIGHT[name])
    foam.set_entry(case, props, "randomSeed", seed(1))
    foam.set_entry(case, "system/dsmcInitialiseDict", "randomSeed", seed(1))
    foam.run(case, "rarefiedMultiphaseInitialise")
    return case


def _run(case, np_=1):
    if np_ > 1:
        foam.run(case, "decomposePar")
    foam.run(case, "rarefiedMultiphaseFoam", np_=np_)
    if np_ > 1:
        foam.run(case, "reconstructPar", "-noLagrangian")


@pytest.fixture(scope="module")
def runs():
    from concurrent.futures import ThreadPoolExecutor
    cases = {name: _setup(name) for name in WEIGHT}
    with ThreadPoolExecutor(max_workers=2) as pool:
        jobs = [pool.submit(_run, cases[name]) for name in ("wedge", "sector30")]
        for job in jobs:
            job.result()
    _run(cases["parallel"], np_=2)
    return cases


def _binned(case):
    bins = md.bin_index(foam.cell_centres(case), LENGTH, ROWS_RADIUS, NX, NR)
    return md.binned_batches(case, bins, NX * NR, MASS, SKIP)


@pytest.fixture(scope="module")
def binned(runs):
    return {name: _binned(case) for name, case in runs.items()}


def _report(ok, what, figures):
    print(f"{'PASS' if ok else 'FAIL'} axisymmetricGas {what}: {figures}")
    return ok


def _check(binned, a, b):
    result = md.compare(binned[a], binned[b])
    ok = True
    for name, (mean_a, mean_b, se, dev, dof) in result.items():
        max_dev = np.array([t_limit(d, M) for d in dof])
        worst = np.unravel_index((abs(dev) / max_dev).argmax(), (NX, NR))
        scale = abs(mean_a).max()
        chi2 = (dev ** 2).mean()
        max_chi2, null, null_sd = md.chi2_limit(binned[a][name], binned[b][name], dof, ALPHA)
        field_ok = (abs(dev) < max_dev).all() and chi2 < max_chi2
        offset = ""
        if name in ("n", "T"):
            # per batch, the mean over the bins relative to b's means: its
            # batch spread carries the bins' correlation
            qa = (binned[a][name] / mean_b).mean(axis=1)
            qb = (binned[b][name] / mean_b).mean(axis=1)
            rel = qa.mean() - qb.mean()         # = mean of (a - b)/b
            va, vb = qa.var(ddof=1) / len(qa), qb.var(ddof=1) / len(qb)
            rel_se = math.sqrt(va + vb)
            rel_dof = (va + vb) ** 2 / (va ** 2 / (len(qa) - 1) + vb ** 2 / (len(qb) - 1))
            max_offset = t_limit(rel_dof, M)
            field_ok &= abs(rel) < max_offset * rel_se
            offset = (f", mean relative difference {100 * rel:+.3f} +- "
                      f"{100 * rel_se:.3f} % (limit {max_offset:.2f} s.e., t with "
                      f"{rel_dof:.0f} d.o.f.)")
        ok &= _report(field_ok, f"freeStreamPlate {a} vs {b} {name}",
                      f"max |dev|/limit {(abs(dev) / max_dev).max():.2f} at (x, r) "
                      f"bin {worst} (|dev| {abs(dev)[worst[0] * NR + worst[1]]:.2f}, "
                      f"limits {max_dev.min():.2f}-{max_dev.max():.2f}), mean dev "
                      f"{dev.mean():+.2f}, mean dev^2 {chi2:.2f} (null {null:.2f} +- "
                      f"{null_sd:.2f}, limit {max_chi2:.2f}){offset}, se {se.min() / scale:.4f}-"
                      f"{se.max() / scale:.4f} of the field's largest value")
    return ok


def test_sector_matches_axisymmetric(binned):
    """The wedge (axisymmetric, weighted) and the 3-D sector agree in every
    (x, r) bin within noise."""
    assert _check(binned, "wedge", "sector30")


def test_parallel_matches_serial(binned):
    """The wedge on 2 ranks, reconstructed, agrees with the serial wedge."""
    assert _check(binned, "wedge", "parallel")


def _inflow_per_step(case, sectors):
    """Analytic simulators entering per step through the inlet (drift U0
    into the domain) and the outer radius (drift along it), Bird eq. 4.22:
    n c_mp A (exp(-s^2) + sqrt(pi) s (1 + erf s))/(2 sqrt(pi)), with the
    faces of `sectors` copies of the 5 degree wedge."""
    dt = float(foam.get_entry(case, "system/controlDict", "deltaT"))
    weight = float(foam.get_entry(case, "constant/dsmcProperties", "nEquivalentParticles"))
    c_mp = math.sqrt(2 * K_B * T0 / MASS)
    half = math.radians(2.5)
    r = 0.05                                       # vertex radius
    inlet = sectors * r * r * math.sin(half) * math.cos(half)
    outer = sectors * LENGTH * 2 * r * math.sin(half)

    def flux(s):
        return (math.exp(-s * s) + math.sqrt(math.pi) * s * (1 + math.erf(s))) \
            / (2 * math.sqrt(math.pi))

    return N0 / weight * c_mp * dt * (inlet * flux(U0 / c_mp) + outer * flux(0))


@pytest.mark.parametrize("name", ["wedge", "sector30", "parallel"])
def test_account(runs, name):
    """Every simulator accounted for: in each step the balance's inflow is
    what FreeStream inserted, nothing lost, and the inserted total is the
    analytic flux (to within one simulator per inflow face)."""
    case = runs[name]
    log = os.path.join(case, "log.rarefiedMultiphaseFoam")
    inserted = foam.log_values(log, "Particles inserted")[:, 0]
    in_out = foam.log_values(log, "Simulators in / out this step")
    with open(log) as f:
        text = f.read()
    lost = "lost away from patches" in text
    sectors = 6 if name == "sector30" else 1
    faces = sectors * (NR + NX)
    expected = _inflow_per_step(case, sectors) * len(inserted)
    mismatched = int((in_out[:, 0] != inserted).sum())
    out = {p: foam.log_values(log, f"out through {p}")[-1, 0]
           for p in ("inlet", "outer") if f"out through {p}" in text}
    figures = (f"{len(inserted)} steps, inserted {inserted.sum():.0f} "
               f"(analytic {expected:.1f}, off by {inserted.sum() - expected:.1f}, "
               f"limit {faces} faces), steps where in != inserted: {mismatched}, "
               f"out {out}, lost: {lost}")
    ok = (len(inserted) == len(in_out) and not mismatched and not lost
          and abs(inserted.sum() - expected) < faces)
    assert _report(ok, f"freeStreamPlate {name} account", figures)
