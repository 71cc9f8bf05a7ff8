# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""dustCloudStream, reduced (200 steps, 0.2 ms, written every 100), every
coupling type of Allrun-types (its `types=` line), each through the case's
Allrun; a type the solver does not know fails (a missing model is a fault,
not a skip).

Checks (physical, each able to fail):
- none: every parcel keeps its initial velocity (0) and temperature
  (300 K) exactly.
- every other type: the grains speed up and heat up (mean U_x and T rise
  between writes), and the mean velocity along the stream at 0.1 and
  0.2 ms equals the integral of the drag of a grain at rest in the
  nominal free stream (n = 1e21 m^-3 argon, 1000 K, 500 m/s):

      dv/dt = (3/4) C_D rho_g (U - v)^2/(rho_p d),

  C_D the free-molecular sphere's (doc/physics.md 4.2; validation/dragLaws/
  reference.py, independent of the C++) for the free-molecular models
  (oneWay, twoWayDirect, twoWayIndirect, adaptive: Kn_p = lambda/d ~ 3800
  >> KnSwitch) and Loth's for
  Loth (mu from the VHS law at 1000 K), with T_p(t) the run's mean grain
  temperature (linear between writes), by RK4.  Tolerance 3 %: the
  estimate uses the nominal stream, while the grains feel the realized
  gas of their cells, whose density and temperature fluctuate by a few %
  over the ~1000 simulators around the cloud (measured: oneWay +1.0 %,
  +1.4 % at 0.1 and 0.2 ms).
"""

import math
import os
import re
import subprocess
import sys

import numpy as np
import pytest

from rmf import foam, grainseries

HERE = os.path.dirname(os.path.abspath(__file__))
BUILD = os.path.join(foam.PROJECT_DIR, "build", "tutorials", "dustCloudStream")
sys.path.insert(0, os.path.join(foam.PROJECT_DIR, "validation", "dragLaws"))
from reference import cd_fm_closed, loth_cd  # noqa: E402

with open(os.path.join(HERE, "Allrun-types")) as _f:
    TYPES = re.search(r'^types="([^"]*)"', _f.read(), re.M).group(1).split()

K = 1.380649e-23
M_AR, D_AR, OMEGA, T_REF = 66.3e-27, 4.17e-10, 0.81, 273.0
N_GAS, T_GAS, U_GAS = 1e21, 1000.0, 500.0
D_P, RHO_P, T_P0 = 5e-7, 1500.0, 300.0
STEPS, EVERY, DT = 200, 100, 1e-6
TOL = 0.03


def expected_velocity(model, t_end, Tp_of_t, n=400):
    """RK4 of the drag on a grain from rest to t_end."""
    rho = N_GAS*M_AR
    mu = (15*math.sqrt(M_AR*K*T_REF/math.pi)
          / (2*(5 - 2*OMEGA)*(7 - 2*OMEGA)*D_AR**2))*(T_GAS/T_REF)**OMEGA

    def dvdt(t, v):
        v0 = U_GAS - v
        if model == "Loth":
            re = rho*v0*D_P/mu
            ma = v0/math.sqrt(5/3*K/M_AR*T_GAS)
            cd = loth_cd(re, ma, 5/3, Tp_of_t(t)/T_GAS)
        else:
            cd = cd_fm_closed(v0/math.sqrt(2*K*T_GAS/M_AR), Tp_of_t(t)/T_GAS)
        return 0.75*cd*rho*v0**2/(RHO_P*D_P)

    v, t, h = 0.0, 0.0, t_end/n
    for _ in range(n):
        k1 = dvdt(t, v)
        k2 = dvdt(t + h/2, v + h/2*k1)
        k3 = dvdt(t + h/2, v + h/2*k2)
        k4 = dvdt(t + h, v + h*k3)
        v += h/6*(k1 + 2*k2 + 2*k3 + k4)
        t += h
    return v


@pytest.mark.parametrize("model", TYPES)
def test_dustCloudStream_reduced(model):
    case = os.path.join(BUILD, model)
    foam.copy_setup(HERE, case)
    for name in ("Allrun",):
        subprocess.run(["cp", os.path.join(HERE, name), case], check=True)
    foam.set_entry(case, "system/controlDict", "endTime", f"{STEPS*DT:.6g}")
    foam.set_entry(case, "system/controlDict", "writeInterval", EVERY)
    proc = subprocess.run([os.path.join(case, "Allrun"), model], cwd=case,
                          capture_output=True, text=True)
    log = os.path.join(case, "log.rarefiedMultiphaseFoam")
    if proc.returncode != 0:
        text = open(log).read() if os.path.exists(log) else ""
        raise AssertionError(proc.stdout + proc.stderr + text[-3000:])
    assert os.path.exists(os.path.join(case, "dustCloudStream.png"))

    s = grainseries.series(case)
    t, n, ux, speed, T = s.T
    assert len(t) == STEPS//EVERY + 1 and np.all(n == 2000), s

    last = os.path.join(case, foam.latest_time(case), "lagrangian", "grains")
    if model == "none":
        U = foam.read_list(os.path.join(last, "U"))
        Tp = foam.read_list(os.path.join(last, "T"))
        ok = np.all(U == 0) and np.all(Tp == T_P0)
        print(f"\n{'PASS' if ok else 'FAIL'} dustCloudStream none: parcels keep U = 0 and "
              f"T = {T_P0:g} K exactly (largest |U| {np.abs(U).max():g} m/s, largest "
              f"|T - T0| {np.abs(Tp - T_P0).max():g} K)")
        assert ok
        return

    assert np.all(np.diff(ux) > 0) and np.all(np.diff(T) > 0), s

    def Tp_of_t(time):
        return float(np.interp(time, t, T))

    errors = []
    for ti, vi in zip(t[1:], ux[1:]):
        v_ref = expected_velocity(model, ti, Tp_of_t)
        errors.append((ti, vi, v_ref, vi/v_ref - 1))
    worst = max(abs(e[3]) for e in errors)
    ok = worst < TOL
    law = "Loth" if model == "Loth" else "free-molecular"
    print(f"\n{'PASS' if ok else 'FAIL'} dustCloudStream {model}: mean grain U_x against the "
          f"{law} drag integral: "
          + ", ".join(f"{1e3*ti:g} ms {vi:.4f} vs {v_ref:.4f} m/s ({100*e:+.2f} %)"
                      for ti, vi, v_ref, e in errors)
          + f" (tolerance {100*TOL:g} %); mean T_p {T[-1]:.2f} K at {1e3*t[-1]:g} ms")
    assert ok, errors
