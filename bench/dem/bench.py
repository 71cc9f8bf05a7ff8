#!/usr/bin/python3
# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Soft-sphere DEM of rarefiedMultiphaseFoam against LAMMPS on the settle
phase of the regolith erosion box (Berger et al. 2013, Table II).

Box: 10 mm (x, periodic) x 30 mm (y, a floor at y = 0 and a lid at 30 mm)
x 5 mm (z, periodic); 800 grains, d = 1 mm, rho = 2700 kg/m^3; lunar
gravity 1.63 m/s^2 (-y); linear spring-dashpot with Coulomb friction,
k_n = k_t = 8000 N/m, e = 0.8, mu = 0.2, eta_t = eta_n/2, grain-grain
and grain-wall alike; dt = t_c/50 = 5.92e-7 s (t_c of a grain pair).
Start: the erosion box's loose lattice at rest (rmf.erosion.bed_positions,
one jitter seed per --seeds).

Peer: LAMMPS (Debian's `lammps`, installed by this script with apt when
missing), pair_style gran/hooke/history with Kn = Kt = 8000 N/m, gamma_n =
eta_n/m_eff for the grain pair (LAMMPS' damping is per unit effective
mass), gamma_t = gamma_n/2, xmu = 0.2, dampflag 1; fix wall/gran with the
same coefficients for the floor and lid (LAMMPS takes m_eff = m there
with the same gamma_n, so its wall restitution is that of a damping
sqrt(2) times ours: 0.73 instead of 0.8); fix nve/sphere (velocity
Verlet); neighbour skin 0.2 mm, rebuilt as needed.  Same positions, same
dt, same steps.

Ours: demSolidCloud with collisionModel cartesianContacts (the contacts
in sub-steps of dt inside case steps of PER_CASE_STEP of them); the
previous code, pairCollision with the same contacts (a case step per
contact step), for --pair-steps steps.

Measured, one run each, serially and one after the other:
- CPU time per grain-step (contact step): ours from the solver's
  ExecutionTime between its first and last case step; LAMMPS from its
  "Loop time"; the ratio ours/LAMMPS (target: <= 2), and pairCollision's
  over ours;
- with --settle (the whole settle, 0.25 s: 420 000 steps): the settled
  bed height (mean of the 20 highest centres + d/2) and the packing
  fraction between 2 d above the floor and 2 d below the bed height, in
  both; they should agree within the run-to-run spread of either code
  (--seeds gives each code several jitter seeds to measure it).

    /usr/bin/python3 bench/dem/bench.py [--steps N] [--settle] [--seeds K]
                                        [--pair-steps N]

