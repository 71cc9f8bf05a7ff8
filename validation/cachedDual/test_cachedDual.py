# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""averagingMethod cachedDual (src/solidPhase/submodels/AveragingMethods)
gives upstream's dual averaging to the bit.

A reduced copy of the Snider sedimentation set-up (20 000 parcels, MPPIC as
the tutorial has it: twoSided packing, relaxation damping and stochastic
isotropy, which find the cloud's averages by name) runs 40 steps from one initial state
with averagingMethod dual and with cachedDual, serially and on 2 METIS
ranks.  Expected: every file of the last time directory (the parcels'
positions, velocities and all their properties, the Eulerian fields) is
byte-identical between dual and cachedDual, since cachedDual is
upstream's Dual with the dual volumes computed once instead of at each
construction.  So that identity is not trivial, the same run with basic
averaging must differ from dual, and the parcels must have moved.

Measured: identical serially and on 2 ranks (8 files differ with basic).
By hand (not committed): a cachedDual that keeps the prototype's name
instead of the caller's stops the solver at the packing model's look-up
("request for averagingMethod grains:volumeAverage ... failed"); one
whose averages start from 1e-15 instead of 0 fails the identity (8 files
differ).  The solver's time with cachedDual against dual is printed
(information only; bench/cachedDual measures it).

Deterministic: no statistical comparison.
"""

import os

from rmf import foam, snider

BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "cachedDual")
PROPS = "constant/grainsProperties"
PARCELS = 20000         # of the tutorial's weight per alpha_0 (rmf.snider)
STEPS = 40


def initial_state(name):
    return snider.reduced_column(os.path.join(BUILD, name), PARCELS, STEPS)


def run(base, method, np_):
    case = foam.copy_case(base, f"{base}-{method}")
    foam.set_entry(case, PROPS, "solution/averagingMethod", method)
    if np_ > 1:
        foam.run(case, "decomposePar")
    log = foam.run(case, "rarefiedMultiphaseFoam", np_=np_)
    return case, foam.execution_times(log)[-1]


def last_time_dirs(case, np_):
    """The last time directory of each rank (or of the serial case)."""
    roots = [case] if np_ == 1 else [os.path.join(case, f"processor{p}") for p in range(np_)]
    return [os.path.join(root, foam.latest_time(root)) for root in roots]


def test_cached_dual_is_dual():
    base = initial_state("serial")
    dual, t_dual = run(base, "dual", 1)
    cached, t_cached = run(base, "cachedDual", 1)
    basic, _ = run(base, "basic", 1)

    [d] = last_time_dirs(dual, 1)
    [c] = last_time_dirs(cached, 1)
    [b] = last_time_dirs(basic, 1)
    assert os.path.basename(d) != "0", "the run wrote no time"

    Uz = foam.read_list(os.path.join(d, "lagrangian", "grains", "U"))[:, 2]
    # Free fall would reach -g t = -0.39 m/s; packing and isotropy slow it
    assert len(Uz) == PARCELS and Uz.mean() < -0.1, f"mean U_z {Uz.mean():.3f} m/s"

    differ = foam.differing_files(d, c)
    assert not differ, f"{len(differ)} files differ, e.g. {differ[:5]}"
    sensitive = foam.differing_files(d, b)
    assert sensitive, "dual and basic averaging gave the same run"
    print(f"PASS serial: the last time's files identical with dual and "
          f"cachedDual ({len(sensitive)} differ with basic); solver time "
          f"{t_cached:.1f} s against {t_dual:.1f} s")


def test_cached_dual_is_dual_parallel():
    base = initial_state("parallel")
    dual, t_dual = run(base, "dual", 2)
    cached, t_cached = run(base, "cachedDual", 2)

    differ = []
    for d, c in zip(last_time_dirs(dual, 2), last_time_dirs(cached, 2)):
        assert os.path.basename(d) != "0", "the run wrote no time"
        differ += foam.differing_files(d, c)
    assert not differ, f"{len(differ)} files differ, e.g. {differ[:5]}"
    print(f"PASS 2 ranks: the last time's files identical with dual and "
          f"cachedDual; solver time {t_cached:.1f} s against {t_dual:.1f} s")
