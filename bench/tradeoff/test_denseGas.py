# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The denseGas scene of the speed-accuracy study (denseGas.py): its
--quick study (Kn 0.05, the reference, ES-BGK at the reference's step,
and NTC, NTC sub-stepped and ES-BGK at 1 and 20 mean collision times;
one seed, about 20 s), run as tradeoff.py denseGas --quick does.  In the
default suite: it is the reduced form of the gas models' trade
(doc/speed-accuracy.md, "Dense gas"), whose full size is a benchmark.

Checks (each able to fail; the figures are the means and sds over the
quick study's seeds 1-6, measured 2026-12-07):
- ES-BGK at the reference's step (0.1 tau_c) gives the surface's shear,
  heat flux and pressure within 10 % of DSMC's (the study's error target:
  the particle BGK model stands in for DSMC where both are resolved;
  measured |errors| 2.1 +- 1.2, 1.2 +- 0.9 and 0.7 +- 0.2 %: the bound
  is 6.6 sd or more away);
- at 20 mean collision times every model (upstream's NTC, NTC sub-
  stepped, ES-BGK) more than doubles the surface's shear and heat flux
  (the transport of a particle model over a flight of the step,
  doc/physics.md#es-bgk; measured +295 to +325 % and +221 to +246 %, sd
  5 % or less: 24 sd or more above the bound);
- at that step NTC sub-stepped and ES-BGK, both relaxing exactly within
  the step, give the same shear and heat flux within 20 % (measured
  1.074 and 1.078 between them, sd of each error about 5 %: 20 % is more
  than 7 sd from them).
No Bonferroni share: effects this far beyond their noise fail a correct
build with a probability far below rmf_testing.MODULE_ALPHA.  Seeds:
every randomSeed of the study through rmf_testing.seed(1).
"""

import denseGas
from rmf import bench
from rmf_testing import report, seed


def test_dense_gas_quick():
    result = denseGas.study(True, 1, first=seed(1))
    bench.write_outputs("denseGas", **result)
    rows = {r["setting"]: r for r in result["rows"]}
    ran = report("every quick setting ran",
                 sorted(rows) == sorted(s[0] for s in denseGas.settings(True)),
                 f"{len(rows)} settings")
    bgk = rows["bgk0.1"]
    ok_bgk = report("ES-BGK at the resolved step within 10 % of DSMC (shear, heat, pressure)",
                    all(abs(bgk[e]) < 0.10 for e in denseGas.JUDGED),
                    ", ".join(f"{e} {100*bgk[e]:+.1f} %" for e in denseGas.JUDGED))
    long_step = [rows[f"{m}20"] for m in denseGas.MODELS]
    ok_long = report("at 20 tau_c every model more than doubles the surface's shear and heat",
                     all(r["shear"] > 1 and r["heat"] > 1 for r in long_step),
                     ", ".join(f"{r['setting']} {100*r['shear']:+.0f} / {100*r['heat']:+.0f} %"
                               for r in long_step))
    sub, es = rows["subSteps20"], rows["bgk20"]
    ratio = {e: sub[e + "Value"]/es[e + "Value"] for e in ("shear", "heat")}
    ok_same = report("at 20 tau_c NTC sub-stepped and ES-BGK agree within 20 %",
                     all(abs(v - 1) < 0.20 for v in ratio.values()),
                     ", ".join(f"{e} {v:.3f}" for e, v in ratio.items()))
    assert ran and ok_bgk and ok_long and ok_same
