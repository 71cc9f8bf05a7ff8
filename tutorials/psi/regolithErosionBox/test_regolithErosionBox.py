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
  repeats seed 1's run.  Reference: seeds 1-7 of this code with the
  calibrated plume (README; 2026-12-06: 622, 635, 614, 612, 635, 618,
  617): REF_NE = 621.9, REF_SD = 9.5 grains (six degrees of freedom),
  the spread of chaotic grains rather than of our code.  A new run
  (another seed) differs from the seven-run mean with standard deviation
  REF_SD sqrt(1 + 1/7); tolerance: Student's t with 6 degrees of freedom
  at the module's family-wise error shared by m = 2 comparisons,
  t = 8.73 (rmf_testing.t_limit(6, 2)), i.e. 89 grains (14 % of the
  reference): a change that moves the trajectories moves the number
  within it, one that changes the erosion by a seventh or more (the
  planes, the gas's reach, the contacts, the plume) leaves it.
- Berger's onset, "well before 0.02 s" (the calibration's first target,
  README): the erosion number reaches 5 grains before 0.01 s.  Seeds
  1-7: 0.00344-0.00364 s (mean 0.00355, sd 0.00007): 0.01 s is 86 sd
  away, t_6 tail below 1e-9.  The old plume (tanh(y/0.27 m)) starts at
  0.029 s and fails it.
  Family-wise error: 2.5e-4 (rmf_testing.MODULE_ALPHA) over m = 2
  statistical comparisons (these two; the bed checks compare with
  LAMMPS's range, the planes and the account are exact).

The collisionless variant, reduced (0.1 s of plume from the same settled
bed, about 20 s more): Berger's collisionless box by our rule (the grains
the gas has reached stop touching each other; erosionPlanes'
collisionless, doc/physics.md#erosion-box).  Checks:
- The rule: no grain above the erosion plane touches another grain, at
  the end of any step nor at any contact step (Berger's count, zero at
  every step), (every such grain has been reached; the grains it could
  touch, those not reached, lie at least 5 d lower, below the anchoring
  plane), while at least 100 grains are above it at some step.  With the rule
  broken the base variant's contacts come back: its grains above the
  plane touch others at a fractional collision number of about 0.013
  (README), i.e. a few of some hundred grains at most steps.
- Berger's delayed onset: the erosion starts later than the base
  variant's (same bed, same plume): 0.0086-0.0101 s against
  0.0034-0.0036 s (seeds 1-3).

The mppic variant, reduced (0.05 s, a few seconds): the DEM's settled bed
handed over to MPPIC parcels on the coarser mesh (rmf.erosion settled,
the positionsFile fill).  Checks: the bed top and packing that
erosionPlanes measures at the end of the first step are the DEM's at its
onset within 0.05 d and 0.01 (the grains are the same; one case step of
MPPIC or DEM moves a bed at rest by micrometres; the lattice the DEM
settled from has its top 10 mm higher); no grain lost.

With --long (about 15 minutes): Berger's findings that the calibrated
box reproduces, over jitter seeds 1-3 (rmf_testing.seed(1..3)), each a
full settle, then base (0.2 s of plume), collisionless and
nondissipative (0.1 s) and erosion16 (0.2 s):
- the calibration's last target, depletion by about 0.15 s: the mean
  time to 95 % of the grains eroded within [0.10, 0.20] s (ours
  0.133-0.143 s; sd 0.005 s, the window 8 sd of a three-seed mean away);
- negative erosion from about 0.04 s (an erosion-only phase before it):
  the three seeds' mean first dip within [0.02, 0.08] s, Berger's time
  within a factor of two (ours, seeds 1-7: 0.035-0.051 s, mean 0.044,
  sd 0.0054; false alarm of the window for a three-seed mean, Student's
  t with 6 degrees of freedom: 3.4e-4);
- the ordering nondissipative > collisionless > dissipative: the
  three-seed means of the erosion number at 0.05 s and at 0.1 s
  (seeds 1-3 at 0.05 s: 769-783 > 667-710 > 614-635);
- the 16 d erosion plane's vanishing negative erosion: the share of
  steps 5 or more grains below the running maximum, averaged over the
  three seeds, is above 10 % for the base and below a tenth of the
  base's for erosion16 (2026-12-06: base 25.0, 23.4, 27.6 %, erosion16
  0.15, 1.23, 0.83 %; their mean 0.74 % against the bound 2.5 %, 5.6
  of its three-seed sd away).
