#!/usr/bin/env python3
"""Write doc/work_precision.md and doc/figures/wp_*.png from the CSV of the
work-precision study (bench/work_precision.py).  Every number in the report
is computed here from that CSV.

    make_work_precision_report.py [CSV]    (default doc/work_precision.csv)
"""
import csv
import math
import os
import sys
import time

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from common import ROOT  # noqa: E402

CSV = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "doc", "work_precision.csv")
FIG = os.path.join(ROOT, "doc", "figures")
OUT = os.path.join(ROOT, "doc", "work_precision.md")
os.makedirs(FIG, exist_ok=True)

DEFAULT, DISC = "mg-W-b", "mg-W-b-disc"
SCENES = ["square", "mms", "hertz", "cube3d"]
TITLE = {"square": "square (prm/square.prm)", "mms": "manufactured solution (prm/elasticity_mms.prm)",
         "hertz": "half-disc Hertz (prm/hertz.prm)", "cube3d": "3D cube (prm/cube3d.prm)"}
MAIN_CONFIGS = [DEFAULT, DISC, "mg-V-b", "plain-W-b", "plain-V-b", "pgs", "as"]
LABEL = {DEFAULT: "MG default W(b), tol 1e-8", DISC: "MG W(b), discretization stop",
         "mg-V-b": "MG V(b), tol 1e-8", "plain-W-b": "plain W(b) (Krylov 0)",
         "plain-V-b": "plain V(b) (Krylov 0)", "pgs": "projected Gauss-Seidel",
         "as": "active set + direct"}
STYLE = {DEFAULT: "o-", DISC: "s--", "mg-V-b": "^-", "plain-W-b": "v:", "plain-V-b": "<:",
         "pgs": "x-.", "as": "D-"}


# ----------------------------------------------------------------- data
def num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return v


with open(CSV) as f:
    ALL = [{k: num(v) for k, v in r.items()} for r in csv.DictReader(f)]
META = next((r for r in ALL if r["case"] == "_meta"), {"note": "", "wall_s": float("nan")})
RUNS = [r for r in ALL if r["case"] != "_meta"]
for r in RUNS:
    r["level"] = int(r["level"])
META_KV = dict(kv.split("=", 1) for kv in META["note"].split("; ") if "=" in kv)


def ok(r):
    return r is not None and r["status"] == "ok"


def converged(r):
    return ok(r) and str(r["converged"]).lower() == "true"


def get(scene, config, level):
    for r in RUNS:
        if r["scene"] == scene and r["config"] == config and r["level"] == level:
            return r
    return None


def series(scene, config):
    return sorted((r for r in RUNS if r["scene"] == scene and r["config"] == config and ok(r)),
                  key=lambda r: r["level"])


def fmt(v, f=".3g"):
    if v is None or v == "" or (isinstance(v, float) and math.isnan(v)):
        return "–"
    return format(v, f)


def table(header, body):
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in body]
    return "\n".join(lines) + "\n"


def fit_slope(xs, ys):
    """Least-squares slope of log y over log x (None for fewer than 2 points)."""
    p = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x and y and x > 0 and y > 0]
    if len(p) < 2:
        return None
    return float(np.polyfit([a for a, _ in p], [b for _, b in p], 1)[0])


def legend(ax, size):
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=size)


def loglog(ax, xs, ys, style, label, fit_from=0.0):
    """Plot one series log-log with its fitted slope in the legend (fitted over
    the points with x >= fit_from when there are two, else over all)."""
    pts = [(x, y) for x, y in zip(xs, ys) if x and y and x > 0 and y > 0]
    if not pts:
        return
    big = [p for p in pts if p[0] >= fit_from]
    s = fit_slope(*zip(*(big if len(big) >= 2 else pts)))
    ax.loglog([x for x, _ in pts], [y for _, y in pts], style, ms=4,
              label=f"{label} (slope {s:.2f})" if s is not None else label)


# ----------------------------------------------------------------- errors
def reference(scene):
    """Finest converged default-solver run (the force reference)."""
    c = [r for r in series(scene, DEFAULT) if converged(r)]
    return c[-1] if c else None


REF = {s: reference(s) for s in ["square", "cube3d"]}


