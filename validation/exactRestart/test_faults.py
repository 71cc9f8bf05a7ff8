# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Faults while writing (doc/physics.md#restart, "Faults").

The gas family of testing/rmf_families.py (dsmcFoam's freeSpacePeriodic, own
stream, writeFormat binary, about 40 000 simulators) is run to N steps;
then a second run to 2N steps is broken while it writes time 2N:
- killed: the run kills itself with SIGKILL in the middle of writing 2N,
  through writeGuard's test hook (environment variable
  RMF_TEST_KILL_WHILE_WRITING=<2N>, writeGuard.H): after the marker
  <2N>/uniform/writing, uniform/time and some of the time's objects are
  written, before the rest (no race with a signal from outside);
- file-size limit: the run gets RLIMIT_FSIZE (ulimit -f) of 200 kB, less
  than its simulator files (about 1 MB each), so a write of time 2N
  exceeds it.
Expected, each checked:
- the broken run leaves <2N> marked; killed, it exits by SIGKILL having
  written part of <2N> (uniform/time and fewer files than the
  uninterrupted run); with the limit it exits with code 1 and says "file
  size limit exceeded ... writing time <2N>" (no signal);
- time N is untouched (byte for byte as before the broken run);
- the restart (startFrom latestTime) reports the time directory set
  aside, renames it <2N>.incomplete, starts from N, and its <2N> is byte
  for byte the uninterrupted 2N-step run's (the restart is exact,
  test_exactRestart), with no marker left.
"""

import os
import resource
import signal
import subprocess

import pytest

import rmf_families as families
from rmf import foam

BUILD = os.path.join(foam.PROJECT_DIR, "build", "validation", "restartFaults")
CONTROL = "system/controlDict"
STEPS = 10
LIMIT = 200_000     # [bytes] RLIMIT_FSIZE: above every field, below a simulator file


@pytest.fixture(scope="module")
def cases():
    """(base run to N, the uninterrupted run to 2N, dt)."""
    base = families.gas(os.path.join(BUILD, "base"), 1)
    dt = float(foam.get_entry(base, CONTROL, "deltaT"))
    foam.set_entry(base, CONTROL, "startFrom", "latestTime")
    foam.set_entry(base, CONTROL, "writeControl", "timeStep")
    foam.set_entry(base, CONTROL, "writeInterval", STEPS)
    whole = foam.copy_case(base, os.path.join(BUILD, "whole"))
    foam.set_entry(whole, CONTROL, "endTime", f"{2*STEPS*dt:.17g}")
    foam.run(whole, "rarefiedMultiphaseFoam")
    foam.set_entry(base, CONTROL, "endTime", f"{STEPS*dt:.17g}")
    foam.run(base, "rarefiedMultiphaseFoam")
    foam.set_entry(base, CONTROL, "endTime", f"{2*STEPS*dt:.17g}")
    return base, whole


def _files(case, t):
    out = {}
    for path, _, names in os.walk(os.path.join(case, t)):
        for n in names:
            with open(os.path.join(path, n), "rb") as f:
                out[os.path.relpath(os.path.join(path, n), case)] = f.read()
    return out


def _check_recovery(case, whole, t_mid, t_end):
    """Restart after the broken run: t_end set aside, rerun exact."""
    assert os.path.isfile(os.path.join(case, t_end, "uniform", "writing")), \
        f"the broken write of {t_end} left no marker"
    log = foam.run(case, "rarefiedMultiphaseFoam", log="log.recover")
    with open(log) as f:
        text = f.read()
    assert "set aside as " + t_end + ".incomplete" in text, "no report of the incomplete time"
    assert "Create mesh for time = " + t_mid in text, "the restart did not start from N"
    assert os.path.isdir(os.path.join(case, t_end + ".incomplete"))
    assert not os.path.exists(os.path.join(case, t_end, "uniform", "writing"))
    diff = foam.differing_files(os.path.join(whole, t_end), os.path.join(case, t_end))
    print(f"  recovered {t_end}: {len(diff)} files differ from the uninterrupted run")
    assert not diff, diff


def test_killed_while_writing(cases):
    base, whole = cases
    case = foam.copy_case(base, os.path.join(BUILD, "killed"))
    t_mid, t_end = foam.times(whole)[-2:]
    before = _files(case, t_mid)
    env = dict(os.environ, RMF_TEST_KILL_WHILE_WRITING=t_end)
    with open(os.path.join(case, "log.killed"), "w") as log:
        proc = subprocess.run(["rarefiedMultiphaseFoam"], cwd=case, stdout=log,
                              stderr=subprocess.STDOUT, env=env)
    with open(os.path.join(case, "log.killed")) as f:
        assert "kills itself while writing time " + t_end in f.read(), "hook not armed"
    # Killed in the middle of the write: beside the marker, Time's
    # uniform/time (written first) is there, some of the rest is not
    written = set(_files(case, t_end)) - {os.path.join(t_end, "uniform", "writing")}
    complete = set(_files(whole, t_end))
    print(f"\nkilled while writing {t_end} (exit {proc.returncode}): {len(written)} of"
          f" {len(complete)} files written")
    assert proc.returncode == -signal.SIGKILL
    assert os.path.join(t_end, "uniform", "time") in written
    assert written < complete, "not a part of the uninterrupted run's files"
    assert _files(case, t_mid) == before, f"time {t_mid} changed"
    _check_recovery(case, whole, t_mid, t_end)


def test_file_size_limit(cases):
    base, whole = cases
    case = foam.copy_case(base, os.path.join(BUILD, "limited"))
    t_mid, t_end = foam.times(whole)[-2:]
    before = _files(case, t_mid)

    def limit():
        resource.setrlimit(resource.RLIMIT_FSIZE, (LIMIT, LIMIT))

    with open(os.path.join(case, "log.limited"), "w") as log:
        proc = subprocess.run(["rarefiedMultiphaseFoam"], cwd=case, stdout=log,
                              stderr=subprocess.STDOUT, preexec_fn=limit)
    with open(os.path.join(case, "log.limited")) as f:
        text = f.read()
    print(f"\nfile-size limit {LIMIT} B: exit {proc.returncode}")
    assert proc.returncode == 1, f"exit {proc.returncode}"
    assert f"file size limit exceeded (ulimit -f) while writing time {t_end}" in text
    assert _files(case, t_mid) == before, f"time {t_mid} changed"
    _check_recovery(case, whole, t_mid, t_end)