These are comparisons with Berger's statements at tolerances read from
them, and seeds-spread false alarms above the default suite's budget:
they run only with --long, outside it.
"""

import math
import os
import re
import shutil
import subprocess

import numpy as np
import pytest

from rmf import erosion, foam
from rmf_testing import report, seed, t_limit

HERE = os.path.dirname(os.path.abspath(__file__))
BUILD = os.path.join(foam.PROJECT_DIR, "build", "tutorials", "regolithErosionBox")

PLUME = 0.05                        # [s]
LAMMPS_TOP = (14.427e-3, 14.543e-3)     # bench/dem --settle --seeds 3 [m]
LAMMPS_PACKING = (0.596, 0.609)
REF_NE = (622 + 635 + 614 + 612 + 635 + 618 + 617)/7    # N_e at 0.05 s, seeds 1-7
REF_SD = 9.5                        # its standard deviation over seeds
REF_DOF, REF_RUNS = 6, 7            # REF_SD's degrees of freedom; runs in REF_NE
M = 2                               # statistical comparisons (docstring)
BERGER_ONSET = 0.01                 # [s] "well before 0.02 s"


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
    tol = t_limit(REF_DOF, M)*REF_SD*math.sqrt(1 + 1/REF_RUNS)
    ok_ne = report("erosion number at 0.05 s against this code's reference (regression)",
                   abs(ne - REF_NE) <= tol,
                   f"{ne:.0f} vs {REF_NE:.1f} (tol t_6 {t_limit(REF_DOF, M):.2f} x "
                   f"{REF_SD:g} x sqrt(8/7) = {tol:.0f})")
    ok_onset = report("onset well before 0.02 s (Berger)",
                      fig["onset"] is not None and fig["onset"] < BERGER_ONSET,
                      f"{fig['onset']:.4f} s < {BERGER_ONSET} s")
    assert ok_top and ok_packing and ok_planes and ok_account and ok_ne and ok_onset


def test_erosion_box_collisionless():
    if not os.path.exists(os.path.join(BUILD, "base_erosion.npy")):
        test_erosion_box_reduced()
    subprocess.run(["./Allrun", "-variant", "collisionless", "-plume", "0.1"], cwd=BUILD,
                   check=True, stdout=subprocess.DEVNULL)
    s = erosion.read(os.path.join(BUILD, "runs", "collisionless"))
    above = s["above"]
    counted = s["contactSteps"] > 0
    ok_rule = report("collisionless: no reached grain touches another",
                     np.all(s["colliding"][above > 0] == 0)
                     and np.all(s["contactStepCollisions"][counted] == 0)
                     and counted.sum() > 1000 and above.max() >= 100,
                     f"grains above the erosion plane touching another: at most"
                     f" {s['colliding'].max():.0f} at a step's end, Berger's count at"
                     f" most {s['contactStepCollisions'][counted].max():.3f} over"
                     f" {counted.sum()} steps (up to {above.max():.0f} grains above)")

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


def test_collision_number_window():
    """rmf.erosion's 1000-contact-step average of Berger's count, by hand:
    rows of 0, 500, 500, 500 contact steps with step fractions -, 0.2,
    0.4, 0.6 average 0, 0.2, (0.2 + 0.4)/2 = 0.3 and (0.4 + 0.6)/2 = 0.5
    (each window the last rows holding at least 1000 steps, weighted by
    their steps); a series without the counts falls back to the
    end-of-step snapshot's moving average; grains without contacts give
    none."""
    s = {"time": np.array([0.0, 1e-4, 2e-4, 3e-4]), "colliding": np.zeros(4),
         "fractionalCollisions": np.array([0.0, 1.0, 1.0, 1.0]),
         "contactSteps": np.array([0, 500, 500, 500]),
         "contactStepCollisions": np.array([-1, 0.2, 0.4, 0.6])}
    got = erosion.collision_number(s)
    ok_window = report("collision number over 1000 contact steps", np.allclose(
        got, [0, 0.2, 0.3, 0.5], rtol=0, atol=1e-12), f"{got}")
    snapshot = {k: s[k] for k in ("time", "colliding", "fractionalCollisions")}
    ok_old = report("without the counts: the snapshot's average", np.allclose(
        erosion.collision_number(snapshot),
        erosion.moving_average(s["time"], s["fractionalCollisions"])), "")
    ok_none = report("no contacts resolved: none", erosion.collision_number(
        dict(s, colliding=-np.ones(4))) is None, "")
    assert ok_window and ok_old and ok_none


LONG = os.path.join(foam.PROJECT_DIR, "build", "tutorials", "regolithErosionBoxLong")
LONG_RUNS = (("base", 0.2), ("collisionless", 0.1), ("nondissipative", 0.1),
             ("erosion16", 0.2))


def dip_share(s):
    """Share of the steps with N_e at least ONSET grains below its running
    maximum (negative erosion)."""
    ne = s["erosionNumber"]
    return float(np.mean(np.maximum.accumulate(ne) - ne >= erosion.ONSET))


@pytest.mark.long
def test_erosion_box_berger_findings():
    figs = {name: [] for name, _ in LONG_RUNS}
    dips = {name: [] for name, _ in LONG_RUNS}
    for k in (1, 2, 3):
        case = os.path.join(LONG, f"seed{k}")
        if os.path.exists(case):
            shutil.rmtree(case)
        shutil.copytree(HERE, case, ignore=shutil.ignore_patterns("runs", "__pycache__", "*.py"))
        erosion.write_bed(case, seed(k))
        for name, plume in LONG_RUNS:
            subprocess.run(["./Allrun", "-variant", name, "-plume", str(plume)], cwd=case,
                           check=True, stdout=subprocess.DEVNULL)
            s = erosion.read(os.path.join(case, "runs", name))
            figs[name].append(erosion.figures(s))
            dips[name].append(dip_share(s))

    def mean(name, key):
        values = [f[key] for f in figs[name]]
        return None if None in values else float(np.mean(values))

    depleted = mean("base", "depleted")
    ok_depleted = report("depletion by about 0.15 s (Berger; the calibration)",
                         depleted is not None and 0.10 <= depleted <= 0.20,
                         f"95 % eroded at {depleted} s (mean of 3 seeds), in [0.10, 0.20] s")
    negative = mean("base", "negative")
    ok_negative = report("negative erosion from about 0.04 s (Berger)",
                         negative is not None and 0.02 <= negative <= 0.08,
                         f"first dip at {negative} s (mean of 3 seeds), in [0.02, 0.08] s")
    ok_order = True
    for at in (0.05, 0.1):
        n = {name: mean(name, f"Ne{at}") for name in ("nondissipative", "collisionless", "base")}
        ok_order &= report(f"ordering at {at} s: nondissipative > collisionless > dissipative",
                           n["nondissipative"] > n["collisionless"] > n["base"],
                           ", ".join(f"{name} {v:.0f}" for name, v in n.items()))
    share16, share = float(np.mean(dips["erosion16"])), float(np.mean(dips["base"]))
    ok_vanish = report("16 d erosion plane: negative erosion vanishes",
                       share16 < 0.1*share and share > 0.10,
                       f"steps 5 grains below the running maximum: erosion16 {100*share16:.2f} %,"
                       f" base {100*share:.1f} % (3 seeds)")
    assert ok_depleted and ok_negative and ok_order and ok_vanish