def error(r):
    """The scene's error measure of run r, or None."""
    if not ok(r):
        return None
    if r["scene"] in REF:
        ref = REF[r["scene"]]
        if ref is None or r["level"] >= ref["level"] or r.get("contact") == "no" or \
                r.get("body_force") not in ("scene", "", None):
            return None
        return abs(r["force_y"] - ref["force_y"]) / abs(ref["force_y"])
    if r["scene"] == "mms":
        return r["error_u_h1"] if r.get("body_force") in ("scene", "") else None
    if r["scene"] == "hertz":
        return r["pressure_error_l2_rel"]
    return None


ERRNAME = {"square": "|F_y − F_y(ref)| / |F_y(ref)|", "cube3d": "|F_z − F_z(ref)| / |F_z(ref)|",
           "mms": "‖u − u_h‖_H1", "hertz": "rel. L2 error of the contact pressure vs Hertz"}


def solver_text(r):
    if r["config"] == "as":
        return "`Solver/Type=active set`"
    if r["config"] == "pgs":
        return f"`Solver/Type=projected gauss seidel` ({int(r['iterations'])} sweeps)"
    t = [f"`Cycle={r['cycle']}`", f"`Projection={r['projection']}`"]
    if int(r["krylov_steps"]) == 0:
        t.append("`Krylov steps=0`")
    if r["stopping"] == "discretization accuracy":
        t.append("`Stopping criterion=discretization accuracy`")
    else:
        t.append(f"`Tolerance={r['tolerance']}`")
    return "MG " + ", ".join(t)


def cheapest(scene, target, measure):
    cand = [r for r in RUNS if r["scene"] == scene and ok(r) and measure(r) is not None
            and measure(r) <= target]
    return min(cand, key=lambda r: r["wall_s"]) if cand else None


def answer_rows(scene, targets, measure, name):
    body = []
    for t in targets:
        r = cheapest(scene, t, measure)
        if r is None:
            vals = [(measure(z), z) for z in RUNS if z["scene"] == scene and ok(z)
                    and measure(z) is not None]
            best = min(vals, key=lambda v: v[0]) if vals else None
            body.append([TITLE[scene].split(" (")[0], f"{name} ≤ {t:g}", "not reached", "", "",
                         "", f"best measured {fmt(best[0])} ({best[1]['case']})" if best else "",
                         ""])
        else:
            d = get(scene, DEFAULT, r["level"])
            dt = (f"{d['wall_s']:.2f} s, error {fmt(measure(d))}" if ok(d) and
                  measure(d) is not None else "–")
            body.append([TITLE[scene].split(" (")[0], f"{name} ≤ {t:g}", r["level"],
                         int(r["dofs"]), solver_text(r), fmt(r["wall_s"], ".2f"),
                         fmt(measure(r)), dt])
    return body


def j_targets(scene):
    js = [r["functional"] for r in RUNS if r["scene"] == scene and ok(r) and r["functional"] > 0
          and r.get("contact") != "no" and r.get("body_force") in ("scene", "")]
    if not js:
        return []
    k = math.ceil(math.log10(min(js)))
    return [10.0 ** (k + 2), 10.0 ** (k + 1), 10.0 ** k]


def jmeasure(r):
    if r.get("contact") == "no" or r.get("body_force") not in ("scene", ""):
        return None
    return r["functional"]


md = []
# ----------------------------------------------------------------- answer first
md.append("# Work–precision study\n")
md.append("<!-- generated by bench/make_work_precision_report.py from doc/work_precision.csv "
          "(bench/work_precision.sh); do not edit by hand -->\n")
md.append("**Answer.** For a target accuracy, the cheapest measured run that reaches it "
          "(level, solver settings, wall seconds of the whole process, single measurement "
          "on a " + META_KV.get("cpus", "?") + "-core machine; about "
          f"{META['wall_s']:.1f} s of every run is process start, so below ~2 s the choice "
          "between settings is within measurement noise — the last column gives the default "
          "solver on the same level). Errors: contact force relative to "
          "the finest converged default-solver level (" +
          ", ".join(f"{s}: level {REF[s]['level']}" for s in REF if REF[s]) +
          "; runs on that level or finer cannot be rated), the exact H1 error for the "
          "manufactured solution, the relative L2 error of the contact pressure against "
          "Hertz's profile for the half-disc, and the least-squares functional J "
          "(the a-posteriori estimate) for all.\n")
body = []
for s in ["square", "cube3d"]:
    body += answer_rows(s, [1e-3, 1e-4, 1e-5], error, "force rel. error")
