# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Speed-accuracy scene denseGas of bench/tradeoff/tradeoff.py: the gas
models at long steps (DSMC with upstream's majorant, DSMC sub-stepped per
cell, particle ES-BGK) on a near-continuum gas layer on a cold surface,
against DSMC at a resolved step.

Why this case: the main job's dense gas is the gas held on and in the
dust layer under the jet, cold (the grains' and the surface's
temperature, ~200 K), dense (up to 3e24 m^-3) and sheared by the wall
jet above it; its steps are up to 45 mean collision times.  What the
surface feels from it, the shear and the heat flux, is carried through
that layer by the gas's viscosity and conductivity; the pressure by its
momentum.  A shock-layer box would add the shock, whose standoff the
PSI scene measures; here the layer alone: a channel (rmf.channel,
validation/esBGK/channel) of nitrogen (VHS d 4.17e-10 m, omega 0.74,
Larsen-Borgnakke rotation, Z = 5) between the surface (lower wall, 200 K,
at rest) and the jet's side (upper wall, 800 K, moving at 800 m/s along
it), at a Knudsen number KN (lambda at the mean density n = 1e21 m^-3
and 273 K over the width; the physics depends on n only through it),
cells of lambda/CELLS_PER_LAMBDA, SIMULATORS per cell, every setting on
the same mesh, so that the step and the collision model are the only
changes.  The run starts on the linear profile between the walls, runs
WARM slowest-mode times L^2/(pi^2 mu/rho) (at 273 K) to its steady state,
then averages over BATCHES more, one write each.

