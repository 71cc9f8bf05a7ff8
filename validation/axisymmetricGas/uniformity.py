# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Figures of an axisymmetric equilibrium-gas run (validation/axisymmetricGas/wedge):
number density and temperature in radial bins from batch means, the simulator
count over time, and the NTC collision count against the equilibrium VHS rate.

Noise: each written time holds the average over one batch of steps
(fieldAverage with restartOnOutput); the B batch means of a bin give its
standard error std/sqrt(B) (batch-means method, which absorbs the correlation
of successive steps as long as a batch is much longer than the correlation
time: 100 steps against an acoustic crossing of the radius in about 30).
"""

import math
import os

import numpy as np
from scipy import integrate, special

from rmf import foam

K_B = 1.380649e-23


def rwf(r, max_weight, extent):
    """Radial weight factor RWF(r) = 1 + (RWF_max - 1) r/R_max."""
    return 1 + (max_weight - 1) * r / extent


def batches(case, skip=1):
    """Written times after the first `skip` batches (the first one starts from
    the initial fill)."""
    return [t for t in foam.times(case) if float(t) > 0][skip:]


def cell_volumes(case):
    path = os.path.join(case, "0", "V")
    if not os.path.exists(path):
        import subprocess
        subprocess.run(["postProcess", "-func", "writeCellVolumes", "-time", "0"],
                       cwd=case, check=True, stdout=subprocess.DEVNULL)
    return foam.read_field(path)


def radial_batches(case, skip=1):
    """Per radial bin (one row of cells, y being the radius) and per batch:
    number density, and translational temperature (from the mean kinetic
    energy less that of the mean velocity).  Returns the bin radii, the row
    volumes, and (batches, bins) arrays."""
    n = foam.n_cells(case)
    centres = foam.cell_centres(case)
    vol = cell_volumes(case)
    radii = np.unique(np.round(centres[:, 1], 9))
    bins = np.searchsorted(radii, np.round(centres[:, 1], 9))
    mass = float(foam.get_entry(case, "constant/dsmcProperties",
                                "moleculeProperties/Ar/mass"))
    row_vol = np.bincount(bins, vol)

    dens, temp = [], []
    for t in batches(case, skip):
        def read(name):
            return foam.read_field(os.path.join(case, t, name + "Mean"), n)
        rho_n, lin_ke, mom = read("rhoN"), read("linearKE"), read("momentum")
        nv = np.bincount(bins, rho_n * vol)
        ke = np.bincount(bins, lin_ke * vol)
        u = np.array([np.bincount(bins, mom[:, i] * vol) for i in range(3)]) / (mass * nv)
        dens.append(nv / row_vol)
        temp.append((ke / nv - 0.5 * mass * (u ** 2).sum(axis=0)) * 2 / (3 * K_B))
    return radii, row_vol, np.array(dens), np.array(temp)


def expected_simulators(case, density, weight, max_weight, extent):
    """Simulators of a uniform gas of the given number density in the wedge:
    n/F_N times the integral of 1/RWF over the volume, the rows of cells
    being slabs a <= y <= b whose volume grows as y dy."""
    radii, row_vol, _, _ = radial_batches(case, skip=0)
    points = foam.read_points(case)
    edges = np.linspace(0, points[:, 1].max(), len(radii) + 1)
    total = 0.0
    for (a, b), v in zip(zip(edges[:-1], edges[1:]), row_vol):
        inv, _ = integrate.quad(lambda y: y / rwf(y, max_weight, extent), a, b)
        total += v * inv / (0.5 * (b * b - a * a))
    return density / weight * total


def vhs_sigma_cr(mass, diameter, omega, t_ref, temperature):
    """<sigma_T c_r> over the equilibrium relative-speed distribution for
    OpenFOAM's VariableHardSphere cross-section
    sigma_T = pi d^2 (2 k T_ref/(m_r c_r^2))^(omega - 1/2)/Gamma(5/2 - omega)."""
    m_r = mass / 2
    a = m_r / (2 * K_B * temperature)

    def f(c):  # Maxwellian relative speed distribution
        return 4 * math.pi * (a / math.pi) ** 1.5 * c * c * math.exp(-a * c * c)

    def sigma(c):
        return (math.pi * diameter ** 2
                * (2 * K_B * t_ref / (m_r * c * c)) ** (omega - 0.5)
                / special.gamma(2.5 - omega))

    scale = 1 / math.sqrt(a)
    val, _ = integrate.quad(lambda c: sigma(c) * c * f(c), 0, 12 * scale, limit=200)
    return val


def weighting_events(max_weight, extent, radius, dt, temperature, mass,
                     open_outer=False, samples=1000000, rng_seed=1):
    """Expected radial-weighting events (clones + deletions) per step of an
    equilibrium gas at rest in the wedge, computed from the flux of
    molecules between radii, not from the code's counts: (per simulator
    present, per simulator inserted at the outer radius when open).

    Each step every simulator moves on its 3-D straight path (the wedge's
    chord move reaches the same radius) from r0 to r1 and is decided with
    ratio = RWF(r0)/RWF(r1): kept with probability ratio below 1, else
    floor(ratio) copies and one more with the fractional part's
    probability; the expected events are |ratio - 1| either way (doc/
    physics.md#axisymmetric).  Simulators sit at density n/(F_N RWF(r)) in the
    wedge (volume element ~ r dr), velocities Maxwellian at temperature.  The
    outer wall (radius: the flat outer face's distance from the axis) re-
    emits diffusely for the rest of the step; open, a simulator crossing it
    leaves undecided, and one inserted there (weight 1, inward velocity
    from the flux distribution, over a random fraction of the step as
    randomEntryTime) is kept with probability 1/RWF(r1).  The x walls are
    left out: a simulator meeting one (2 % per step) has its radial
    velocity redrawn from the same distribution (at most 0.6 % of the
    events).  Monte Carlo with a fixed generator of its own: relative
    standard error 0.15 % at the default samples (spread over generator
    seeds), the closed weighted wedge's 0.0370 per simulator and step, the
    open one's 0.0368 and 0.898 per inserted simulator; measured against
    the code's counts -0.11 % and -0.26 % (validation/axisymmetricGas)."""
    rng = np.random.default_rng(rng_seed)
    sigma = math.sqrt(K_B * temperature / mass)

    # Radii of the simulators present: r ~ r dr, kept with 1/RWF
    r0 = radius * np.sqrt(rng.random(4 * samples))
    r0 = r0[rng.random(len(r0)) < 1 / rwf(r0, max_weight, extent)][:samples]
    pos = np.column_stack([r0, np.zeros_like(r0)])
    vel = rng.normal(0, sigma, (len(r0), 2))        # radial, azimuthal
    end, inside = _flight(pos, vel, dt, radius, sigma, rng, open_outer)
    ratio = rwf(r0, max_weight, extent) / rwf(np.hypot(*end.T), max_weight, extent)
    present = np.where(inside, abs(ratio - 1), 0).mean()
    if not open_outer:
        return present, 0.0

    # Inserted at the outer radius: inward speed from the flux (Rayleigh)
    n = samples
    pos = np.column_stack([np.full(n, radius), np.zeros(n)])
    vel = np.column_stack([-sigma * np.sqrt(-2 * np.log(1 - rng.random(n))),
                           rng.normal(0, sigma, n)])
    end, inside = _flight(pos, vel, dt * rng.random(n), radius, sigma, rng, open_outer)
    inserted = np.where(inside, 1 - 1 / rwf(np.hypot(*end.T), max_weight, extent), 0).mean()
    return present, inserted


def _flight(pos, vel, dt, radius, sigma, rng, open_outer):
    """Straight flight in the wedge's cross-section (y, z) over dt (scalar
    or per member) inside the cylinder of the given radius: (end points,
    still inside).  At the cylinder a member leaves (open) or is re-emitted
    diffusely (wall: inward normal speed from the flux distribution,
    tangential Maxwellian, of spread sigma) for the rest of the flight."""
    left = np.broadcast_to(np.asarray(dt, float), len(pos)).copy()
    inside = np.ones(len(pos), bool)
    active = np.ones(len(pos), bool)
    for _ in range(10):
        end = pos + vel * left[:, None]
        out = active & (np.hypot(*end.T) > radius)
        pos = np.where((active & ~out)[:, None], end, pos)
        active = out
        if not active.any():
            break
        if open_outer:
            inside[out] = False
            break
        # time to the cylinder: |p + v t| = radius
        p, v = pos[out], vel[out]
        a = (v * v).sum(axis=1)
        b = (p * v).sum(axis=1)
        c = (p * p).sum(axis=1) - radius ** 2
        t = (-b + np.sqrt(np.maximum(b * b - a * c, 0))) / a
        hit = p + v * t[:, None]
        normal = -hit / radius                      # inward
        tangent = np.column_stack([-normal[:, 1], normal[:, 0]])
        k = len(hit)
        speed_n = sigma * np.sqrt(-2 * np.log(1 - rng.random(k)))
        speed_t = rng.normal(0, sigma, k)
        pos[out] = hit
        vel[out] = normal * speed_n[:, None] + tangent * speed_t[:, None]
        left[out] -= t
    return pos, inside