body += answer_rows("mms", [1e-1, 3e-2, 1e-2], error, "‖u−u_h‖_H1")
body += answer_rows("hertz", [0.2, 0.1, 0.05], error, "pressure rel. L2 error")
for s in SCENES:
    body += answer_rows(s, j_targets(s), jmeasure, "J")
md.append(table(["scene", "target", "level", "DoFs", "solver settings", "wall s",
                 "measured error", "default solver on that level"], body))


# extrapolated error of the reference itself (geometric sequence of differences)
def extrapolated(scene):
    s = [r for r in series(scene, DEFAULT) if converged(r)]
    if len(s) < 3:
        return None
    d1 = s[-1]["force_y"] - s[-2]["force_y"]
    d0 = s[-2]["force_y"] - s[-3]["force_y"]
    q = d1 / d0 if d0 else None
    if q is None or not 0 < q < 1:
        return None
    return q, abs(d1 * q / (1 - q)) / abs(s[-1]["force_y"]), s[-1]["level"]


notes = []
for s in REF:
    e = extrapolated(s)
    if e:
        notes.append(f"{s}: the force differences between the last levels shrink by "
                     f"q = {e[0]:.2f} per level, so the reference (level {e[2]}) itself is "
                     f"about {e[1]:.1e} (relative) from the limit (geometric extrapolation)")
if notes:
    md.append("A target below the reference's own error cannot be certified: " +
              "; ".join(notes) + ".\n")

# ----------------------------------------------------------------- setup
ran = [r for r in RUNS if r["status"] in ("ok", "error", "timeout")]
tot = sum(r["wall_s"] for r in ran if isinstance(r["wall_s"], float))
md.append("## How this was measured\n")
md.append(f"Run {META_KV.get('started', '?')} by `bench/work_precision.sh` (git "
          f"`{META_KV.get('git', '?')}`) on a machine with {META_KV.get('cpus', '?')} cores "
          f"and {META_KV.get('mem_gb', '?')} GB memory; the program used all cores (threads) and the cases ran "
          f"one at a time. **Every timing is a single measurement** (other processes, e.g. a "
          f"compiler, may have shared the machine). {len(ran)} cases ran in {tot / 60:.1f} min "
          f"(budget {float(META_KV.get('budget_s', 'nan')) / 60:.0f} min, per-case cap "
          f"{META_KV.get('case_cap_s', '?')} s, a case is skipped when its time predicted from the "
          f"next coarser level exceeds either); "
          f"{sum(1 for r in RUNS if r['status'] == 'skipped')} cases were skipped (list at the "
          "end). VTU output is off (`Output/Write vtu=false`), so the output phase only writes "
          "CSV/JSON. `wall s` is the wall time of the whole process measured by the script; a "
          f"process that does nothing (`--print-parameters`) takes {META['wall_s']:.2f} s "
          "(library loading, MPI start), which dominates the small levels.\n")
loads = [r["load1"] for r in ran if isinstance(r.get("load1"), float)]
bins = sorted({r["binary_mtime"] for r in ran if r.get("binary_mtime")})
if loads:
    md.append(f"Machine load (1-minute load average before each case): mean {np.mean(loads):.2f}, "
              f"max {max(loads):.2f} on {META_KV.get('cpus', '?')} cores"
              + (" — other processes were running during part of the study, so some timings "
                 "are inflated" if max(loads) > 1.5 else "") + ". "
              + (f"The binary was rebuilt during the study (modification times "
                 f"{', '.join(bins)}), so iteration counts may differ slightly between cases."
                 if len(bins) > 1 else "The same binary ran every case.") + "\n")
md.append("Solver names: `mg-<cycle>-<projection>` = monotone multigrid with Krylov steps "
          "50 (the program's default: CG to a residual reduction of 1e-3, at most 50 steps; the scenes set W, projection b, 3+3 smoothing steps, "
          "hertz 5+5), tolerance 1e-8; `-disc` = `Stopping criterion=discretization accuracy` "
          "(fraction 0.1); `plain-*` = Krylov steps 0 (the paper's cycle); `pgs` = projected "
          f"Gauss–Seidel with at most {META_KV.get('pgs_sweeps', '?')} sweeps; `as` = "
          "active set + sparse direct solver. `cycles` counts multigrid cycles (every CG "
          "step of the Krylov variant is one).\n")

