# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Statistical comparison of a DSMC run with an ensemble of independent runs
of the same case, the tolerance being set by the ensemble's own spread.

Cells of a time-averaged DSMC field are not independent: neighbouring cells
share molecules over the averaging window, and inflow or collision counts
move whole regions together (on wedge15Ma5 the run-to-run spread of the
domain-mean temperature is eight times what independent cells would give).
So the noise is measured, not modelled: K runs x_1..x_K of the case with
independent random streams (rarefiedMultiphaseFoam, randomSeed 1..K) give,
for each field,

  level    S1 = domain mean of the field;
  pattern  S2 = RMS over cells of (y - m) - mean(y - m), m the ensemble
           mean: how far the run's spatial pattern lies from the ensemble's.

For a run y under test (stock dsmcFoam, or our parallel run), S1(y) and
S2(y) are compared with their null distributions from the ensemble itself
(leave-one-out: each x_j against the mean of the others, S2 rescaled by
sqrt((1 + 1/K)/(1 + 1/(K-1))) for the smaller ensemble), as a prediction
interval: |S1(y) - mean S1| <= t * sd(S1) * sqrt(1 + 1/K) (two-sided) and
S2(y) <= mean S2 + t * sd(S2) * sqrt(1 + 1/K) (one-sided), t the Student
quantile with K - 1 degrees of freedom at probability 1 - alpha/2 (level)
or 1 - alpha (pattern).

alpha is the false-alarm probability of each single check (a correct
solver fails it with probability alpha when the seeds change; with fixed
seeds the outcome is reproducible): the caller gives its family-wise error
divided by its number of checks (Bonferroni), which compare() cannot know.
A Student quantile assumes normal statistics; at the small alpha of a
Bonferroni share it is large for a small ensemble (K = 6: 28.5 at 1e-6),
so K sets the power.

batch_deviation and corrected_deviation: the batch-means standard error of
binned time averages within one run (each written time one batch), for
validation/axisymmetricGas and validation/axisymmetricGrains.
"""

import math
from dataclasses import dataclass

import numpy as np
from scipy import stats as _stats


@dataclass
class Check:
    name: str
    value: float
    centre: float
    limit: float        # allowed |value - centre| (level) or value (pattern)
    two_sided: bool

    @property
    def passed(self):
        if self.two_sided:
            return abs(self.value - self.centre) <= self.limit
        return self.value <= self.limit

    def __str__(self):
        verdict = "PASS" if self.passed else "FAIL"
        if self.two_sided:
            return (f"{verdict} {self.name}: {self.value:.6g} vs ensemble "
                    f"{self.centre:.6g} +- {self.limit:.3g}")
        return f"{verdict} {self.name}: {self.value:.4g} (limit {self.limit:.4g})"


def _pattern(y, m):
    r = (y - m).reshape(len(y), -1)
    r = r - r.mean(axis=0)
    return np.sqrt(np.mean(r**2))


def n_checks(y):
    """Number of checks compare() makes of run y: a level per component and
    one pattern."""
    return np.asarray(y).reshape(len(y), -1).shape[1] + 1


def compare(name, y, ensemble, alpha):
    """Level and pattern checks of run y (cells[, components]) against the
    ensemble (list of K arrays of the same shape), each at false-alarm
    probability alpha."""
    x = np.array(ensemble, float)
    y = np.asarray(y, float)
    K = len(x)
    if K < 3:
        raise ValueError(f"{name}: ensemble of {K} runs, need at least 3")
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(y))):
        raise ValueError(f"{name}: non-finite values")

    level = x.reshape(K, len(y), -1).mean(axis=1)           # (K, components)
    level_y = y.reshape(len(y), -1).mean(axis=0)
    scale = np.sqrt((1 + 1/K)/(1 + 1/(K - 1)))
    pattern = np.array([scale*_pattern(x[j], np.delete(x, j, axis=0).mean(axis=0))
                        for j in range(K)])
    pattern_y = _pattern(y, x.mean(axis=0))

    grow = np.sqrt(1 + 1/K)
    t2 = _stats.t.isf(alpha/2, K - 1)
    t1 = _stats.t.isf(alpha, K - 1)

    checks = []
    for c in range(level.shape[1]):
        label = f"{name} level" + (f"[{c}]" if level.shape[1] > 1 else "")
        sd = level[:, c].std(ddof=1)
        checks.append(Check(label, level_y[c], level[:, c].mean(),
                            t2*sd*grow, True))
    checks.append(Check(f"{name} pattern", pattern_y, pattern.mean(),
                        pattern.mean() + t1*pattern.std(ddof=1)*grow, False))
    return checks


def batch_deviation(samples, expected):
    """Per bin, over the batches (rows) of samples: the mean, its standard
    error (batch spread / sqrt(batches)) and the deviation of the mean
    from expected in standard errors."""
    mean = samples.mean(axis=0)
    se = samples.std(axis=0, ddof=1)/np.sqrt(len(samples))
    return mean, se, (mean - expected)/se


def corrected_deviation(samples, expected):
    """batch_deviation with the standard error corrected for correlated
    batches: an AR(1) correlation rho, the median over the bins of the
    batch means' lag-1 autocorrelation, when positive, inflates the
    variance of the mean by (1 + rho)/(1 - rho).  Returns mean, se, dev and
    rho."""
    mean, se, _ = batch_deviation(samples, expected)
    x = samples - mean
    rho = float(np.median((x[1:] * x[:-1]).sum(axis=0) / (x * x).sum(axis=0)))
    se = se * math.sqrt((1 + max(rho, 0)) / (1 - max(rho, 0)))
    return mean, se, (mean - expected) / se, rho