Runs under build/bench/dem.  Prints a table and writes
build/bench/dem/results.txt.
"""

import argparse
import math
import os
import re
import shutil
import subprocess
import sys

import numpy as np

from rmf import erosion, foam
from rmf.dem import D, KN, MASS, RHO, zeta

BOX = os.path.join(foam.PROJECT_DIR, "validation", "demContacts", "box")
BUILD = os.path.join(foam.PROJECT_DIR, "build", "bench", "dem")
# cartesianContacts: contact steps per case step (the erosion box's case
# step of 2e-5 s is 34 of them)
PER_CASE_STEP = 34

KT = KN                     # rmf.dem: D, RHO, MASS, KN (Berger's grains)
E = 0.8
MU = 0.2
G = 1.63
LX, LY, LZ = 0.010, 0.030, 0.005
N = 800
SETTLE = 0.25               # [s]

M_EFF = MASS/2
ETA_N = 2*math.sqrt(M_EFF*KN)*zeta(E)
TC = math.pi/math.sqrt(KN/M_EFF - (ETA_N/(2*M_EFF))**2)
DT = TC/50


# ---------------------------------------------------------------------------
# Ours

BLOCKMESH = """FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
scale 0.001;
vertices ((0 0 0) (10 0 0) (10 30 0) (0 30 0) (0 0 5) (10 0 5) (10 30 5) (0 30 5));
blocks (hex (0 1 2 3 4 5 6 7) (10 30 5) simpleGrading (1 1 1));
boundary
(
    xLow  { type cyclic; neighbourPatch xHigh; faces ((0 4 7 3)); }
    xHigh { type cyclic; neighbourPatch xLow;  faces ((1 2 6 5)); }
    floor { type wall; faces ((0 1 5 4)); }
    lid   { type wall; faces ((3 7 6 2)); }
    zLow  { type cyclic; neighbourPatch zHigh; faces ((0 3 2 1)); }
    zHigh { type cyclic; neighbourPatch zLow;  faces ((4 5 6 7)); }
);
"""


def run_ours(x0, steps, name, contacts):
    """Our DEM on the box: contacts "pair" (pairCollision, a case step per
    contact step) or "cartesian" (cartesianContacts, PER_CASE_STEP contact
    steps per case step); CPU per grain-step and the final positions."""
    case = foam.copy_setup(BOX, os.path.join(BUILD, name))
    with open(os.path.join(case, "system", "blockMeshDict"), "w") as f:
        f.write(BLOCKMESH)
    with open(os.path.join(case, "constant", "bedPositions"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class vectorField;"
                f" object bedPositions; }}\n{len(x0)}\n(\n")
        f.writelines(f"({p[0]:.17g} {p[1]:.17g} {p[2]:.17g})\n" for p in x0)
        f.write(")\n")
    with open(os.path.join(case, "system", "grainsInitialiseDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary;"
                " object grainsInitialiseDict; }\nregions\n{\n"
                f"    bed {{ type positionsFile; file bedPositions; nParticle 1;"
                f" d {D}; U0 (0 0 0); }}\n}}\n")
    props = "constant/grainsProperties"
    for path in ("subModels/pairCollisionCoeffs/pairLinearSpringDashpotCoeffs/",
                 "subModels/pairCollisionCoeffs/wallLinearSpringDashpotCoeffs/",
                 "subModels/cartesianContactsCoeffs/grainGrain/",
                 "subModels/cartesianContactsCoeffs/grainWall/"):
        for key, value in (("kn", KN), ("kt", KT), ("e", E), ("mu", MU)):
            foam.set_entry(case, props, path + key, value)
    per_step = 1
    if contacts == "cartesian":
        foam.set_entry(case, props, "subModels/collisionModel", "cartesianContacts")
        per_step = PER_CASE_STEP
    foam.set_entry(case, "constant/g", "value", f"(0 {-G} 0)")
    control = "system/controlDict"
    case_steps = -(-steps//per_step)
    foam.set_entry(case, control, "deltaT", f"{per_step*DT:.17g}")
    foam.set_entry(case, control, "endTime", f"{case_steps*per_step*DT:.17g}")
    foam.set_entry(case, control, "writeInterval", case_steps)
    foam.run(case, "blockMesh")
    foam.run(case, "rarefiedMultiphaseInitialise")
    log = foam.run(case, "rarefiedMultiphaseFoam")
    cpu = foam.execution_times(log)
    path = os.path.join(case, foam.latest_time(case), "lagrangian", "grains")
    x = foam.read_positions(os.path.join(path, "positions"))
    return (cpu[-1] - cpu[0])/((len(cpu) - 1)*per_step*N), x


# ---------------------------------------------------------------------------
# LAMMPS

LAMMPS_IN = """units si
atom_style sphere
atom_modify map array
dimension 3
boundary p f p
comm_modify vel yes
read_data grains.data
pair_style gran/hooke/history {kn} {kt} {gn} {gt} {mu} 1
pair_coeff * *
neighbor 2e-4 bin
neigh_modify delay 0 every 1 check yes
fix integrate all nve/sphere
fix gravity all gravity {g} vector 0 -1 0
fix floor all wall/gran hooke/history {kn} {kt} {gn} {gt} {mu} 1 yplane 0.0 {ly}
timestep {dt}
thermo 10000
run {steps}
write_dump all custom final.dump id x y z modify sort id
"""


def ensure_lammps():
    if shutil.which("lmp"):
        return
    if os.geteuid() != 0:
        sys.exit("bench/dem: LAMMPS (lmp) missing and not root to install it")
    subprocess.run(["apt-get", "install", "-y", "-q", "--no-install-recommends", "lammps"],
                   check=True, env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"))


def run_lammps(x0, steps, name):
    case = os.path.join(BUILD, name)
    if os.path.exists(case):
        shutil.rmtree(case)
    os.makedirs(case)
    with open(os.path.join(case, "grains.data"), "w") as f:
        f.write(f"grains\n\n{len(x0)} atoms\n1 atom types\n\n"
                f"0 {LX} xlo xhi\n0 {LY} ylo yhi\n0 {LZ} zlo zhi\n\nAtoms # sphere\n\n")
        for i, p in enumerate(x0):
            f.write(f"{i + 1} 1 {D} {RHO} {p[0]:.17g} {p[1]:.17g} {p[2]:.17g}\n")
    gn = ETA_N/M_EFF
    with open(os.path.join(case, "in.settle"), "w") as f:
        f.write(LAMMPS_IN.format(kn=KN, kt=KT, gn=gn, gt=gn/2, mu=MU, g=G, ly=LY,
                                 dt=f"{DT:.17g}", steps=steps))
    with open(os.path.join(case, "log.lammps.out"), "w") as out:
        subprocess.run(["lmp", "-in", "in.settle"], cwd=case, stdout=out,
                       stderr=subprocess.STDOUT, check=True)
    with open(os.path.join(case, "log.lammps.out")) as f:
        text = f.read()
    loop = float(re.search(r"Loop time of ([0-9.eE+-]+) on", text).group(1))
    with open(os.path.join(case, "final.dump")) as f:
        lines = f.read().split("ITEM: ATOMS id x y z")[1].split("\n")
    x = np.array([[float(v) for v in ln.split()[1:]] for ln in lines if ln.strip()])
    return loop/(steps*N), x


# ---------------------------------------------------------------------------


def bed(x):
    """Bed height (20 highest centres + d/2) and packing fraction between
    2 d above the floor and 2 d below the bed height."""
    top = np.sort(x[:, 1])[-20:].mean() + D/2
    lo, hi = 2*D, top - 2*D
    inside = (x[:, 1] > lo) & (x[:, 1] < hi)
    return top, inside.sum()*math.pi*D**3/6/((hi - lo)*LX*LZ)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=20000)
    parser.add_argument("--settle", action="store_true",
                        help=f"run the whole settle ({SETTLE} s) and compare the beds")
    parser.add_argument("--seeds", type=int, default=1)
    parser.add_argument("--pair-steps", type=int, default=2000,
                        help="steps of the previous code (pairCollision), 0: none")
    args = parser.parse_args()
    steps = int(round(SETTLE/DT)) if args.settle else args.steps
    ensure_lammps()
    os.makedirs(BUILD, exist_ok=True)
    print(f"bench/dem: {N} grains, dt = {DT:.4e} s (t_c/50), {steps} steps")
    rows = []
    for seed in range(1, args.seeds + 1):
        x0 = erosion.bed_positions(seed)
        ours, x_ours = run_ours(x0, steps, f"ours-{seed}", "cartesian")
        theirs, x_lmp = run_lammps(x0, steps, f"lammps-{seed}")
        rows.append((seed, ours, theirs, bed(x_ours), bed(x_lmp)))
    lines = [f"{'seed':>4} {'ours us/grain-step':>20} {'LAMMPS':>10} {'ratio':>7}"
             f" {'bed ours mm':>12} {'bed LAMMPS':>11} {'alpha ours':>11} {'alpha LAMMPS':>13}"]
    for seed, ours, theirs, (h1, a1), (h2, a2) in rows:
        lines.append(f"{seed:>4} {1e6*ours:>20.3f} {1e6*theirs:>10.3f} {ours/theirs:>7.2f}"
                     f" {1e3*h1:>12.3f} {1e3*h2:>11.3f} {a1:>11.3f} {a2:>13.3f}")
    if not args.settle:
        lines.append("(bed figures only mean something with --settle)")
    ratio = min(r[1] for r in rows)/min(r[2] for r in rows)
    lines.append(
        f"bench dem: ratio ours/LAMMPS = {ratio:.1f} (target <= 2)"
        f"{'' if ratio <= 2 else ' MISSES TARGET'}; {N} grains, {steps} steps;"
        f" ours {1e6*min(r[1] for r in rows):.3f}, LAMMPS {1e6*min(r[2] for r in rows):.3f}"
        " us CPU per grain-step")
    if args.pair_steps:
        pair, _ = run_ours(erosion.bed_positions(1), args.pair_steps, "pair-1", "pair")
        best = min(r[1] for r in rows)
        lines.append(
            f"bench dem: cartesianContacts against pairCollision (the previous code,"
            f" first {args.pair_steps} steps): {pair/best:.1f} times faster;"
            f" pairCollision {1e6*pair:.3f} us CPU per grain-step")
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(BUILD, "results.txt"), "w") as f:
        f.write(text + "\n")


if __name__ == "__main__":
    main()
