# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Kinetic-theory references for the grains' drag and heat, computed apart
from the C++ (src/coupling/dragLaws): the laws use the math module only,
so they stand as an independent typing of doc/physics.md#one-way and #loth.
validation/dragLaws/reference.py makes Test-dragLaws' reference table from
them, and validation/dragLaws/test_reference.py checks them.

Free-molecular sphere drag C_D(s): not from the closed form of doc/physics.md#one-way
but by integrating over the sphere the momentum flux of a drifting
Maxwellian gas onto a flat surface element with diffuse re-emission at the
wall temperature (pressure and shear of the element from kinetic theory:
incident flux of a drifting Maxwellian, half-Maxwellian re-emission; e.g.
Schaaf & Chambre 1958, Bird 1994 ch. 7).  Composite Simpson rule in the
polar angle; the closed form is given next to it as a cross-check.

Loth (2008) drag and lift and his Nusselt heat: doc/physics.md#loth typed
here again, term by term.  A typing error shared by the doc, this module
and the C++ would pass the tables; Test-dragLaws therefore also checks the
C++ against laws published apart from Loth's, which his correlation
reduces to in its limits: Stokes, Schiller-Naumann over the Cunningham
factor as Davies (1945) fitted it, Clift-Gauvin at Ma = 0, the
free-molecular sphere at Re -> 0, Saffman's shear lift.  Tabulated values
of Loth's own were not at hand.

analytic_grain integrates a grain's velocity and temperature in a uniform
stream with these laws (bench/tradeoff's dustCloudStream scene and
tutorials/coupling/dustCloudStream's test); stream_case_data reads its
stream and grain from such a case.

The VHS gas's viscosity, mean collision time and mean free path (Bird
1994 eqs. 4.62-4.65): the expected values of the gas's tests and
benchmarks.
"""

import math

import numpy as np

from rmf import foam

SQRT_PI = math.sqrt(math.pi)
K_B = 1.380649e-23


# ---------------------------------------------------------------------------
# The VHS gas (the tests' and benchmarks' expected transport and times)

def vhs_viscosity(T, mass, d, omega, T_ref=273.0):
    """VHS viscosity at T [Pa s], Chapman-Enskog first approximation
    (Bird 1994 eq. 4.62; d the diameter at T_ref)."""
    return (15*math.sqrt(mass*K_B*T_ref/math.pi)/(2*(5 - 2*omega)*(7 - 2*omega)*d**2)
            * (T/T_ref)**omega)


def vhs_collision_time(n, T, mass, d, omega, T_ref=273.0):
    """VHS mean collision time at n and T [s] (Bird 1994 eq. 4.64)."""
    return 1/(4*n*d*d*math.sqrt(math.pi*K_B*T_ref/mass)*(T/T_ref)**(1 - omega))


def vhs_mean_free_path(n, T, d, omega, T_ref=273.0):
    """VHS mean free path at n and T [m] (Bird 1994 eq. 4.65)."""
    return (T/T_ref)**(omega - 0.5)/(math.sqrt(2)*math.pi*d*d*n)


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
    """doc/physics.md#one-way closed form (for the cross-check column only)."""
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
    """Free-molecular heat of a fully accommodating sphere
    (doc/physics.md#one-way) over pi R^2 n k T_g c_m: the molecules that strike
    it bring their kinetic energy in its frame, E|w|^3 m/2 = k T_g c_m
    E|w/c_m|^3, and
    leave with 2 k T_p each."""
    m1, m3 = speed_moments(s)
    return m3 - 2*tp_by_tg*m1


# ---------------------------------------------------------------------------
# Loth (2008), doc/physics.md#loth

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
    """C_L(Re, omega*) with Omega* = omega*/2 (doc/physics.md#loth)."""
    if omega <= 0:
        return 0.0
    eps = math.sqrt(omega/re)
    j = (0.3*(1 + math.tanh(2.5*(math.log10(eps) + 0.191)))
         * (2/3 + math.tanh(6*eps - 1.92)))
    spin = omega/2
    cl_spin = 1 - (0.675 + 0.15*(1 + math.tanh(0.28*(spin - 2)))) \
        * math.tanh(0.18*math.sqrt(re))
    return 12.92/math.pi*j*eps + spin*cl_spin


def nusselt(re, kn, gamma, pr):
    """Loth's heat (doc/physics.md#loth): Ranz-Marshall's continuum Nu_c,
    the free-molecular Nu_fm of a sphere at rest (alpha_T = 1), and
    Sherman's interpolation between them."""
    nu_c = 2 + 0.6*math.sqrt(re)*pr**(1/3)
    nu_fm = (gamma + 1)*pr/(4*gamma*kn)
    return nu_c/(1 + nu_c/nu_fm)


