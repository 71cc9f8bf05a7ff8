# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The DEM test box (validation/demContacts/box: a walled cube of 10 mm,
no gas) and its grains: d = 1 mm, rho = 2700 kg/m^3, k_n = 8000 N/m
(Berger et al. 2013, Table II); the linear spring-dashpot's contact time
in closed form, and the grains placed in a case through positions files.
Used by validation/demContacts and validation/exactRestart's DEM family."""

import math
import os

D = 1e-3                    # grain diameter [m]
R = D/2
RHO = 2700.0                # [kg/m^3]
MASS = RHO*math.pi*D**3/6   # one grain [kg]
KN = 8000.0                 # [N/m]
L = 0.01                    # box side [m]


def zeta(e):
    """The damping ratio of a linear spring-dashpot of restitution e."""
    lne = math.log(e)
    return -lne/math.sqrt(math.pi**2 + lne**2)


def contact_time(e, m_eff, k=KN):
    """Its contact time t_c for effective mass m_eff and stiffness k."""
    w = math.sqrt(k/m_eff)
    return math.pi/(w*math.sqrt(1 - zeta(e)**2))


def write_grains(case, groups, seed=1):
    """groups: name -> (positions (n, 3), U0, sigmaU)."""
    regions = []
    for name, (xs, U0, sigmaU) in groups.items():
        with open(os.path.join(case, "constant", name + "Positions"), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class vectorField;"
                    f" object {name}Positions; }}\n{len(xs)}\n(\n")
            for x in xs:
                f.write(f"({x[0]:.17g} {x[1]:.17g} {x[2]:.17g})\n")
            f.write(")\n")
        regions.append(
            f"    {name} {{ type positionsFile; file {name}Positions;"
            f" nParticle 1; d {D}; U0 ({U0[0]:.17g} {U0[1]:.17g} {U0[2]:.17g});"
            f" sigmaU {sigmaU}; }}\n")
    with open(os.path.join(case, "system", "grainsInitialiseDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary;"
                " object grainsInitialiseDict; }\n"
                f"randomSeed {seed};\nregions\n{{\n" + "".join(regions) + "}\n")
