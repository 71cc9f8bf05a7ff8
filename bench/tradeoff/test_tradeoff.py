# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The speed-accuracy driver (tradeoff.py, rmf.bench): its Pareto front and curve
error against hand-worked cases, and the erosion box's --quick study
(0.05 s of plume, one seed; about 1.5 minutes; with ./Alltest --long
only: it measures the study's settings, a benchmark, while the erosion
box's physics is checked in the default suite by
tutorials/psi/regolithErosionBox's reduced run and validation/
demContacts; the suite's 35-minute budget, testing/README.md).

Checks of the quick study (each able to fail; the reference's own row,
cost 1 and errors 0 by construction, is not checked: it could not fail):
- contact resolution: DEM at t_c/20 stays within 10 % of the t_c/50
  reference in the erosion curve and rate (the issue's error target; a
  coarser contact step that changed the erosion by more would make the
  study's cheap DEM settings wrong); measured 2026-12-06 (the
  calibrated plume): 1.6 % and 0.2 % here, 1.1 % and 0.8 % over 0.2 s
  and 3 seeds;
- NTC alone holds no bed, and the study tells it apart: its erosion
  number at 0.05 s is below 60 % of the DEM's (the bed sinks into itself
  while the gas lifts its top; with the calibrated plume, 2026-12-06,
  the tutorial's runs give 257 against the DEM's 622, 41 %; with the
  previous plume 0 against 166).

