# rarefiedMultiphaseFoam. Copyright (C) 2026 The rarefiedMultiphaseFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (the licence is in COPYING)
"""The benchmarks' shared part: the speed-accuracy study's scene-independent
half (bench/tradeoff/tradeoff.py and its scene modules, such as
bench/tradeoff/apollo.py, doc/speed-accuracy.md): a run's CPU time, the
errors, the Pareto front and the study's outputs (CSV, picture, report) in
OUT/<scene>."""

import csv
import os

import numpy as np

from rmf import figures, foam

OUT = os.path.join(foam.PROJECT_DIR, "build", "bench", "tradeoff")
TARGET = 0.10               # the error target of the recommendation


def cpu_time(log):
    """The solver's CPU time [s] at the end of its log (its last
    ExecutionTime)."""
    return foam.execution_times(log)[-1]


def pareto_front(cost, error):
    """Indices of the settings no other setting beats in both cost and
    error (ties kept), in order of cost."""
    cost = np.asarray(cost, float)
    error = np.asarray(error, float)
    front = []
    for i in np.argsort(cost, kind="stable"):
        dominated = np.any((cost <= cost[i]) & (error <= error[i])
                           & ((cost < cost[i]) | (error < error[i])))
        if not dominated and np.isfinite(error[i]):
            front.append(int(i))
    return front


def curve_error(t, y, t_ref, y_ref, grid):
    """RMS difference of two curves on a grid, over the reference's final
    value."""
    a = np.interp(grid, t, y)
    b = np.interp(grid, t_ref, y_ref)
    return float(np.sqrt(np.mean((a - b)**2))/max(abs(y_ref[-1]), 1e-300))


def relative_error(x, ref):
    if x is None or ref is None or ref == 0:
        return float("nan")
    return float(x/ref - 1)


def spread(rows, key):
    """The rows' values of key over the seeds, as text: "mean ± sd" (the
    finite ones; one value alone, or n/a)."""
    v = np.array([r[key] for r in rows], float)
    v = v[np.isfinite(v)]
    if len(v) == 0:
        return "n/a"
    if len(v) == 1:
        return f"{v[0]:.4g}"
    return f"{v.mean():.4g} ± {v.std(ddof=1):.2g}"


def against_reference(rows, errors, base="reference"):
    """Each row's cost (its CPU time over the base setting's of the same
    seed) and its errors (row[e] from row[e + "Value"]) against the
    reference setting's of the same seed; returns the reference's rows."""
    def of(name, seed):
        return next(b for b in rows if b["setting"] == name and b["seed"] == seed)
    for r in rows:
        ref = of("reference", r["seed"])
        r["cost"] = r["cpu"]/of(base, r["seed"])["cpu"]
        for e in errors:
            r[e] = relative_error(r[e + "Value"], ref[e + "Value"])
    return [r for r in rows if r["setting"] == "reference"]


