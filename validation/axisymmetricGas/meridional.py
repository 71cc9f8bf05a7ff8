# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Figures of a gas run binned in the meridional (x, r) plane, for comparing
an axisymmetric run with a 3-D run of the same (x, r) blocking, or two
axisymmetric runs with each other (validation/axisymmetricGas/freeStreamPlate).

A cell belongs to the bin of its centre: x by columns of equal width, the
radius r = sqrt(y^2 + z^2) by rows of equal height (the rows of blockMesh's
wedge are slabs of constant y; a 3-D sector built from turned copies of the
wedge has its cell centres at the same radii).  Per bin and per batch (one
written time of the fieldAverage means, uniformity.batches): number density
(molecules over bin volume), mean velocity (x, radial) from the momentum,
each cell's momentum turned into its own meridional plane first, and
translational temperature (mean kinetic energy less that of the mean
velocity).  Noise: batch means, rmf.stats.batch_deviation.
"""

import os

import numpy as np
from scipy import stats

from rmf import foam
from rmf.stats import batch_deviation

import uniformity as uf

FIELDS = ("n", "Ux", "Ur", "T")


def bin_index(centres, length, radius, nx, nr):
    """Bin of each cell centre: column * nr + row, columns of length/nx in x
    from 0, rows of radius/nr in r from the axis (radius: the rows' outer
    edge, e.g. the wedge's y of the outer face)."""
    r = np.hypot(centres[:, 1], centres[:, 2])
    ix = np.floor(centres[:, 0] / (length / nx)).astype(int)
    ir = np.floor(r / (radius / nr)).astype(int)
    if ix.min() < 0 or ix.max() >= nx or ir.min() < 0 or ir.max() >= nr:
        raise ValueError("cell centres outside the bins")
    return ix * nr + ir


def binned_batches(case, bins, nbins, mass, skip):
    """Per batch (rows) and bin (columns): dict of arrays "n" [m^-3],
    "Ux", "Ur" [m/s], "T" [K], and "V" (bin volumes, one row)."""
    n = foam.n_cells(case)
    centres = foam.cell_centres(case)
    vol = uf.cell_volumes(case)
    theta = np.arctan2(centres[:, 2], centres[:, 1])
    cos, sin = np.cos(theta), np.sin(theta)
    bin_vol = np.bincount(bins, vol, nbins)

    def binned(values):
        return np.bincount(bins, values * vol, nbins)

    out = {name: [] for name in FIELDS}
    for t in uf.batches(case, skip):
        def read(name):
            return foam.read_field(os.path.join(case, t, name + "Mean"), n)
        rho_n, lin_ke, mom = read("rhoN"), read("linearKE"), read("momentum")
        number = binned(rho_n)
        px = binned(mom[:, 0])
        pr = binned(mom[:, 1] * cos + mom[:, 2] * sin)
        pt = binned(mom[:, 2] * cos - mom[:, 1] * sin)
        ux, ur, ut = px / (mass * number), pr / (mass * number), pt / (mass * number)
        ke = binned(lin_ke) / number - 0.5 * mass * (ux ** 2 + ur ** 2 + ut ** 2)
        out["n"].append(number / bin_vol)
        out["Ux"].append(ux)
        out["Ur"].append(ur)
        out["T"].append(ke * 2 / (3 * uf.K_B))
    out = {name: np.array(rows) for name, rows in out.items()}
    out["V"] = bin_vol
    return out


def compare(a, b, fields=FIELDS):
    """Per field: the two runs' batch means, the deviation of their
    difference in combined standard errors sqrt(se_a^2 + se_b^2), and its
    degrees of freedom (Welch-Satterthwaite), per bin."""
    result = {}
    for name in fields:
        mean_a, se_a, _ = batch_deviation(a[name], 0)
        mean_b, se_b, _ = batch_deviation(b[name], 0)
        se = np.hypot(se_a, se_b)
        dof = se ** 4 / (se_a ** 4 / (len(a[name]) - 1) + se_b ** 4 / (len(b[name]) - 1))
        result[name] = (mean_a, mean_b, se, (mean_a - mean_b) / se, dof)
    return result


def chi2_null(a, b, dof):
    """Null distribution of the mean over the bins of dev^2 (compare) for
    two runs that differ by noise only: (mean, standard deviation, and the
    scale and degrees of freedom of the scaled chi^2 matched to them).

    Each dev is Student's t with dof (the bins' median), E[t^2] = dof/(dof -
    2), Var[t^2] = 2 g with g = dof^2 (dof - 1)/((dof - 2)^2 (dof - 4)).
    The bins' noise is correlated in space (neighbouring bins, and a mode
    common to the domain): for correlations rho_ij of the devs the mean of
    M of them has Var = 2 g sum_ij rho_ij^2/M^2.  rho_ij from the batches'
    covariance of the difference of the means (C_a/B_a + C_b/B_b), each
    rho_ij^2 less its sampling bias (1 - rho^2)^2/(B_a + B_b - 2).  The
    distribution of the mean is taken as a scaled chi^2 with that mean and
    variance (Satterthwaite)."""
    cov = np.cov(a.T) / len(a) + np.cov(b.T) / len(b)
    sd = np.sqrt(np.diag(cov))
    rho = cov / np.outer(sd, sd)
    m = len(sd)
    off = rho[~np.eye(m, dtype=bool)]
    squares = m + max((off ** 2 - (1 - off ** 2) ** 2 / (len(a) + len(b) - 2)).sum(), 0)
    nu = float(np.median(dof))
    mean = nu / (nu - 2)
    g = nu * nu * (nu - 1) / ((nu - 2) ** 2 * (nu - 4))
    var = 2 * g * squares / m ** 2
    k = 2 * mean * mean / var
    return mean, np.sqrt(var), mean / k, k


def chi2_limit(a, b, dof, alpha):
    """Upper limit of the mean of dev^2 exceeded with probability alpha
    under chi2_null; also returns the null's mean and standard deviation."""
    mean, sd, scale, k = chi2_null(a, b, dof)
    return scale * stats.chi2.isf(alpha, k), mean, sd