Settings: the reference, DSMC (upstream's NTC) at Lambda = dt/tau_c =
REFERENCE_STEP (tau_c at the mean density and 273 K); ES-BGK at the same
step (the model's own error); at each long step Lambda in STEPS, NTC with
upstream's majorant ("ntc", as the crater settings), NTC from bound
majorants sub-stepped per cell ("subSteps", collisionsPerSubStep 1, as the
resolved settings) and ES-BGK in every cell ("bgk", the resolved
settings above Lambda 20).

Observables, the batches' mean (relative errors against the reference
of the same seed):
  shear     the surface's shear stress (fDMean along the wall);
  heat      its heat flux (qMean, into the surface);
  pressure  its pressure (-fDMean normal to it);
  T1        the translational temperature of the gas in the cell on the
            surface;
  slip      the gas's velocity along the surface in that cell.
Judged: shear, heat and pressure (what the grains and the surface
feel).  Noise: the reference's values over its seeds are given in the
note; the batch means' standard error of each run is in the CSV.

Expected (doc/physics.md#es-bgk): a particle model transports momentum
and heat over a flight of the step, so at a step of a = p dt/mu the
viscosity and conductivity seen are mu (a/2) coth(a/2), ~p dt/2 for a >>
1, whichever the collision model: NTC sub-stepped relaxes exactly within
the step and BGK too, and both stiffen the layer alike; upstream's
majorant also loses collisions (acceptance above 1).

Cost: the solver's CPU time (its last ExecutionTime), least over the
seeds, over the reference's least; every run simulates the same physical
time.  Full size: KN 0.02 (100 cells), 2 seeds, about 15 minutes;
--quick: KN 0.05 (40 cells), steps 1 and 20, 1 seed, about 20 s.
"""

import math
import os

import numpy as np

from rmf import channel, foam
from rmf.bench import OUT, against_reference, cpu_time, spread
from rmf.kinetic import vhs_collision_time, vhs_mean_free_path, vhs_viscosity

N2 = dict(mass=46.5e-27, d=4.17e-10, omega=0.74)
T_REF = 273.0
N_GAS, T_FILL = 1e21, 500.0
SURFACE, JET = (200.0, 0.0), (800.0, 800.0)        # (T [K], U_x [m/s]) of the walls
KN = {False: 0.02, True: 0.05}                      # full, --quick
CELLS_PER_LAMBDA, SIMULATORS = 2, 50
WARM, BATCHES = 2, 8
REFERENCE_STEP = 0.1
STEPS = (1, 5, 20, 45)
QUICK_STEPS = (1, 20)
GAS_ENTRIES = [("typeIdList", "(N2)"),
               ("BinaryCollisionModel", "LarsenBorgnakkeVariableHardSphere"),
               ("LarsenBorgnakkeVariableHardSphereCoeffs",
                "{ Tref 273; relaxationCollisionNumber 5; }")]
MODELS = {
    "ntc": ("NTC, upstream's majorant", []),
    "subSteps": ("NTC sub-stepped (collisionSubSteps)",
                 [("collisionSubSteps", "{ collisionsPerSubStep 1; maxSubSteps 1000; }")]),
    "bgk": ("ES-BGK in every cell", [("esBGK", "{ switchAbove 1e-9; switchBelow 1e-10; }")]),
}
ERRORS = ("shear", "heat", "pressure", "T1", "slip")
JUDGED = ("shear", "heat", "pressure")


def settings(quick):
    """(name, label, Lambda, model) of the scene's settings."""
    out = [("reference", f"NTC, Lambda {REFERENCE_STEP:g} (reference)", REFERENCE_STEP, "ntc"),
           (f"bgk{REFERENCE_STEP:g}", f"ES-BGK, Lambda {REFERENCE_STEP:g}", REFERENCE_STEP,
            "bgk")]
    for step in (QUICK_STEPS if quick else STEPS):
        for model, (label, _) in MODELS.items():
            out.append((f"{model}{step:g}", f"{label}, Lambda {step:g}", step, model))
    return out


def geometry(quick):
    """(L, cells, tau_c, slowest-mode time, lambda) of the channel."""
    lam = vhs_mean_free_path(N_GAS, T_REF, N2["d"], N2["omega"], T_REF)
    L = lam/KN[quick]
    cells = int(round(CELLS_PER_LAMBDA/KN[quick]))
    tau = vhs_collision_time(N_GAS, T_REF, N2["mass"], N2["d"], N2["omega"], T_REF)
    mu = vhs_viscosity(T_REF, N2["mass"], N2["d"], N2["omega"], T_REF)
    return L, cells, tau, channel.slowest_time(L, mu, N_GAS*N2["mass"]), lam


def run(case, step, model, seed, quick):
    """A setting's channel, run; returns the case."""
    L, cells, tau, slowest, lam = geometry(quick)
    dt = step*tau
    batch = max(1, int(math.ceil(slowest/dt)))
    entries = GAS_ENTRIES + MODELS[model][1]
    case = channel.make(case, L, lam, cells, N_GAS,
                        T_FILL, SIMULATORS, seed, dt, batch, WARM + BATCHES,
                        {"lower": SURFACE, "upper": JET}, entries=entries,
                        remove=() if model == "bgk" else ("esBGK",))
    foam.run(case, "rarefiedMultiphaseFoam")
    return case


def observe(case):
    """The observables' batch means and their standard errors."""
    rows = []
    for time in foam.times(case)[WARM + 1:]:
        _, U, T = channel.batch_fields(case, time)
        fD = channel.wall_load(case, time, "fDMean", "lower")
        q = channel.wall_load(case, time, "qMean", "lower")
        rows.append((fD[0], q, -fD[1], T[0], U[0, 0]))
    v = np.array(rows)
    out = {}
    for i, name in enumerate(ERRORS):
        out[name + "Value"] = float(v[:, i].mean())
        out[name + "Se"] = float(v[:, i].std(ddof=1)/math.sqrt(len(v)))
    out["batches"] = len(v)
    return out


def study(quick, seeds, names=None, first=1):
    """Runs the scene's settings over seeds first..first + seeds - 1 (the
    arguments of rmf.bench.write_outputs, as bench/tradeoff/apollo.py's
    study)."""
    out = os.path.join(OUT, "denseGas")
    os.makedirs(out, exist_ok=True)
    chosen = [s for s in settings(quick) if names is None or s[0] in names]
    rows = []
    for seed in range(first, first + seeds):
        for name, label, step, model in chosen:
            case = run(os.path.join(out, f"seed{seed}", name), step, model, seed, quick)
            row = {"setting": name, "label": label, "seed": seed,
                   "cpu": cpu_time(os.path.join(case, "log.rarefiedMultiphaseFoam"))}
            row.update(observe(case))
            rows.append(row)
            print(f"seed {seed} {name}: shear {row['shearValue']:.4g} Pa, heat "
                  f"{row['heatValue']:.4g} W/m^2, p {row['pressureValue']:.4g} Pa, T1 "
                  f"{row['T1Value']:.4g} K, slip {row['slipValue']:.4g} m/s, CPU "
                  f"{row['cpu']:.1f} s", flush=True)
    refs = against_reference(rows, ERRORS)
    _, cells, tau, slowest, _ = geometry(quick)
    noise = "; ".join(f"{e} {spread(refs, e + 'Value')}" for e in ERRORS)
    note = (f"Dense gas on a cold surface (bench/tradeoff/denseGas.py): nitrogen in a "
            f"channel at Kn {KN[quick]:g}, {cells} cells, {SIMULATORS} simulators a cell, "
            f"between the surface ({SURFACE[0]:g} K, at rest) and the jet's side "
            f"({JET[0]:g} K, {JET[1]:g} m/s); {WARM} + {BATCHES} slowest-mode times "
            f"({WARM + BATCHES}*{slowest/tau:.0f} tau_c), {seeds} seed(s).  Lambda = "
            "dt/tau_c at the mean density and 273 K.  Reference: NTC at Lambda "
            f"{REFERENCE_STEP:g}; its values over the seeds (SI units, mean ± sd): "
            f"{noise}.  Errors against the reference of the same seed: shear, heat, "
            "pressure on the surface; T1 and slip of the gas in the cell on it.  Cost: "
            "the solver's CPU time over the reference's.")
    return dict(rows=rows, errors=list(ERRORS), main_error="shear", note=note,
                judged=JUDGED, cost_label="the reference's", base="reference")
