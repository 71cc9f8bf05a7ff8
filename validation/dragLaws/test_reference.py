# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The reference table of Test-dragLaws (applications/test/Test-dragLaws/
dragLawsReference.H) is what validation/dragLaws/reference.py makes: a
changed reference is a reviewed commit, never a silent edit.  The
kinetic-theory references it is made from are rmf.kinetic's, checked
here too."""

import math
import os
import subprocess
import sys

import reference
from rmf import kinetic

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
HEADER = os.path.join(ROOT, "applications", "test", "Test-dragLaws",
                      "dragLawsReference.H")


def test_header_matches_script():
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "src", "python"))
    made = subprocess.run([sys.executable, os.path.join(HERE, "reference.py"),
                           "--header"], capture_output=True, text=True,
                          check=True, env=env).stdout
    with open(HEADER) as f:
        stored = f.read()
    print("PASS" if made == stored else "FAIL",
          "dragLawsReference.H is reference.py's output")
    assert made == stored


def test_integral_matches_closed_form():
    """The surface integral (the reference) and doc/physics.md#one-way's closed
    form agree to 1e-11 (Simpson with 4000 intervals; at s = 0.01 the closed
    form loses ~3 digits to cancellation in double precision)."""
    worst = 0.0
    for s, ratio in reference.FM_POINTS:
        a = kinetic.cd_fm_integrated(s, ratio)
        b = kinetic.cd_fm_closed(s, ratio)
        worst = max(worst, abs(a - b)/b)
    print("PASS" if worst < 1e-11 else "FAIL",
          "free-molecular C_D: integral vs closed form, worst rel. diff %.2e"
          " (tol 1e-11)" % worst)
    assert worst < 1e-11


# The drag's jump where adaptive switches from Loth to free-molecular
# (its default KnSwitch: Kn_p = 10), argon (gamma 5/3), T_p = T_g, per
# speed ratio s: C_D,Loth/C_D,fm - 1 as rmf.kinetic (hence Test-dragLaws'
# C++, which matches its tables) gives it.  Stored to 4 digits: a change
# of either law moves it, and that is a reviewed commit.
SWITCH_JUMP = {0.05: -0.0363, 0.2: -0.0331, 0.5: -0.0573, 1.0: -0.1111,
               2.0: -0.0815, 5.0: -0.0563}


def test_adaptive_switch_jump():
    """The stability matrix's grain Knudsen number across adaptive's
    switch: the drag is not continuous there.  Loth's rarefied branch
    lies 3-11 % below the free-molecular sphere drag at Kn_p = 10 (the
    most at s = 1), so a grain crossing the switch sees its drag jump by
    that much; doc/speed-accuracy.md states it."""
    gamma, kn = 5/3, 10.0
    worst = 0.0
    rows = []
    for s, stored in SWITCH_JUMP.items():
        ma = s/math.sqrt(gamma/2)
        re = math.sqrt(math.pi*gamma/2)*ma/kn
        jump = kinetic.loth_cd(re, ma, gamma, 1.0)/kinetic.cd_fm_closed(s, 1.0) - 1
        worst = max(worst, abs(jump - stored))
        rows.append(f"s {s:g}: {100*jump:+.2f} %")
    ok = worst < 0.5e-4
    print("PASS" if ok else "FAIL", "drag jump at Kn_p = 10 (Loth over free-molecular):",
          ", ".join(rows), f"(stored to 1e-4, worst difference {worst:.1e})")
    assert ok


# The heat's jump at the same switch: Loth's Nusselt heat over the
# free-molecular heat of the accommodating sphere, both as reference.py
# gives them (Test-dragLaws checks the C++ against its tables; the
# free-molecular heat is the one validation/freeMolecularCoupling checks
# on the solver), argon (gamma 5/3, Eucken's Pr 2/3), Kn_p = 10, per
# grain-to-gas temperature ratio and speed ratio s.  Stored to 4 digits.
HEAT_JUMP = {
    0.5: {0.05: -0.0169, 0.2: -0.0746, 0.5: -0.3097, 1.0: -0.6577, 2.0: -0.9080,
          5.0: -0.9917},
    2.0: {0.05: -0.0120, 0.2: 0.0011, 0.5: 0.0897, 1.0: 0.9271, 2.0: -1.4150,
          5.0: -1.0186},
}


def test_adaptive_switch_heat_jump():
    """The stability matrix's grain Knudsen number across adaptive's
    switch, for the heat.  With Re = sqrt(pi gamma/2) Ma/Kn and
    mu/lambda = rho c_m/sqrt(pi), Loth's Q = Nu pi d kappa (T_g - T_p)
    over pi R^2 n k T_g c_m is Nu 4 Kn gamma (1 - T_p/T_g)/((gamma - 1)
    sqrt(pi) Pr), the free-molecular one E|w/c_m|^3 - 2 (T_p/T_g)
    E|w/c_m|; the two agree as s -> 0 and Kn -> infinity (checked below
    to 1e-6 at Kn 1e8).  At Kn_p = 10 the heat jumps by 1-2 % at
    s = 0.05 (Sherman's interpolation), but Loth's heat has no stream
    kinetic energy (no recovery temperature): the jump reaches -66 % at
    s = 1 for a grain at T_g/2, and for a grain at 2 T_g the
    free-molecular heat changes sign near s = 1.5 while Loth's keeps
    cooling it (-141.5 % at s = 2).  doc/speed-accuracy.md states it."""
    gamma, pr, kn = 5/3, 2/3, 10.0

    def jump(s, tau, kn):
        ma = s/math.sqrt(gamma/2)
        re = math.sqrt(math.pi*gamma/2)*ma/kn
        loth = (kinetic.nusselt(re, kn, gamma, pr)*4*kn*gamma*(1 - tau)
                /((gamma - 1)*math.sqrt(math.pi)*pr))
        return loth/kinetic.heat_fm(s, tau) - 1

    limit = max(abs(jump(1e-7, tau, 1e8)) for tau in HEAT_JUMP)
    worst = 0.0
    rows = []
    for tau, stored in HEAT_JUMP.items():
        for s, value in stored.items():
            j = jump(s, tau, kn)
            worst = max(worst, abs(j - value))
            rows.append(f"T_p/T_g {tau:g}, s {s:g}: {100*j:+.2f} %")
    ok = worst < 0.5e-4 and limit < 1e-6
    print("PASS" if ok else "FAIL", "heat jump at Kn_p = 10 (Loth over free-molecular):",
          ", ".join(rows), f"(stored to 1e-4, worst difference {worst:.1e}; "
          f"the free-molecular limit {limit:.1e}, tolerance 1e-6)")
    assert ok