def write_outputs(scene, rows, errors, main_error, note, judged=None,
                  cost_label="the reference's", base="base"):
    """CSV of every run, the Pareto picture of the seeds' means and the
    markdown report; the recommendation is the cheapest setting whose
    judged errors (default main_error and rate) are all within TARGET.
    A setting's cost is its least CPU time over the seeds over the base
    setting's least (the machine's contention only ever adds time), with
    the spread of the seeds' own ratios beside it."""
    judged = judged or (main_error, "rate")
    out = os.path.join(OUT, scene)
    keys = list(rows[0].keys())
    with open(os.path.join(out, "tradeoff.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)

    # Mean and spread over the seeds, per setting
    names = list(dict.fromkeys(r["setting"] for r in rows))
    least_base = min(r["cpu"] for r in rows if r["setting"] == base)
    summary = []
    for name in names:
        every = [r for r in rows if r["setting"] == name]
        failed = [r for r in every if r.get("failed")]
        runs = [r for r in every if not r.get("failed")]
        label = every[0]["label"]
        if failed:
            label += (f"; **failed** in {len(failed)} of {len(every)} seeds"
                      f" (seed {failed[0]['seed']}, {failed[0]['failed']})")
        cpu = min(r["cpu"] for r in runs) if runs else float("nan")
        entry = {"setting": name, "label": label, "seeds": len(runs),
                 "cost": cpu/least_base,
                 "costSd": float(np.std([r["cost"] for r in runs], ddof=1))
                 if len(runs) > 1 else 0.0,
                 "cpu": cpu}
        runs = runs or every
        for e in errors:
            v = np.array([r[e] for r in runs], float)
            entry[e] = float(np.mean(np.abs(v))) if np.all(np.isfinite(v)) else float("nan")
            entry[e + "Sd"] = float(np.std(np.abs(v), ddof=1)) if len(v) > 1 and np.all(
                np.isfinite(v)) else 0.0
        summary.append(entry)

    cost = [s["cost"] for s in summary]
    err = [s[main_error] for s in summary]
    front = pareto_front(cost, err)

    plt = figures.pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 5))
    for i, s in enumerate(summary):
        if not np.isfinite(s[main_error]):
            continue
        ax.errorbar(s["cost"], max(s[main_error], 1e-4), yerr=s[main_error + "Sd"],
                    xerr=s["costSd"],
                    fmt="o", color="C3" if i in front else "C0", capsize=3)
        ax.annotate(s["setting"], (s["cost"], max(s[main_error], 1e-4)),
                    textcoords="offset points", xytext=(5, 4), fontsize=8)
    fx = [summary[i]["cost"] for i in front]
    fy = [max(summary[i][main_error], 1e-4) for i in front]
    ax.step(fx, fy, where="post", color="C3", lw=1, label="Pareto front")
    ax.axhline(TARGET, color="grey", ls=":", lw=1, label=f"{100*TARGET:.0f} % error")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(f"CPU time / {cost_label}")
    ax.set_ylabel(f"{main_error} error (|relative|; reference at 1e-4)")
    ax.set_title(f"Speed-accuracy: {scene}")
    ax.legend(fontsize=8)
    fig.tight_layout()
    png = os.path.join(out, "tradeoff.png")
    figures.save(fig, png)

    ok = [s for s in summary if all(np.isfinite(s[e]) and s[e] <= TARGET
                                    for e in judged)]
    best = min(ok, key=lambda s: s["cost"]) if ok else None
    lines = [f"# Speed-accuracy: {scene}", "", note, "",
             "| setting | what | seeds | least CPU [s] | cost / base | "
             + " | ".join(f"{e} error" for e in errors) + " | Pareto |",
             "|---|---|---|---|---|" + "---|"*len(errors) + "---|"]
    for i, s in enumerate(summary):
        cells = []
        for e in errors:
            if np.isfinite(s[e]):
                sd = f" ± {100*s[e + 'Sd']:.1f}" if s["seeds"] > 1 else ""
                cells.append(f"{100*s[e]:.1f}{sd} %")
            else:
                cells.append("–")
        spread = f" ± {s['costSd']:.2f}" if s["seeds"] > 1 else ""
        cost = f"{s['cost']:.3f}{spread}" if np.isfinite(s["cost"]) else "–"
        cpu = f"{s['cpu']:.1f}" if np.isfinite(s["cpu"]) else "–"
        lines.append(f"| {s['setting']} | {s['label']} | {s['seeds']} | {cpu} |"
                     f" {cost} | " + " | ".join(cells)
                     + f" | {'yes' if i in front else ''} |")
    lines += ["", "Cheapest setting within "
              f"{100*TARGET:.0f} % of the reference in " + " and ".join(judged) + ": "
              + (f"**{best['setting']}** ({best['label']}), at {best['cost']:.3f} of"
                 f" {cost_label} CPU time." if best else "none."), ""]
    with open(os.path.join(out, "tradeoff.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))
    print(os.path.join(out, "tradeoff.csv"))
    print(png)
    print(os.path.join(out, "tradeoff.md"))
    return summary, best