The dustCloudStream --quick study (0.1 ms, one seed; about 20 s idle,
--long only: its physics is checked in the default suite by
tutorials/coupling/dustCloudStream's test) and its analytic reference:
- the molecular speed moments relative to the grain, E|w| and E|w|^3 of
  a drifting Maxwellian, against quadrature of the speed's distribution
  (to 1e-8);
- none: the grains neither move nor heat (errors exactly -100 %);
- the free-molecular types (oneWay, twoWayDirect, twoWayIndirect,
  adaptive) at the nominal weight and step: mean U_x and heating against
  the analytic integrals in the nominal stream, within t_limit(19, 8) =
  5.4 times their sd over 20 seeds (FM_SD: the grains feel the realized
  gas of their cells; until 2026-12-06 a flat 3 %, which 3 of those 20
  seeds exceeded in U_x, up to +4.2 %, and the heating up to +5.3 %);
- Loth's Nusselt heat, which leaves out the stream's kinetic energy,
  heats the grains more slowly than the free-molecular sum: its heating
  error is below -20 % (the tutorial's README: 351 K against 383 K at
  1.5 ms, -39 %), so the study tells the two apart (measured -44.7 % at
  0.1 ms, 6.7 times Loth's heating sd over 20 seeds, 3.7 %, below the
  bound).

Family-wise error: 2.5e-4 (rmf_testing.MODULE_ALPHA) over the 8
comparisons above (4 types x U_x and heating; the 4 types gave the same
figures to the last digit for each seed), Student's t with 19 degrees of
freedom; the other checks are exact or effects far beyond their noise.

The Snider --quick study (the narrow column to 0.2 s, one seed; about
50 s idle, --long only: validation/sniderSedimentation checks the
tutorial's physics in the default suite) and its reference, the ideal
settling:
- free_fall_bed against hand-worked figures: Snider's column (alpha_0
  0.3, 0.3 m) has its bed at g t^2/2 and its top at 0.3 - g t^2/2 until
  they meet at t = sqrt(0.3/g) = 0.175 s, h = 0.15 m; every slab mean
  conserves the grains (the column's alpha_0 height at every t);
- the tutorial's setting follows the ideal settling: alpha(z) within
  10 % of alpha_cp (RMS over the slabs) at 0.1, 0.15 and 0.2 s
  (measured 3.3, 4.6, 3.0 %; the Poisson scatter of a packed slab's
  parcel count alone is 4.2 %, so a wrong bed height or level shows
  above it: one slab of 7.5 mm too high or low adds sqrt(1/40) = 16 %);
- dual and cachedDual averaging give the same run (cachedDual caches
  dual's volumes, doc/physics.md#dem): the same errors to the last bit;
- sixteen times fewer parcels are further from the ideal (a packed slab
  then holds 36 parcels: Poisson scatter 17 %; measured 39.6 %).
"""

import csv
import os
import subprocess
import sys

import numpy as np
import pytest
from scipy import integrate

import tradeoff
from rmf import bench, kinetic
from rmf_testing import report, t_limit

HERE = os.path.dirname(os.path.abspath(__file__))


def test_pareto_front():
    # (cost, error): a, b, c on the front; d beaten by b; e ties c's
    # cost with a larger error; f has no error (not placed)
    cost = [1.0, 0.5, 0.1, 0.6, 0.1, 0.05]
    error = [0.0, 0.1, 0.5, 0.2, 0.7, np.nan]
    front = bench.pareto_front(cost, error)
    assert report("Pareto front", front == [2, 1, 0], f"{front} (expected [2, 1, 0])")


def test_curve_error():
    # y = 2t against y_ref = t on [0, 1]: RMS of t over y_ref(1) = 1,
    # sqrt(mean t^2) on a grid of 1001 points = sqrt(1/3) to 1e-3
    t = np.linspace(0, 1, 11)
    grid = np.linspace(0, 1, 1001)
    e = bench.curve_error(t, 2*t, t, t, grid)
    assert report("curve error", abs(e - np.sqrt(1/3)) < 1e-3,
                  f"{e:.5f} vs sqrt(1/3) = {np.sqrt(1/3):.5f}")


@pytest.mark.long
def test_erosion_box_quick():
    subprocess.run([sys.executable, os.path.join(HERE, "tradeoff.py"), "erosionBox",
                    "--quick"], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(tradeoff.OUT, "erosionBox", "tradeoff.csv")) as f:
        rows = {r["setting"]: r for r in csv.DictReader(f)}
    names = [n for n, _ in tradeoff.EROSION_SETTINGS]
    ref = rows["base"]
    ok_all = report("every setting ran", sorted(rows) == sorted(names),
                    f"{len(rows)} of {len(names)}")
    s20 = rows["steps20"]
    ok_20 = report("DEM at t_c/20 within 10 % of t_c/50",
                   abs(float(s20["curve"])) < 0.1 and abs(float(s20["rate"])) < 0.1,
                   f"curve {100*float(s20['curve']):.1f} %, rate {100*float(s20['rate']):.1f} %")
    ok_ntc = report("NTC alone holds no bed",
                    float(rows["ntc"]["Ne"]) < 0.6*float(ref["Ne"]),
                    f"N_e {float(rows['ntc']['Ne']):.0f} against the DEM's {float(ref['Ne']):.0f}")
    assert ok_all and ok_20 and ok_ntc


def test_speed_moments():
    # The speed c = |w| of a Maxwellian of unit c_m = sqrt(2kT/m) drifting
    # at s has the density c/(s sqrt(pi)) [exp(-(c-s)^2) - exp(-(c+s)^2)]
    worst = 0.0
    for s in (1e-3, 0.3, 1.0, 2.5, 8.0):
        def pdf(c):
            return c/(s*np.sqrt(np.pi))*(np.exp(-(c - s)**2) - np.exp(-(c + s)**2))
        m1 = integrate.quad(lambda c: c*pdf(c), 0, s + 12, epsabs=0, epsrel=1e-12)[0]
        m3 = integrate.quad(lambda c: c**3*pdf(c), 0, s + 12, epsabs=0, epsrel=1e-12)[0]
        c1, c3 = kinetic.speed_moments(s)
        worst = max(worst, abs(c1/m1 - 1), abs(c3/m3 - 1))
    assert report("speed moments against quadrature", worst < 1e-8, f"largest {worst:.1e}")


# sd of the free-molecular departures from the analytic integrals at
# 0.1 ms in the nominal stream, U_x and heating, over seeds
# rmf_testing.seed(100..119) (tutorial settings, 2026-12-06)
FM_SD = {"U": 0.0167, "heating": 0.0232}
FM_TOL = {e: t_limit(19, 8)*sd for e, sd in FM_SD.items()}


@pytest.mark.long
def test_dust_cloud_stream_quick():
    subprocess.run([sys.executable, os.path.join(HERE, "tradeoff.py"), "dustCloudStream",
                    "--quick"], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(tradeoff.OUT, "dustCloudStream", "tradeoff.csv")) as f:
        rows = {r["setting"]: r for r in csv.DictReader(f)}
    names = [s[0] for s in tradeoff.STREAM_SETTINGS]
    ok_all = report("every setting ran", sorted(rows) == sorted(names),
                    f"{len(rows)} of {len(names)}")
    none = rows["none"]
    ok_none = report("none: no motion, no heating",
                     float(none["U"]) == -1 and float(none["heating"]) == -1,
                     f"U {none['U']}, heating {none['heating']}")
    fm = ("oneWay", "twoWayDirect", "twoWayIndirect", "adaptive")
    ok_fm = report("free-molecular types against the analytic integrals",
                   all(abs(float(rows[n][e])) < tol for n in fm for e, tol in FM_TOL.items()),
                   ", ".join(f"{n} U {100*float(rows[n]['U']):+.2f} %, heating "
                             f"{100*float(rows[n]['heating']):+.2f} %" for n in fm)
                   + f" (tolerances {100*FM_TOL['U']:.1f} %, {100*FM_TOL['heating']:.1f} %)")
    loth = float(rows["Loth"]["heating"])
    ok_loth = report("Loth heats more slowly", loth < -0.2, f"heating {100*loth:+.1f} %")
    assert ok_all and ok_none and ok_fm and ok_loth


def test_free_fall_bed():
    g, height, alpha0 = 9.8, 0.3, 0.3
    edges = np.linspace(0, height, 41)
    worst = 0.0
    for t in (0.05, 0.1, 0.15, 0.175, 0.3):
        a, bed = tradeoff.snider.free_fall_bed(t, edges, alpha0, height, 0.6, g)
        expect = min(g*t*t/2, 0.15)
        worst = max(worst, abs(bed - expect), abs(float(np.sum(a*np.diff(edges)))
                                                  - alpha0*height))
    assert report("ideal settling", worst < 1e-12, f"largest deviation {worst:.1e}")


@pytest.mark.long
def test_snider_quick():
    subprocess.run([sys.executable, os.path.join(HERE, "tradeoff.py"), "snider", "--quick"],
                   check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(tradeoff.OUT, "snider", "tradeoff.csv")) as f:
        rows = {r["setting"]: r for r in csv.DictReader(f)}
    names = [s[0] for s in tradeoff.SNIDER_SETTINGS]
    ok_all = report("every setting ran", sorted(rows) == sorted(names),
                    f"{len(rows)} of {len(names)}")
    times = ("t0.1", "t0.15", "t0.2")
    base = rows["base"]
    ok_base = report("the tutorial's setting within 10 % of the ideal settling",
                     all(float(base[t]) < 0.1 for t in times),
                     ", ".join(f"{t[1:]} s {100*float(base[t]):.1f} %" for t in times))
    ok_dual = report("dual and cachedDual the same",
                     all(rows["dual"][e] == base[e] for e in times),
                     f"profile {rows['dual']['profile']} and {base['profile']}")
    w16 = rows["weight16"]
    ok_w16 = report("W x 16 further from the ideal",
                    float(w16["profile"]) > float(base["profile"]),
                    f"{100*float(w16['profile']):.1f} % against {100*float(base['profile']):.1f} %")
    assert ok_all and ok_base and ok_dual and ok_w16
