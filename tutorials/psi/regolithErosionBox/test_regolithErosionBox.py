# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""regolithErosionBox, reduced: the base variant through the case's Allrun
with 0.05 s of plume after the 0.25 s settle (about 1.5 minutes).

Checks (each able to fail):
- The settled bed at the plume's onset (erosionPlanes' line in the log:
  the mean height of the 20 highest centres + d/2, and the packing
  fraction between 2 d above the floor and 2 d below that top) against
  LAMMPS's settle of the same 800 grains (bench/dem --settle --seeds 3,
  gran/hooke/history, 2026-12-02): top 14.427-14.543 mm, packing
  0.596-0.609 over three jitter seeds.  Tolerance: that range widened by
  its own width on both sides (ours, the same three seeds:
  14.434-14.528 mm, 0.601-0.606).  A gas acting during the settle, or
  contacts that fail, move the bed far outside (the bed top was 73.6 mm
  when the gas acted from the start).
- The planes move down together by the eroded depth, at every step:
  drop = max over the steps so far of N_e V_p/(phi A), from the series'
  own erosion numbers and the onset's packing, within 1e-6 d (the
  series' 10 digits resolve 1e-9 d).
- The account: no grain lost away from a patch; the grains present are
  800 less those out through the top.
- Erosion at 0.05 s of plume: a regression check against this code's
  own runs (no independent reference exists), not a validation.  The
  bed's jitter seed (rmf.erosion bed --seed N, written through
  rmf_testing.seed(1); seed set 0 writes the tutorial's own bed, seed 1)
  is the run's only seed: the DEM and the plume draw nothing, so set 0
  repeats seed 1's run.  Reference: the mean of seeds 1-3 of this code
  (2026-12-02: 166, 150, 180; REF_NE = 165.3); with the initial grains
  written with 12 digits instead of 17, 165, 170, 167 (and 167, 172, 175
  with the settle and the plume in one run): pooled about each set's
  mean, REF_SD = 9.1 grains (nine runs, six degrees of freedom), the
  spread of chaotic grains rather than of our code.  A new run (another
  seed) differs from the three-run mean with standard deviation REF_SD
  sqrt(1 + 1/3); tolerance: Student's t with 6 degrees of freedom at the
  module's family-wise error, t = 7.71 (rmf_testing.t_limit(6)), i.e.
  81 grains (49 % of the reference): a change that moves the
  trajectories moves the number within it, one that changes the erosion
  by half or more (the planes, the gas's reach, the contacts) leaves it.
  Measured 2026-12-06: 174 (the code has changed since seed 1's 166).  Family-wise error: 2.5e-4
  (rmf_testing.MODULE_ALPHA) over m = 1 statistical comparison (this
  one; the bed checks compare with LAMMPS's range, the planes and the
  account are exact).

The collisionless variant, reduced (0.1 s of plume from the same settled
bed, about 20 s more): Berger's collisionless box by our rule (the grains
the gas has reached stop touching each other; erosionPlanes'
collisionless, doc/physics.md 7.3).  Checks:
- The rule: no grain above the erosion plane touches another grain at
  any step (every such grain has been reached; the grains it could touch,
  those not reached, lie at least 5 d lower, below the anchoring plane),
  while at least 100 grains are above it at some step.  With the rule
  broken the base variant's contacts come back: its grains above the
  plane touch others at a fractional collision number of about 0.013
  (README), i.e. a few of some hundred grains at most steps.
- Berger's delayed onset: the erosion starts later than the base
  variant's (same bed, same plume), 0.066 s against 0.029 s here.

The mppic variant, reduced (0.05 s, a few seconds): the DEM's settled bed
handed over to MPPIC parcels on the coarser mesh (rmf.erosion settled,
the positionsFile fill).  Checks: the bed top and packing that
erosionPlanes measures at the end of the first step are the DEM's at its
onset within 0.05 d and 0.01 (the grains are the same; one case step of
MPPIC or DEM moves a bed at rest by micrometres; the lattice the DEM
settled from has its top 10 mm higher); no grain lost.

(Berger's monolayer jump, the set of reached grains lifted within a few
ms, is in the README with the full run's figures: over 1-2 ms it rises
only about 2.3 times as fast as the base variant's start here, too close
to the base for a bound set from one seed.)
"""

import math
import os
import re
import shutil
import subprocess

import numpy as np

from rmf import erosion, foam
from rmf_testing import report, seed, t_limit

HERE = os.path.dirname(os.path.abspath(__file__))
BUILD = os.path.join(foam.PROJECT_DIR, "build", "tutorials", "regolithErosionBox")

PLUME = 0.05                        # [s]
LAMMPS_TOP = (14.427e-3, 14.543e-3)     # bench/dem --settle --seeds 3 [m]
LAMMPS_PACKING = (0.596, 0.609)
REF_NE = (166 + 150 + 180)/3       # erosion number at 0.05 s, seeds 1-3
REF_SD = 9.1                        # its standard deviation over seeds
REF_DOF, REF_RUNS = 6, 3            # REF_SD's degrees of freedom; runs in REF_NE


def widened(lo, hi):
    return lo - (hi - lo), hi + (hi - lo)


def solver_log(run):
    with open(os.path.join(run, "log.rarefiedMultiphaseFoam")) as f:
        return f.read()


def settled_bed(log):
    """Bed top [m] and packing that erosionPlanes measured at the onset."""
    m = re.search(r"erosionPlanes: bed top (\S+) m, packing (\S+), (\d+) grains", log)
    return float(m.group(1)), float(m.group(2))


def check_account(name, log, s):
    """No grain lost away from a patch; the grains present at the end are
    800 plus those in less those out (the last report's totals)."""
    n_in, n_out = map(int, re.findall(r"Parcels in / out since start\s*=\s*(\d+) / (\d+)",
                                      log)[-1])
    present = int(s["grains"][-1])
    return report(name, "lost away from patches" not in log
                  and present == erosion.N_GRAINS + n_in - n_out,
                  f"{present} grains present, {n_in} in, {n_out} out, none lost")


def test_erosion_box_reduced():
    if os.path.exists(BUILD):
        shutil.rmtree(BUILD)
    shutil.copytree(HERE, BUILD, ignore=shutil.ignore_patterns("runs", "__pycache__", "*.py"))
    erosion.write_bed(BUILD, seed(1))
    subprocess.run(["./Allrun", "-variant", "base", "-plume", str(PLUME)], cwd=BUILD,
                   check=True, stdout=subprocess.DEVNULL)
    run = os.path.join(BUILD, "runs", "base")
    log = solver_log(run)
    top, packing = settled_bed(log)

    lo, hi = widened(*LAMMPS_TOP)
    ok_top = report("settled bed top against LAMMPS", lo <= top <= hi,
                    f"{1e3*top:.3f} mm in [{1e3*lo:.3f}, {1e3*hi:.3f}] mm")
    lo, hi = widened(*LAMMPS_PACKING)
    ok_packing = report("settled bed packing against LAMMPS", lo <= packing <= hi,
                        f"{packing:.4f} in [{lo:.3f}, {hi:.3f}]")

    s = erosion.read(run)
    np.save(os.path.join(BUILD, "base_erosion.npy"),
            np.vstack([s["time"], s["erosionNumber"]]))
    vp = math.pi*erosion.D**3/6
    area = erosion.LX*erosion.LZ
    drop = np.maximum.accumulate(s["erosionNumber"]*vp/(packing*area))
    # The erosion plane starts 1 d above the onset's bed top; the
    # anchoring plane stays 4 + 1 d below it
    err = np.max(np.abs(top + erosion.D - drop - s["erosion"]))/erosion.D
    err_a = np.max(np.abs(s["erosion"] - s["anchoring"] - 5*erosion.D))/erosion.D
    # (the series is written with 10 significant digits: 1e-12 m here)
    ok_planes = report("planes moved by the eroded depth", err < 1e-6 and err_a < 1e-6,
                       f"largest departure {err:.1e} d (erosion plane),"
                       f" {err_a:.1e} d (plane spacing); drop at the end"
                       f" {drop[-1]/erosion.D:.2f} d")

    ok_account = check_account("grain account", log, s)

    fig = erosion.figures(s)
    ne = s["erosionNumber"][-1]
    tol = t_limit(REF_DOF)*REF_SD*math.sqrt(1 + 1/REF_RUNS)
    ok_ne = report("erosion number at 0.05 s against this code's reference (regression)",
                   abs(ne - REF_NE) <= tol,
                   f"{ne:.0f} vs {REF_NE:.1f} (tol t_6 {t_limit(REF_DOF):.2f} x "
                   f"{REF_SD:g} x sqrt(4/3) = {tol:.0f});"
                   f" onset {fig['onset']:.4f} s")
    assert ok_top and ok_packing and ok_planes and ok_account and ok_ne


def test_erosion_box_collisionless():
    if not os.path.exists(os.path.join(BUILD, "base_erosion.npy")):
        test_erosion_box_reduced()
    subprocess.run(["./Allrun", "-variant", "collisionless", "-plume", "0.1"], cwd=BUILD,
                   check=True, stdout=subprocess.DEVNULL)
    s = erosion.read(os.path.join(BUILD, "runs", "collisionless"))
    above = s["above"]
    ok_rule = report("collisionless: no reached grain touches another",
                     np.all(s["colliding"][above > 0] == 0) and above.max() >= 100,
                     f"grains above the erosion plane touching another: at most"
                     f" {s['colliding'].max():.0f} (up to {above.max():.0f} grains above)")

    t_base, ne_base = np.load(os.path.join(BUILD, "base_erosion.npy"))
    # (erosion.figures' onset: the first N_e of at least ONSET grains)
    onset_base = float(t_base[np.argmax(ne_base >= erosion.ONSET)] - t_base[0])
    fig = erosion.figures(s)
    ok_onset = report("collisionless: onset later than with contacts",
                      fig["onset"] is not None and fig["onset"] > onset_base,
                      f"{fig['onset']:.4f} s against {onset_base:.4f} s")

    assert ok_rule and ok_onset


def test_erosion_box_parcels():
    if not os.path.exists(os.path.join(BUILD, "runs", "base")):
        test_erosion_box_reduced()
    subprocess.run(["./Allrun", "-variant", "mppic", "-plume", "0.05"], cwd=BUILD,
                   check=True, stdout=subprocess.DEVNULL)
    run = os.path.join(BUILD, "runs", "mppic")
    log = solver_log(run)
    top_d, phi_d = settled_bed(solver_log(os.path.join(BUILD, "runs", "base")))
    top_m, phi_m = settled_bed(log)
    ok_bed = report("settled bed handed to MPPIC",
                    abs(top_m - top_d) < 0.05*erosion.D and abs(phi_m - phi_d) < 0.01,
                    f"top {1e3*top_m:.4f} mm vs DEM {1e3*top_d:.4f} mm (tol 0.05 mm),"
                    f" packing {phi_m:.4f} vs {phi_d:.4f} (tol 0.01)")
    ok_account = check_account("grain account (mppic)", log, erosion.read(run))
    assert ok_bed and ok_account
