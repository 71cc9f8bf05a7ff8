#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Reference values for applications/test/Test-dragLaws, computed apart from
the C++ (src/coupling/dragLaws) with the Python standard library only.

    /usr/bin/python3 validation/dragLaws/reference.py          # print the table
    /usr/bin/python3 validation/dragLaws/reference.py --header # the C++ header

The header it writes, applications/test/Test-dragLaws/dragLawsReference.H,
is committed; validation/dragLaws/test_reference.py fails when it no longer
matches what this script makes.  Changing a reference value is a reviewed
commit with a reason (STYLE.md).

Free-molecular sphere drag C_D(s): not from the closed form of doc/physics.md 4.2
but by integrating over the sphere the momentum flux of a drifting
Maxwellian gas onto a flat surface element with diffuse re-emission at the
wall temperature (pressure and shear of the element from kinetic theory:
incident flux of a drifting Maxwellian, half-Maxwellian re-emission; e.g.
Schaaf & Chambre 1958, Bird 1994 ch. 7).  Composite Simpson rule in the
polar angle; the closed form is printed next to it as a cross-check.

Loth (2008) drag and lift: doc/physics.md 4.5 typed here again, term by term.
A typing error shared by the doc, this script and the C++ would pass these
tables; Test-dragLaws therefore also checks the C++ against laws published
apart from Loth's, which his correlation reduces to in its limits: Stokes,
Schiller-Naumann over the Cunningham factor as Davies (1945) fitted it,
Clift-Gauvin at Ma = 0, the free-molecular sphere at Re -> 0, Saffman's
shear lift.  Tabulated values of Loth's own were not at hand.
"""

import math
import sys

SQRT_PI = math.sqrt(math.pi)


# ---------------------------------------------------------------------------
# Free-molecular sphere, by surface integration

def element_coefficients(s, cos_t, tw_by_tg):
    """Pressure and shear coefficient (over 1/2 rho U^2) of a surface element
    whose inward normal makes angle t with the stream; diffuse re-emission
    at the wall temperature, full accommodation."""
    sn = s*cos_t                                  # normal speed ratio
    st = s*math.sqrt(max(0.0, 1.0 - cos_t*cos_t))  # tangential speed ratio
    e = math.exp(-sn*sn)
    one_erf = 1.0 + math.erf(sn)
    flux = e + SQRT_PI*sn*one_erf  # incident flux / (n c_m / (2 sqrt(pi)))
    p_in = (sn*e/SQRT_PI + (0.5 + sn*sn)*one_erf)/(s*s)
    p_out = 0.5*math.sqrt(tw_by_tg)*flux/(s*s)
    tau = st*flux/(SQRT_PI*s*s)
    return p_in + p_out, tau


def cd_fm_integrated(s, tw_by_tg, n=4000):
    """C_D = (1/(pi R^2)) integral over the sphere of the stream-wise force
          = 2 int_0^pi (C_p cos t + C_tau sin t) sin t dt."""
    h = math.pi/n
    total = 0.0
    for i in range(n + 1):
        t = i*h
        cp, ctau = element_coefficients(s, math.cos(t), tw_by_tg)
        f = (cp*math.cos(t) + ctau*math.sin(t))*math.sin(t)
        w = 1 if i in (0, n) else (4 if i % 2 else 2)
        total += w*f
    return 2.0*total*h/3.0


def cd_fm_closed(s, tp_by_tg):
    """doc/physics.md 4.2 closed form (for the cross-check column only)."""
    s2 = s*s
    return (math.exp(-s2)*(2*s2 + 1)/(SQRT_PI*s**3)
            + math.erf(s)*(4*s2*s2 + 4*s2 - 1)/(2*s2*s2)
            + 2*SQRT_PI/(3*s)*math.sqrt(tp_by_tg))


def speed_moments(s):
    """E|w| and E|w|^3 of the molecular speed relative to a body at drift
    speed ratio s of a Maxwellian, in units of c_m = sqrt(2kT/m) and c_m^3
    (closed forms; checked against quadrature in bench/tradeoff's
    test_tradeoff.py)."""
    e = math.exp(-s*s)/SQRT_PI
    if s < 1e-6:
        return 2/SQRT_PI, 4/SQRT_PI
    erf = math.erf(s)
    m1 = (s + 1/(2*s))*erf + e
    m3 = (s**3 + 3*s + 3/(4*s))*erf + (s*s + 2.5)*e
    return m1, m3


def heat_fm(s, tp_by_tg):
    """Free-molecular heat of a fully accommodating sphere (doc/physics.md
    4.2) over pi R^2 n k T_g c_m: the molecules that strike it bring their
    kinetic energy in its frame, E|w|^3 m/2 = k T_g c_m E|w/c_m|^3, and
    leave with 2 k T_p each."""
    m1, m3 = speed_moments(s)
    return m3 - 2*tp_by_tg*m1


# ---------------------------------------------------------------------------
# Loth (2008), doc/physics.md 4.5

def loth_cd(re, ma, gamma, tp_by_tg):
    if re < 45:
        kn = math.sqrt(math.pi*gamma/2)*ma/re
        s = ma*math.sqrt(gamma/2)
        f_kn = 1/(1 + kn*(2.514 + 0.8*math.exp(-0.55/kn))) if kn > 0 else 1.0
        cd_kn_re = 24/re*(1 + 0.15*re**0.687)*f_kn
        if s > 0:
            cd_fm = cd_fm_closed(s, tp_by_tg)
            cd_fm_re = cd_fm/(1 + (cd_fm/1.63 - 1)*math.sqrt(re/45))
        else:
            cd_fm_re = 1.63/math.sqrt(re/45)   # cd_fm -> infinity
        m4 = ma**4
        return cd_kn_re/(1 + m4) + m4*cd_fm_re/(1 + m4)
    if ma <= 1.45:
        c_m = 5/3 + 2/3*math.tanh(3*math.log(ma + 0.1))
    else:
        c_m = 2.044 + 0.2*math.exp(-1.8*math.log(ma/1.5)**2)
    if ma <= 0.89:
        g_m = 1 - 1.525*ma**4
    else:
        g_m = 0.0002 + 0.0008*math.tanh(12.77*(ma - 2.02))
    h_m = 1 - 0.258*c_m/(1 + 514*g_m)
    return (24/re*(1 + 0.15*re**0.687)*h_m
            + 0.42*c_m/(1 + 42500*g_m/re**1.16))


def loth_cl(re, omega):
    """C_L(Re, omega*) with Omega* = omega*/2 (doc/physics.md 4.5)."""
    if omega <= 0:
        return 0.0
    eps = math.sqrt(omega/re)
    j = (0.3*(1 + math.tanh(2.5*(math.log10(eps) + 0.191)))
         * (2/3 + math.tanh(6*eps - 1.92)))
    spin = omega/2
    cl_spin = 1 - (0.675 + 0.15*(1 + math.tanh(0.28*(spin - 2)))) \
        * math.tanh(0.18*math.sqrt(re))
    return 12.92/math.pi*j*eps + spin*cl_spin


# ---------------------------------------------------------------------------
# The table

FM_POINTS = [(0.01, 1.0), (0.1, 1.0), (0.5, 1.0), (1.0, 1.0), (2.0, 1.0),
             (5.0, 1.0), (1.0, 0.25), (2.0, 4.0)]

# (Re, Ma, gamma, Tp/Tg): both branches, every C_M / G_M piece
LOTH_CD_POINTS = [
    (0.1, 0.05, 1.4, 1.0), (1.0, 0.3, 1.4, 1.0), (10.0, 0.8, 5/3, 1.0),
    (30.0, 2.0, 1.4, 0.5), (44.0, 4.0, 1.4, 1.0), (0.5, 6.0, 5/3, 2.0),
    (45.0, 0.5, 1.4, 1.0), (100.0, 0.3, 1.4, 1.0), (1000.0, 0.95, 1.4, 1.0),
    (300.0, 1.2, 1.4, 1.0), (1e4, 2.5, 1.4, 1.0), (2e5, 0.1, 1.4, 1.0),
    (1e4, 0.0, 1.4, 1.0),
]

# (Re, omega*)
def nusselt(re, kn, gamma, pr):
    """Loth's heat (doc/physics.md 4.5): Ranz-Marshall's continuum Nu_c,
    the free-molecular Nu_fm of a sphere at rest (alpha_T = 1), and
    Sherman's interpolation between them."""
    nu_c = 2 + 0.6*math.sqrt(re)*pr**(1/3)
    nu_fm = (gamma + 1)*pr/(4*gamma*kn)
    return nu_c/(1 + nu_c/nu_fm)


