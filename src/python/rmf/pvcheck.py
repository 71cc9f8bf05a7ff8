# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""Run rmf/pvsnapshot.py under ParaView's pvbatch (in Xvfb) on a case and
check what a user would see: the reader's view of the case against the
case's own files, and a picture that is not blank.

    from rmf import pvcheck
    failures, found = pvcheck.check(case, field="alpha.grains", cloud="grains")
"""

import fcntl
import json
import os
import subprocess

import numpy as np

from rmf import foam

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "pvsnapshot.py")


def snapshot(case, field, cloud, output):
    """The JSON pvsnapshot prints (raises on a failed pvbatch).  No time
    limit: a slow machine is not a failure (a hung pvbatch is left to the
    suite's runner)."""
    # xvfb-run -a picks a free display number without a lock against another
    # starting at once (./Alltest's two workers): one at a time per project
    os.makedirs(os.path.join(foam.PROJECT_DIR, "build"), exist_ok=True)
    with open(os.path.join(foam.PROJECT_DIR, "build", "pvbatch.lock"), "a") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        for attempt in range(3):
            proc = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
                                   "pvbatch", SCRIPT, case, "--field", field,
                                   "--cloud", cloud, "--output", output],
                                  capture_output=True, text=True)
            # An X server that xvfb-run started badly: again
            if "CreateAWindow" not in proc.stdout + proc.stderr:
                break
    lines = [line for line in proc.stdout.splitlines() if line.startswith("{")]
    if proc.returncode != 0 or not lines:
        raise RuntimeError(f"pvbatch failed ({proc.returncode}):\n"
                           f"{proc.stdout[-2000:]}\n{proc.stderr[-2000:]}")
    return json.loads(lines[-1])


def check(case, field, cloud, extra_cells=(), extra_parcels=()):
    """(failures, what ParaView read).  Checked: the last written time;
    every cell count; field among the cell arrays with the range of the
    field file; the cloud with as many parcels as its U file and the
    project's own parcel fields (specularFraction, thermalAccommodation)
    and extra_parcels among its arrays; extra_cells among the cell
    arrays; the picture, 800 x 600, not blank (more than 1 % of its
    pixels away from the white background, more than 20 colours)."""
    import matplotlib.image

    output = os.path.join(case, "snapshot.png")
    found = snapshot(case, field, cloud, output)
    t = foam.latest_time(case)
    failures = []
    if abs(found["time"] - float(t)) > 1e-9*max(1.0, float(t)):
        failures.append(f"time {found['time']} against the last written {t}")
    if found.get("cells") != foam.n_cells(case):
        failures.append(f"{found.get('cells')} cells against {foam.n_cells(case)}")
    for name in (field,) + tuple(extra_cells):
        if name not in found.get("cellArrays", []):
            failures.append(f"cell array {name} missing")
    values = foam.read_field(os.path.join(case, t, field), foam.n_cells(case))
    if found.get("field") is None or not np.allclose(found["field"],
                                                     [values.min(), values.max()],
                                                     rtol=1e-6, atol=1e-12):
        failures.append(f"{field} range {found.get('field')} against the file's"
                        f" [{values.min()}, {values.max()}]")
    parcels = len(foam.read_list(os.path.join(case, t, "lagrangian", cloud, "U")))
    seen = found["clouds"].get(cloud)
    if not seen or seen["parcels"] != parcels:
        failures.append(f"cloud {cloud}: {seen and seen['parcels']} parcels against"
                        f" {parcels} in its files")
    for name in ("specularFraction", "thermalAccommodation") + tuple(extra_parcels):
        if not seen or name not in seen["arrays"]:
            failures.append(f"cloud array {name} missing")

    image = matplotlib.image.imread(output)
    if image.shape[:2] != (600, 800):
        failures.append(f"picture {image.shape[1]} x {image.shape[0]}")
    rgb = (image[..., :3]*255).astype(int)
    drawn = np.any(rgb < 250, axis=-1).mean()
    colours = len(np.unique(rgb.reshape(-1, 3), axis=0))
    if drawn < 0.01 or colours < 20:
        failures.append(f"blank picture: {100*drawn:.1f} % drawn, {colours} colours")
    print(f"ParaView on {case}: time {found['time']}, {found.get('cells')} cells,"
          f" cloud {cloud} {seen and seen['parcels']} parcels; picture {output}:"
          f" {100*drawn:.0f} % drawn, {colours} colours")
    return failures, found