# the 3D levels: how far memory goes (as far as fits in 20 GB)
cube = [r for r in ran if r["scene"] == "cube3d" and isinstance(r.get("peak_rss_mb"), float)]
if cube:
    top = max(r["level"] for r in cube)
    at = {L: max(r["peak_rss_mb"] for r in cube if r["level"] == L) for L in {r["level"] for r in cube}}
    dofs = {r["level"]: r["dofs"] for r in cube}
    if top - 1 in dofs:
        growth = dofs[top] / dofs[top - 1]
        per_dof = at[top] * 1024 / dofs[top]
        md.append(f"3D levels: the finest 3D level run is {top} ({int(dofs[top])} DoFs, peak "
                  f"memory {at[top] / 1024:.1f} GB, {per_dof:.1f} KB per DoF). Level {top + 1} "
                  f"would have about {dofs[top] * growth / 1e6:.1f} million DoFs (×{growth:.1f}) "
                  f"and need about {per_dof * dofs[top] * growth / 1024 ** 2:.0f} GB at the same "
                  "memory per DoF, more than the 20 GB the study may use, so it is not run.\n")

# ----------------------------------------------------------------- plots
def scene_error_plot(fname, xkey, title, fit_from=0.0):
    fig, axes = plt.subplots(2, 4, figsize=(17, 8))
    for j, s in enumerate(SCENES):
        for i, meas in enumerate([error, lambda r: r["sqrt_functional"]]):
            ax = axes[i][j]
            for c in MAIN_CONFIGS:
                rs = [r for r in series(s, c) if meas(r) is not None]
                loglog(ax, [xkey(r) for r in rs], [meas(r) for r in rs], STYLE[c], LABEL[c],
                       fit_from)
            ax.set_title(TITLE[s], fontsize=9)
            ax.set_ylabel(ERRNAME[s] if i == 0 else "sqrt(J)", fontsize=8)
            ax.set_xlabel(title, fontsize=8)
            ax.grid(alpha=0.3, which="both")
            legend(ax, 6)
    fig.tight_layout()
    fig.savefig(os.path.join(FIG, fname), dpi=90)
    plt.close(fig)


scene_error_plot("wp_error_vs_time.png", lambda r: r["wall_s"], "wall time [s]", 3.0)
scene_error_plot("wp_error_vs_dofs.png", lambda r: r["dofs"], "DoFs")


def per_scene_plot(fname, ykey, ylabel):
    fig, axes = plt.subplots(1, 4, figsize=(17, 4.2))
    for ax, s in zip(axes, SCENES):
        for c in MAIN_CONFIGS:
            rs = series(s, c)
            loglog(ax, [r["dofs"] for r in rs], [ykey(r) for r in rs], STYLE[c], LABEL[c])
        ax.set_title(TITLE[s], fontsize=9)
        ax.set_xlabel("DoFs")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3, which="both")
        legend(ax, 6)
    fig.tight_layout()
    fig.savefig(os.path.join(FIG, fname), dpi=90)
    plt.close(fig)


per_scene_plot("wp_time_vs_dofs.png", lambda r: r["wall_s"], "wall time [s]")
per_scene_plot("wp_solve_time_vs_dofs.png", lambda r: r["time_solve_s"], "solve time [s]")
per_scene_plot("wp_memory_vs_dofs.png", lambda r: r["peak_rss_mb"], "peak RSS [MB]")

md.append("## Work–precision plots\n")
md.append("Log–log; the legend gives the least-squares slope of each line (against wall "
          "time fitted over the runs of ≥ 3 s where there are two, since process start "
          "dominates shorter runs). Top row: the "
          "scene's own error measure; bottom row: sqrt(J), the least-squares functional "
          "(an error-norm-like a-posteriori quantity). Not every solver ran on every "
          "level (see the tables).\n")
md.append("![error vs time](figures/wp_error_vs_time.png)\n")
md.append("![error vs DoFs](figures/wp_error_vs_dofs.png)\n")
md.append("Wall time (whole process) and solve time against DoFs:\n")
md.append("![time vs DoFs](figures/wp_time_vs_dofs.png)\n")
md.append("![solve time vs DoFs](figures/wp_solve_time_vs_dofs.png)\n")
md.append("Peak memory (`peak_rss_mb`, the process high-water mark, includes the ~"
          f"{min(r['peak_rss_mb'] for r in RUNS if ok(r)):.0f} MB of the smallest run):\n")