# ---------------------------------------------------------------------------
# A grain in a uniform stream

def analytic_grain(gas, grain, t_end, law="freeMolecular", n=2000):
    """Velocity and temperature of a grain from rest at T0 in a uniform
    monatomic stream, by RK4 of
        m_p dv/dt = 1/2 rho (U - v)^2 pi R^2 C_D,   m_p c_p dT_p/dt = Q.
    law "freeMolecular": C_D(s, T_p/T_g), the closed form cd_fm_closed,
    and
        Q = pi R^2 n [m/2 E|w|^3 - 2 k T_p E|w|],
    the free-molecular drag and heat of a fully accommodating, diffusely
    re-emitting sphere (doc/physics.md#one-way): the molecules that strike the
    grain bring their kinetic energy in its frame and leave with 2 k T_p
    each.  law "Loth": loth_cd's Loth C_D(Re, Ma, gamma, T_p/T_g) and
    Nusselt heat Q = Nu pi d kappa (T_g - T_p) (doc/physics.md#loth; alpha_T
    1, Eucken's Pr 2/3, kappa = mu c_p,g/Pr), mu the VHS law's at T_g
    (gas's d, omega, Tref: doc/physics.md#cell-averages), as the solver's gas
    dsmc
    takes it from the cell's averaged temperature."""
    m, nd, Tg, U = gas["m"], gas["n"], gas["T"], gas["U"]
    d, rho_p, cp = grain["d"], grain["rho"], grain["cp"]
    area = math.pi*d*d/4
    mass = rho_p*math.pi*d**3/6
    cm = math.sqrt(2*K_B*Tg/m)
    if law == "Loth":
        gamma, pr, R = 5/3, 2/3, K_B/m
        mu = (15*math.sqrt(m*K_B*gas["Tref"]/math.pi)
              / (2*(5 - 2*gas["omega"])*(7 - 2*gas["omega"])*gas["dRef"]**2)
              * (Tg/gas["Tref"])**gas["omega"])
        kappa = mu*gamma*R/((gamma - 1)*pr)
        kn = mu/(nd*m*d)*math.sqrt(math.pi/(2*R*Tg))

    def rates(y):
        v, Tp = y
        u = U - v
        s = u/cm
        if law == "Loth":
            re = nd*m*u*d/mu
            drag = 0.5*nd*m*u*u*area*loth_cd(re, u/math.sqrt(gamma*R*Tg), gamma, Tp/Tg)
            heat = nusselt(re, kn, gamma, pr)*math.pi*d*kappa*(Tg - Tp)
        else:
            m1, m3 = speed_moments(s)
            drag = 0.5*nd*m*u*u*area*cd_fm_closed(s, Tp/Tg) if s > 0 else 0.0
            heat = area*nd*(0.5*m*m3*cm**3 - 2*K_B*Tp*m1*cm)
        return np.array([drag/mass, heat/(mass*cp)])

    y = np.array([0.0, grain["T0"]])
    h = t_end/n
    for _ in range(n):
        k1 = rates(y)
        k2 = rates(y + h/2*k1)
        k3 = rates(y + h/2*k2)
        k4 = rates(y + h*k3)
        y = y + h/6*(k1 + 2*k2 + 2*k3 + k4)
    return float(y[0]), float(y[1])


def stream_case_data(case):
    """The stream's and the grains' properties, read from the case."""
    def get(d, e):
        return float(foam.get_entry(case, d, e).strip("()").split()[0])
    props, grains = "constant/dsmcProperties", "constant/grainsProperties"
    inlet = "PatchInflowCoeffs/inlet/"
    gas = {"m": get(props, "moleculeProperties/Ar/mass"), "n": get(props, inlet + "n"),
           "T": get(props, inlet + "T"), "U": get(props, inlet + "U"),
           "dRef": get(props, "moleculeProperties/Ar/diameter"),
           "omega": get(props, "moleculeProperties/Ar/omega"),
           "Tref": get(props, "VariableHardSphereCoeffs/Tref")}
    grain = {"d": get("system/grainsInitialiseDict", "regions/cloud/d"),
             "rho": get(grains, "constantProperties/rho0"),
             "cp": get(grains, "constantProperties/Cp0"),
             "T0": get(grains, "constantProperties/T0")}
    return gas, grain