LOTH_CL_POINTS = [(0.1, 0.01), (1.0, 0.1), (10.0, 0.5), (40.0, 0.2),
                  (100.0, 1.0), (500.0, 4.0)]


def table():
    fm = [(s, r, cd_fm_integrated(s, r), cd_fm_closed(s, r)) for s, r in FM_POINTS]
    cd = [(re, ma, g, r, loth_cd(re, ma, g, r)) for re, ma, g, r in LOTH_CD_POINTS]
    cl = [(re, w, loth_cl(re, w)) for re, w in LOTH_CL_POINTS]
    return fm, cd, cl


def header():
    fm, cd, cl = table()
    out = [
        "// rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors",
        "// SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)",
        "// Generated by validation/dragLaws/reference.py --header: do not edit.",
        "// Free-molecular sphere C_D by surface integration of the kinetic",
        "// momentum flux (diffuse, full accommodation); Loth (2008) C_D, C_L",
        "// from doc/physics.md 4.5 typed apart from the C++.",
        "",
        "// {s, Tp/Tg, C_D}",
        "static const double fmReference[][3] =",
        "{",
    ]
    out += ["    {%r, %r, %.17g}," % (s, r, v) for s, r, v, _ in fm]
    out += ["};", "", "// {Re, Ma, gamma, Tp/Tg, C_D}",
            "static const double lothCdReference[][5] =", "{"]
    out += ["    {%r, %r, %r, %r, %.17g}," % (re, ma, g, r, v)
            for re, ma, g, r, v in cd]
    out += ["};", "", "// {Re, omegaStar, C_L}",
            "static const double lothClReference[][3] =", "{"]
    out += ["    {%r, %r, %.17g}," % (re, w, v) for re, w, v in cl]
    out += ["};", ""]
    return "\n".join(out)


def main():
    if "--header" in sys.argv:
        sys.stdout.write(header())
        return
    fm, cd, cl = table()
    print("free-molecular C_D(s): s  Tp/Tg  integrated  closed  rel.diff")
    for s, r, v, c in fm:
        print("  %5g %5g  %.12f  %.12f  %.2e" % (s, r, v, c, abs(v - c)/c))
    print("Loth C_D: Re  Ma  gamma  Tp/Tg  C_D")
    for re, ma, g, r, v in cd:
        print("  %8g %5g %6.4f %4g  %.10f" % (re, ma, g, r, v))
    print("Loth C_L: Re  omega*  C_L")
    for re, w, v in cl:
        print("  %8g %6g  %.10f" % (re, w, v))


if __name__ == "__main__":
    main()