md.append("![memory vs DoFs](figures/wp_memory_vs_dofs.png)\n")

# slopes table
body = []
for s in SCENES:
    for c in MAIN_CONFIGS:
        rs = series(s, c)
        if len(rs) < 2:
            continue
        big = [r for r in rs if r["dofs"] >= 1e4] or rs
        e = [r for r in rs if error(r) is not None]
        body.append([s, c, f"{rs[0]['level']}–{rs[-1]['level']}",
                     fmt(fit_slope([r["dofs"] for r in e], [error(r) for r in e]), ".2f"),
                     fmt(fit_slope([r["dofs"] for r in rs], [r["sqrt_functional"] for r in rs]), ".2f"),
                     fmt(fit_slope([r["dofs"] for r in big], [r["time_solve_s"] for r in big]), ".2f"),
                     fmt(fit_slope([r["dofs"] for r in big], [r["peak_rss_mb"] for r in big]), ".2f"),
                     fmt(rs[-1]["wall_s"], ".1f"), fmt(rs[-1]["peak_rss_mb"], ".0f")])
md.append("Fitted slopes against DoFs (error and sqrt(J) over all levels; solve time and memory "
          "over the levels with ≥ 10⁴ DoFs where there are two or more, else all) and the "
          "finest level's wall time and memory:\n")
md.append(table(["scene", "solver", "levels", "error slope", "sqrt(J) slope",
                 "solve-time slope", "memory slope", "finest wall s", "finest MB"], body))

# ----------------------------------------------------------------- per-level tables
md.append("## Levels\n")
for s in SCENES:
    md.append(f"### {TITLE[s]}\n")
    levels = sorted({r["level"] for r in RUNS if r["scene"] == s})
    body = []
    for L in levels:
        line = [L]
        dofs = next((r["dofs"] for r in RUNS if r["scene"] == s and r["level"] == L and ok(r)), None)
        line.append(int(dofs) if dofs else "–")
        for c in [DEFAULT, DISC, "as", "pgs"]:
            r = get(s, c, L)
            if r is None:
                line.append("")
            elif not ok(r):
                line.append(f"{r['status']}")
            else:
                cyc = "" if c in ("as", "pgs") else f" / {int(r['cycles'])} cyc"
                nc = "" if converged(r) else " ✗"
                line.append(f"{r['wall_s']:.2f} s / {int(r['iterations'])} it{cyc}{nc} / "
                            f"{fmt(error(r))} / J {fmt(r['functional'])}")
        body.append(line)
    md.append(f"Cells: wall s / iterations (/ cycles) (✗ = not converged) / {ERRNAME[s]} / J.\n")
    md.append(table(["level", "DoFs", DEFAULT, DISC, "as", "pgs"], body))

# ----------------------------------------------------------------- solver matrix
md.append("## All solver settings on the small levels\n")
md.append("Cells: wall s / cycles (iterations for as and pgs; ✗ = not converged) / the scene's "
          "error. The last column gives, per setting, the largest relative difference of the "
          "force (square, cube) or J (mms, hertz) to the active-set solution on the same level.\n")
for s in SCENES:
    mats = sorted({r["config"] for r in RUNS if r["scene"] == s and r["group"] == "matrix"})
    mats = [c for c in MAIN_CONFIGS if c in mats] + [c for c in mats if c not in MAIN_CONFIGS]
    levels = sorted({r["level"] for r in RUNS if r["scene"] == s and r["group"] == "matrix"})
    if not mats:
        continue
    body = []
    for c in mats:
        line = [c]
        dev = []
        for L in levels:
            r = get(s, c, L)
            a = get(s, "as", L)
            if not ok(r):
                line.append(r["status"] if r else "")
                continue
            k = int(r["iterations"]) if c in ("as", "pgs") else int(r["cycles"])
            line.append(f"{r['wall_s']:.2f} / {k}{'' if converged(r) else ' ✗'} / {fmt(error(r))}")
            if ok(a):
                key = "force_y" if s in REF else "functional"
                if a[key]:
                    dev.append(abs(r[key] - a[key]) / abs(a[key]))
        line.append(fmt(max(dev), ".1e") if dev else "–")
        body.append(line)
    md.append(f"### {TITLE[s]}\n")
    md.append(table(["setting"] + [f"level {L}" for L in levels] + ["max rel. diff. to as"], body))

