# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The apolloPSI scene of the speed-accuracy study (apollo.py): its
--quick study (apollo.QUICK settings, 20 us of the scaled Apollo PSI
demo, one seed; 2.5-3 minutes), run as tradeoff.py apolloPSI --quick
does (apollo.study, then rmf.bench.write_outputs).  With ./Alltest --long
only: it measures the study (a benchmark, bench/), and the physics it
checks on the way, the jet's push on the layer and the inflow, the
default suite checks in test_apolloScaledPSI's reduced runs; at 165 s
it was the suite's slowest test (the suite's 35-minute budget,
testing/README.md).

Checks of the quick study (each able to fail; measured 2026-12-03 with
seed 1):
- every quick setting ran, and the report was written (the reference's
  own errors, 0, and the base's cost, 1, hold by construction and are not
  checked: they could not fail);
- the shock stands by 20 us in every setting: a standoff on the axis
  between 1 and 3 mm (measured 1.69-2.10 mm; the demo's standoff is
  3.2 mm over 40-100 us, README.md's vibration table, and still moving
  out at 20 us: 2.0 mm at 20 us, 3.1 mm at 40 us in a 60 us run);
- the base's standoff within 10 % of the reference's (the study's error
  target; measured 2.2 %; at 60 us its two seeds differ by about 2 %);
- the jet pushes the layer down in every setting: the surface drop on
  the axis above 5 of rmf.psi's sigma of it (measured 0.32-0.38 mm
  against sigma 0.017-0.019 mm, 17 sigma and more);
"""

import os

import numpy as np
import pytest

import apollo
from rmf import bench
from rmf_testing import report


@pytest.mark.long
def test_apollo_quick():
    result = apollo.study(True, 1)
    bench.write_outputs("apolloPSI", **result)
    rows = {r["setting"]: r for r in result["rows"]}
    ok_all = report("every quick setting ran",
                    sorted(rows) == sorted(apollo.QUICK) and os.path.exists(
                        os.path.join(bench.OUT, "apolloPSI", "tradeoff.md")),
                    f"{len(rows)} of {len(apollo.QUICK)}")
    base = rows["base"]
    standoff = {n: r["standoffValue"] for n, r in rows.items()}
    ok_shock = report("a shock on the axis by 20 us, 1-3 mm",
                      all(np.isfinite(v) and 1e-3 < v < 3e-3 for v in standoff.values()),
                      ", ".join(f"{n} {1e3*v:.2f} mm" for n, v in standoff.items()))
    ok_base = report("base's standoff within 10 % of the reference",
                     abs(base["standoff"]) < 0.10, f"{100*base['standoff']:+.1f} %")
    z = {n: r["dropValue"]/r["dropSigma"] for n, r in rows.items()}
    ok_drop = report("the layer pushed down on the axis (drop > 5 sigma)",
                     all(np.isfinite(v) and v > 5 for v in z.values()),
                     ", ".join(f"{n} {1e3*rows[n]['dropValue']:.3f} mm ({v:.0f} sigma)"
                               for n, v in z.items()))
    assert ok_all and ok_shock and ok_base and ok_drop