same, groups, spread = 0, 0, []
for s_ in SCENES:
    for L in range(3, 10):
        for cyc in "VW":
            for stop in ("", "-disc"):
                rs = [get(s_, f"mg-{cyc}-{p}{stop}", L) for p in "abcd"]
                if all(ok(r) for r in rs):
                    groups += 1
                    same += len({int(r["cycles"]) for r in rs}) == 1
                    t = [r["time_solve_s"] for r in rs]
                    spread.append(max(t) / min(t) if min(t) > 0 else 1.0)
if groups:
    md.append(f"**Projections a–d.** In {same} of {groups} (scene, level, cycle, stopping) groups "
              "the four projections need the same number of cycles; the solve times within a "
              f"group differ by a factor of at most {max(spread):.2f} (median "
              f"{float(np.median(spread)):.2f}), which at these sizes is within the noise of "
              "single measurements.\n")

# ----------------------------------------------------------------- tolerance sweep
md.append("## Tolerance sweep\n")
md.append("Default solver with `Solver/Tolerance` from 1e-2 to 1e-10. Algebraic error = "
          "difference to the run with the tightest tolerance on the same level; "
          "discretization error = difference of the (tolerance 1e-8) result to the next finer "
          "level's (default solver, or active set where the default did not run). "
          "'Digits' = −log10(tolerance); cycles and seconds per digit are least-squares "
          "slopes over the sweep.\n")
fig, axes = plt.subplots(1, 3, figsize=(16, 4.2))
sweeps = sorted({(r["scene"], r["level"]) for r in RUNS if r["group"] == "tolerance"})
summary = []
for s, L in sweeps:
    rs = sorted([r for r in RUNS if r["scene"] == s and r["level"] == L and ok(r)
                 and r["config"].startswith(DEFAULT) and r["stopping"] == "tolerance"
                 and r["config"] in (DEFAULT,) + tuple(f"{DEFAULT}-tol{t}" for t in
                                                        ["1e-2", "1e-3", "1e-4", "1e-5", "1e-6",
                                                         "1e-7", "1e-9", "1e-10"])],
                key=lambda r: -float(r["tolerance"]))
    if len(rs) < 2:
        continue
    conv = rs[-1]
    fine = get(s, DEFAULT, L + 1) if converged(get(s, DEFAULT, L + 1)) else get(s, "as", L + 1)
    base = get(s, DEFAULT, L)
    key = "force_y"
    disc = abs(fine[key] - base[key]) / abs(fine[key]) if ok(fine) and ok(base) else None
    disc_j = abs(fine["functional"] - base["functional"]) / base["functional"] \
        if ok(fine) and ok(base) else None
    body = []
    digits = [-math.log10(float(r["tolerance"])) for r in rs]
    for r in rs:
        alg = abs(r[key] - conv[key]) / abs(conv[key])
        alg_j = abs(r["functional"] - conv["functional"]) / conv["functional"]
        body.append([r["tolerance"], int(r["iterations"]), int(r["cycles"]),
                     fmt(r["time_solve_s"], ".2f"), fmt(r["wall_s"], ".2f"),
                     "yes" if converged(r) else "no",
                     fmt(alg, ".1e"), fmt(alg_j, ".1e")])
        r["_alg"] = alg
    cyc_per = float(np.polyfit(digits, [r["cycles"] for r in rs], 1)[0])
    sec_per = float(np.polyfit(digits, [r["time_solve_s"] for r in rs], 1)[0])
    enough = next((r for r in rs if disc is not None and r["_alg"] <= 0.1 * disc), None)
    enough1 = next((r for r in rs if disc is not None and r["_alg"] <= disc), None)
    summary.append((s, L, cyc_per, sec_per, disc, enough, enough1, base))
    md.append(f"### {s}, level {L} ({int(rs[0]['dofs'])} DoFs)\n")
    md.append(table(["tolerance", "iterations", "cycles", "solve s", "wall s", "converged",
                     "force: algebraic rel. error", "J: algebraic rel. error"], body))
    md.append(f"Discretization error (level {L} vs {L + 1}): force {fmt(disc, '.1e')}, "
              f"J {fmt(disc_j, '.1e')} (relative). {cyc_per:.2f} cycles and {sec_per:.3f} s of "
              f"solve time per extra digit. The algebraic force error drops below 1/10 of the "
              f"discretization error from tolerance "
              f"{enough['tolerance'] if enough else '– (never)'} on ({int(enough['cycles']) if enough else '–'} cycles, "
              f"{fmt(enough['time_solve_s'] if enough else None, '.2f')} s solve vs "
              f"{fmt(base['time_solve_s'], '.2f')} s at 1e-8), below the discretization error "
              f"itself from {enough1['tolerance'] if enough1 else '– (never)'}.\n")
    lab = f"{s} L{L}"
    axes[0].plot(digits, [r["cycles"] for r in rs], "o-", label=lab)
    axes[1].plot(digits, [r["time_solve_s"] for r in rs], "o-", label=lab)
    axes[2].semilogy(digits[:-1], [max(r["_alg"], 1e-17) for r in rs[:-1]], "o-", label=f"{lab} algebraic")
    if disc:
        axes[2].axhline(disc, ls="--", color=axes[2].lines[-1].get_color(),
                        label=f"{lab} discretization")
for ax, yl in zip(axes, ["cycles", "solve time [s]", "relative force error"]):
    ax.set_xlabel("digits = −log10(tolerance)")
    ax.set_ylabel(yl)
    ax.grid(alpha=0.3, which="both")
    legend(ax, 7)
fig.tight_layout()
fig.savefig(os.path.join(FIG, "wp_tolerance.png"), dpi=90)
plt.close(fig)
md.append("![tolerance sweep](figures/wp_tolerance.png)\n")

# ----------------------------------------------------------------- phases
md.append("## Time per phase\n")
PH = [("setup", lambda r: r["t_setup"]), ("assembly", lambda r: r["t_assembly"]),
      ("definiteness check", lambda r: r["t_definiteness"]),
      ("initial guess", lambda r: r["t_initial_guess"]),
      ("Galerkin operators + patches", lambda r: r["t_galerkin"]),
      ("smoothing", lambda r: r["t_smoothing"]), ("coarse solve", lambda r: r["t_coarse"]),
      ("solve, rest", lambda r: r["t_solve"] - r["t_galerkin"] - r["t_smoothing"] - r["t_coarse"]),
      ("output + process", lambda r: r["t_output"])]
md.append("From `time_sections_s` of summary.json (wall seconds: TimerOutput sections, and the three `Solve: ...` parts timed by the solver itself). 'setup' = "
          "mesh, DoFs and levels plus the solver's set-up (multigrid hierarchy, patches, "
          "sparsity patterns of the Galerkin products). The three "
          "`Solve: ...` sections lie inside `Solve`; 'solve, rest' is `Solve` minus them (CG "
          "steps, line search, restriction/prolongation, monitor). There is no output section "
          "in summary.json: **'output + process' = the process wall time measured by the script "
          "minus the sum of the top-level sections**, i.e. writing CSV/JSON plus process start "
          f"and exit (≈ {META['wall_s']:.2f} s for a process that does nothing). Default solver.\n")
fig, axes = plt.subplots(1, 3, figsize=(16, 4.5))
for ax, s in zip(axes, ["square", "mms", "cube3d"]):
    rs = series(s, DEFAULT)
    if not rs:
        continue
    body = []
    bottom = np.zeros(len(rs))
    for name, fn in PH:
        v = np.array([max(fn(r), 0.0) / r["wall_s"] for r in rs])
        ax.bar([str(r["level"]) for r in rs], v, bottom=bottom, label=name)
        bottom += v
    for k, r in enumerate(rs):
        ax.text(k, 1.01, f"{r['wall_s']:.1f}s", ha="center", fontsize=7)
    ax.set_ylim(0, 1.1)
    ax.set_xlabel("level")
    ax.set_ylabel("fraction of wall time")
    ax.set_title(f"{s}, default solver", fontsize=9)
    for r in rs:
        body.append([r["level"], int(r["dofs"])] + [fmt(fn(r), ".3f") for _, fn in PH]
                    + [fmt(r["wall_s"], ".2f")])
    md.append(f"### {s}\n")
    md.append(table(["level", "DoFs"] + [n for n, _ in PH] + ["wall"], body))
axes[-1].legend(fontsize=7, loc="center left", bbox_to_anchor=(1.0, 0.5))
fig.tight_layout()
fig.savefig(os.path.join(FIG, "wp_phases.png"), dpi=90)
plt.close(fig)
md.append("![phases](figures/wp_phases.png)\n")

# ----------------------------------------------------------------- effects
md.append("## Cost of each effect\n")
md.append("The same geometry with and without an effect. Square: contact on the bottom side "
          "(scene) or none (`Contact boundary ids` empty, the bottom side traction free); "
          "body force none (scene), declared zero (`0; 0`) or `0; -0.01`. Manufactured solution: "
          "its body force (scene) or none (`Data/Body force` empty; a different problem, "
          "timed only). Default solver, seconds.\n")
EFF = [("square", DEFAULT, "contact, no body force (scene)"),
       ("square", "mg-W-b-bf0", "contact, body force 0; 0"),
       ("square", "mg-W-b-bf", "contact, body force 0; -0.01"),
       ("square", "mg-W-b-nocontact", "no contact, no body force"),
       ("square", "mg-W-b-nocontact-bf", "no contact, body force 0; -0.01"),
       ("mms", DEFAULT, "mms: body force (scene)"),
       ("mms", "mg-W-b-nobf", "mms: no body force")]
levels = sorted({r["level"] for r in RUNS if r["group"] == "effects"})
body = []
for L in levels:
    for s, c, name in EFF:
        r = get(s, c, L)
        if not ok(r):
            body.append([L, name, r["status"] if r else "not run"] + [""] * 7)
            continue
        body.append([L, name, int(r["dofs"]), fmt(r["t_setup"], ".3f"), fmt(r["t_assembly"], ".3f"),
                     fmt(r["t_definiteness"], ".3f"), fmt(r["t_initial_guess"], ".3f"),
                     fmt(r["t_solve"], ".3f"), int(r["cycles"]), fmt(r["wall_s"], ".2f")])
md.append(table(["level", "case", "DoFs", "setup", "assembly", "definiteness", "initial guess",
                 "solve", "cycles", "wall"], body))
lines = []
for L in levels:
    a, z, b = get("square", DEFAULT, L), get("square", "mg-W-b-bf0", L), get("square", "mg-W-b-bf", L)
    m, mn = get("mms", DEFAULT, L), get("mms", "mg-W-b-nobf", L)
    nc = get("square", "mg-W-b-nocontact", L)
    if ok(a) and ok(b) and ok(z):
        lines.append(f"level {L}: square assembly without body force {a['t_assembly']:.3f} s, with "
                     f"a declared zero body force {z['t_assembly']:.3f} s, with 0; -0.01 "
                     f"{b['t_assembly']:.3f} s (undeclared/declared = "
                     f"{a['t_assembly'] / b['t_assembly']:.2f})")
    if ok(m) and ok(mn):
        lines.append(f"level {L}: mms assembly with its body force {m['t_assembly']:.3f} s, "
                     f"without {mn['t_assembly']:.3f} s (ratio {mn['t_assembly'] / m['t_assembly']:.2f})")
    if ok(a) and ok(nc):
        lines.append(f"level {L}: square without contact: setup {nc['t_setup']:.3f} s vs "
                     f"{a['t_setup']:.3f} s, definiteness check {nc['t_definiteness']:.3f} s vs "
                     f"{a['t_definiteness']:.3f} s, solve {nc['t_solve']:.3f} s "
                     f"({int(nc['cycles'])} cycles) vs {a['t_solve']:.3f} s "
                     f"({int(a['cycles'])} cycles), same DoFs {int(nc['dofs'])} = {int(a['dofs'])}")
if lines:
    md.append("Measured: " + "; ".join(lines) + ".\n")

# ----------------------------------------------------------------- surprises, skipped
md.append("## Not converged, stopped, failed and skipped cases\n")
nc = [r for r in RUNS if ok(r) and not converged(r)]
if nc:
    md.append("Finished without reaching the stopping criterion (measured figures): " +
              "; ".join(f"{r['case']}: {int(r['iterations'])} iterations, {r['wall_s']:.1f} s, "
                        f"error {fmt(error(r))}" for r in nc) + ".\n")
bad = [r for r in RUNS if r["status"] in ("skipped", "timeout", "error")]
md.append(table(["case", "status", "reason"], [[r["case"], r["status"], r["note"]] for r in bad])
          if bad else "None.\n")
md.append(f"\nReport generated {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}.\n")

with open(OUT, "w") as f:
    f.write("\n".join(md))
print(f"wrote {OUT}")
