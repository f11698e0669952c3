#!/usr/bin/env python3
"""Write doc/work_precision.md and doc/figures/wp_*.png from the CSV of the
work-precision study (bench/work_precision.py). Every number in the report
is computed here from that CSV; its prose is
bench/work_precision_template.md, whose blocks (`@@ name`) the sections
below fill in and put together in order.

    make_work_precision_report.py [CSV]    (default doc/work_precision.csv)
"""
import csv
import math
import os
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from common import ROOT, load_template  # noqa: E402

FIG = os.path.join(ROOT, "doc", "figures")
OUT = os.path.join(ROOT, "doc", "work_precision.md")
BLOCKS = load_template(os.path.join(ROOT, "bench", "work_precision_template.md"))

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
ERRNAME = {"square": "|F_y − F_y(ref)| / |F_y(ref)|", "cube3d": "|F_z − F_z(ref)| / |F_z(ref)|",
           "mms": "‖u − u_h‖_H1", "hertz": "rel. L2 error of the contact pressure vs Hertz"}
# the scenes whose error is the contact force against the finest converged
# default-solver run
FORCE_SCENES = ["square", "cube3d"]
# the tolerances of the sweep besides the default's 1e-8
SWEEP = ["1e-2", "1e-3", "1e-4", "1e-5", "1e-6", "1e-7", "1e-9", "1e-10"]


def fill(block, **values):
    return BLOCKS[block].substitute(**values)


# ----------------------------------------------------------------- formatting
def fmt(v, f=".3g"):
    if v is None or v == "" or (isinstance(v, float) and math.isnan(v)):
        return "–"
    return format(v, f)


def table(header, body):
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in body]
    return "\n".join(lines)


# ----------------------------------------------------------------- data
def num(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return v


def ok(r):
    return r is not None and r["status"] == "ok"


def converged(r):
    return ok(r) and str(r["converged"]).lower() == "true"


class Study:
    """The rows of the study's CSV: the runs and the meta row (the machine,
    the budget, the start-up time of a process that does nothing)."""

    def __init__(self, path):
        with open(path) as f:
            rows = [{k: num(v) for k, v in r.items()} for r in csv.DictReader(f)]
        self.meta = next((r for r in rows if r["case"] == "_meta"),
                         {"note": "", "wall_s": float("nan")})
        self.runs = [r for r in rows if r["case"] != "_meta"]
        for r in self.runs:
            r["level"] = int(r["level"])
        self.meta_kv = dict(kv.split("=", 1) for kv in self.meta["note"].split("; ")
                            if "=" in kv)
        self.ref = {s: self.reference(s) for s in FORCE_SCENES}
        # the cases that ran (not the skipped ones)
        self.ran = [r for r in self.runs if r["status"] in ("ok", "error", "timeout")]

    def about(self, key):
        return self.meta_kv.get(key, "?")

    def get(self, scene, config, level):
        for r in self.runs:
            if r["scene"] == scene and r["config"] == config and r["level"] == level:
                return r
        return None

    def series(self, scene, config):
        return sorted((r for r in self.runs
                       if r["scene"] == scene and r["config"] == config and ok(r)),
                      key=lambda r: r["level"])

    def reference(self, scene):
        """The finest converged default-solver run (the force reference)."""
        c = [r for r in self.series(scene, DEFAULT) if converged(r)]
        return c[-1] if c else None

    def error(self, r):
        """The scene's error measure of run r, or None."""
        if not ok(r):
            return None
        if r["scene"] in self.ref:
            ref = self.ref[r["scene"]]
            if ref is None or r["level"] >= ref["level"] or r.get("contact") == "no" or \
                    r.get("body_force") not in ("scene", "", None):
                return None
            return abs(r["force_y"] - ref["force_y"]) / abs(ref["force_y"])
        if r["scene"] == "mms":
            return r["error_u_h1"] if r.get("body_force") in ("scene", "") else None
        if r["scene"] == "hertz":
            return r["pressure_error_l2_rel"]
        return None


# ----------------------------------------------------------------- plots
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


def save(fig, name):
    fig.tight_layout()
    fig.savefig(os.path.join(FIG, name), dpi=90)
    plt.close(fig)


def scene_error_plot(st, name, xkey, xlabel, fit_from=0.0):
    """Per scene: its error (top) and sqrt(J) (bottom) against @p xkey."""
    fig, axes = plt.subplots(2, 4, figsize=(17, 8))
    for j, s in enumerate(SCENES):
        for i, measure in enumerate([st.error, lambda r: r["sqrt_functional"]]):
            ax = axes[i][j]
            for c in MAIN_CONFIGS:
                rs = [r for r in st.series(s, c) if measure(r) is not None]
                loglog(ax, [xkey(r) for r in rs], [measure(r) for r in rs], STYLE[c], LABEL[c],
                       fit_from)
            ax.set_title(TITLE[s], fontsize=9)
            ax.set_ylabel(ERRNAME[s] if i == 0 else "sqrt(J)", fontsize=8)
            ax.set_xlabel(xlabel, fontsize=8)
            ax.grid(alpha=0.3, which="both")
            legend(ax, 6)
    save(fig, name)


def per_scene_plot(st, name, ykey, ylabel):
    """Per scene: @p ykey against the DoFs."""
    fig, axes = plt.subplots(1, 4, figsize=(17, 4.2))
    for ax, s in zip(axes, SCENES):
        for c in MAIN_CONFIGS:
            rs = st.series(s, c)
            loglog(ax, [r["dofs"] for r in rs], [ykey(r) for r in rs], STYLE[c], LABEL[c])
        ax.set_title(TITLE[s], fontsize=9)
        ax.set_xlabel("DoFs")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3, which="both")
        legend(ax, 6)
    save(fig, name)


# ----------------------------------------------------------------- sections
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


def answer_rows(st, scene, targets, measure, name):
    """Per target: the cheapest run of @p scene with @p measure at most the
    target, or the best one measured."""
    body = []
    runs = [r for r in st.runs if r["scene"] == scene and ok(r) and measure(r) is not None]
    for t in targets:
        reached = [r for r in runs if measure(r) <= t]
        label = [TITLE[scene].split(" (")[0], f"{name} ≤ {t:g}"]
        if not reached:
            best = min(((measure(z), z) for z in runs), key=lambda v: v[0]) if runs else None
            body.append(label + ["not reached", "", "", "",
                                 f"best measured {fmt(best[0])} ({best[1]['case']})" if best
                                 else "", ""])
            continue
        r = min(reached, key=lambda r: r["wall_s"])
        d = st.get(scene, DEFAULT, r["level"])
        dt = (f"{d['wall_s']:.2f} s, error {fmt(measure(d))}" if ok(d) and
              measure(d) is not None else "–")
        body.append(label + [r["level"], int(r["dofs"]), solver_text(r), fmt(r["wall_s"], ".2f"),
                             fmt(measure(r)), dt])
    return body


def functional(r):
    """J of a run of the scene's own problem (None for the variants without
    contact or with another body force)."""
    if r.get("contact") == "no" or r.get("body_force") not in ("scene", ""):
        return None
    return r["functional"]


def functional_targets(st, scene):
    """The three decades of J above the least J measured on @p scene."""
    js = [r["functional"] for r in st.runs if r["scene"] == scene and ok(r)
          and r["functional"] > 0 and functional(r) is not None]
    if not js:
        return []
    k = math.ceil(math.log10(min(js)))
    return [10.0 ** (k + 2), 10.0 ** (k + 1), 10.0 ** k]


def answer(st):
    """The cheapest run for each target accuracy."""
    body = []
    for s in FORCE_SCENES:
        body += answer_rows(st, s, [1e-3, 1e-4, 1e-5], st.error, "force rel. error")
    body += answer_rows(st, "mms", [1e-1, 3e-2, 1e-2], st.error, "‖u−u_h‖_H1")
    body += answer_rows(st, "hertz", [0.2, 0.1, 0.05], st.error, "pressure rel. L2 error")
    for s in SCENES:
        body += answer_rows(st, s, functional_targets(st, s), functional, "J")
    references = ", ".join(fill("reference", scene=s, level=st.ref[s]["level"])
                           for s in st.ref if st.ref[s])
    return [fill("head", cpus=st.about("cpus"), startup=f"{st.meta['wall_s']:.1f}",
                 references=references,
                 table=table(["scene", "target", "level", "DoFs", "solver settings", "wall s",
                              "measured error", "default solver on that level"], body))]


def extrapolated(st, scene):
    """The distance of the reference of @p scene from the limit, by a
    geometric sequence of the force differences: (q, relative distance,
    level), or None."""
    s = [r for r in st.series(scene, DEFAULT) if converged(r)]
    if len(s) < 3:
        return None
    d1 = s[-1]["force_y"] - s[-2]["force_y"]
    d0 = s[-2]["force_y"] - s[-3]["force_y"]
    q = d1 / d0 if d0 else None
    if q is None or not 0 < q < 1:
        return None
    return q, abs(d1 * q / (1 - q)) / abs(s[-1]["force_y"]), s[-1]["level"]


def reference_accuracy(st):
    notes = []
    for s in st.ref:
        e = extrapolated(st, s)
        if e:
            notes.append(fill("reference_note", scene=s, q=f"{e[0]:.2f}", level=e[2],
                              error=f"{e[1]:.1e}"))
    return [fill("reference_accuracy", notes="; ".join(notes))] if notes else []


def setup(st):
    """How the study ran: the machine, the budget, the load, the solvers."""
    total = sum(r["wall_s"] for r in st.ran if isinstance(r["wall_s"], float))
    parts = [fill("setup", git=st.about("git"), cpus=st.about("cpus"), memory=st.about("mem_gb"),
                  cases=len(st.ran), minutes=f"{total / 60:.1f}",
                  budget=f"{float(st.meta_kv.get('budget_s', 'nan')) / 60:.0f}",
                  case_cap=st.about("case_cap_s"),
                  skipped=sum(1 for r in st.runs if r["status"] == "skipped"),
                  startup=f"{st.meta['wall_s']:.2f}")]
    loads = [r["load1"] for r in st.ran if isinstance(r.get("load1"), float)]
    binaries = sorted({r["binary_mtime"] for r in st.ran if r.get("binary_mtime")})
    if loads:
        parts.append(fill("load", mean=f"{np.mean(loads):.2f}", largest=f"{max(loads):.2f}",
                          cpus=st.about("cpus"),
                          busy=fill("load_busy") if max(loads) > 1.5 else "",
                          binary=fill("binary_rebuilt", times=", ".join(binaries))
                          if len(binaries) > 1 else fill("binary_same")))
    parts.append(fill("solver_names", pgs_sweeps=st.about("pgs_sweeps")))
    return parts + levels_3d(st)


def levels_3d(st):
    """How far the 3D levels go in memory (as far as fits in 20 GB)."""
    cube = [r for r in st.ran if r["scene"] == "cube3d" and isinstance(r.get("peak_rss_mb"), float)]
    if not cube:
        return []
    top = max(r["level"] for r in cube)
    at = {L: max(r["peak_rss_mb"] for r in cube if r["level"] == L)
          for L in {r["level"] for r in cube}}
    dofs = {r["level"]: r["dofs"] for r in cube}
    if top - 1 not in dofs:
        return []
    growth = dofs[top] / dofs[top - 1]
    per_dof = at[top] * 1024 / dofs[top]
    return [fill("levels_3d", level=top, dofs=int(dofs[top]), gb=f"{at[top] / 1024:.1f}",
                 kb_per_dof=f"{per_dof:.1f}", next=top + 1,
                 next_million=f"{dofs[top] * growth / 1e6:.1f}", growth=f"{growth:.1f}",
                 next_gb=f"{per_dof * dofs[top] * growth / 1024 ** 2:.0f}")]


def plots(st):
    """The work-precision plots and the fitted slopes."""
    scene_error_plot(st, "wp_error_vs_time.png", lambda r: r["wall_s"], "wall time [s]", 3.0)
    scene_error_plot(st, "wp_error_vs_dofs.png", lambda r: r["dofs"], "DoFs")
    per_scene_plot(st, "wp_time_vs_dofs.png", lambda r: r["wall_s"], "wall time [s]")
    per_scene_plot(st, "wp_solve_time_vs_dofs.png", lambda r: r["time_solve_s"],
                   "solve time [s]")
    per_scene_plot(st, "wp_memory_vs_dofs.png", lambda r: r["peak_rss_mb"], "peak RSS [MB]")
    body = []
    for s in SCENES:
        for c in MAIN_CONFIGS:
            rs = st.series(s, c)
            if len(rs) < 2:
                continue
            big = [r for r in rs if r["dofs"] >= 1e4] or rs
            e = [r for r in rs if st.error(r) is not None]
            body.append([s, c, f"{rs[0]['level']}–{rs[-1]['level']}",
                         fmt(fit_slope([r["dofs"] for r in e], [st.error(r) for r in e]), ".2f"),
                         fmt(fit_slope([r["dofs"] for r in rs],
                                       [r["sqrt_functional"] for r in rs]), ".2f"),
                         fmt(fit_slope([r["dofs"] for r in big],
                                       [r["time_solve_s"] for r in big]), ".2f"),
                         fmt(fit_slope([r["dofs"] for r in big],
                                       [r["peak_rss_mb"] for r in big]), ".2f"),
                         fmt(rs[-1]["wall_s"], ".1f"), fmt(rs[-1]["peak_rss_mb"], ".0f")])
    smallest = min(r["peak_rss_mb"] for r in st.runs if ok(r))
    return [fill("plots", smallest_mb=f"{smallest:.0f}"),
            fill("slopes", table=table(["scene", "solver", "levels", "error slope",
                                        "sqrt(J) slope", "solve-time slope", "memory slope",
                                        "finest wall s", "finest MB"], body))]


def levels(st):
    """Per scene and level: the default solver, its discretization stop,
    the active set and projected Gauss-Seidel."""
    parts = [fill("levels")]
    for s in SCENES:
        body = []
        for L in sorted({r["level"] for r in st.runs if r["scene"] == s}):
            dofs = next((r["dofs"] for r in st.runs if r["scene"] == s and r["level"] == L
                         and ok(r)), None)
            line = [L, int(dofs) if dofs else "–"]
            for c in [DEFAULT, DISC, "as", "pgs"]:
                r = st.get(s, c, L)
                if r is None:
                    line.append("")
                elif not ok(r):
                    line.append(f"{r['status']}")
                else:
                    cycles = "" if c in ("as", "pgs") else f" / {int(r['cycles'])} cyc"
                    failed = "" if converged(r) else " ✗"
                    line.append(f"{r['wall_s']:.2f} s / {int(r['iterations'])} it{cycles}"
                                f"{failed} / {fmt(st.error(r))} / J {fmt(r['functional'])}")
            body.append(line)
        parts.append(fill("levels_scene", title=TITLE[s], error_name=ERRNAME[s],
                          table=table(["level", "DoFs", DEFAULT, DISC, "as", "pgs"], body)))
    return parts


def settings(st):
    """Every solver setting on the small levels, against the active set."""
    parts = [fill("settings")]
    for s in SCENES:
        matrix = [r for r in st.runs if r["scene"] == s and r["group"] == "matrix"]
        configs = sorted({r["config"] for r in matrix})
        configs = [c for c in MAIN_CONFIGS if c in configs] + \
            [c for c in configs if c not in MAIN_CONFIGS]
        if not configs:
            continue
        matrix_levels = sorted({r["level"] for r in matrix})
        body = []
        for c in configs:
            line = [c]
            deviations = []
            for L in matrix_levels:
                r, a = st.get(s, c, L), st.get(s, "as", L)
                if not ok(r):
                    line.append(r["status"] if r else "")
                    continue
                k = int(r["iterations"]) if c in ("as", "pgs") else int(r["cycles"])
                line.append(f"{r['wall_s']:.2f} / {k}{'' if converged(r) else ' ✗'} / "
                            f"{fmt(st.error(r))}")
                if ok(a):
                    key = "force_y" if s in st.ref else "functional"
                    if a[key]:
                        deviations.append(abs(r[key] - a[key]) / abs(a[key]))
            line.append(fmt(max(deviations), ".1e") if deviations else "–")
            body.append(line)
        parts.append(fill("settings_scene", title=TITLE[s], table=table(
            ["setting"] + [f"level {L}" for L in matrix_levels] + ["max rel. diff. to as"],
            body)))
    return parts + projections(st)


def projections(st):
    """Whether the projections a-d differ in cycles and time."""
    same, groups, spread = 0, 0, []
    for s in SCENES:
        for L in range(3, 10):
            for cycle in "VW":
                for stop in ("", "-disc"):
                    rs = [st.get(s, f"mg-{cycle}-{p}{stop}", L) for p in "abcd"]
                    if all(ok(r) for r in rs):
                        groups += 1
                        same += len({int(r["cycles"]) for r in rs}) == 1
                        t = [r["time_solve_s"] for r in rs]
                        spread.append(max(t) / min(t) if min(t) > 0 else 1.0)
    if not groups:
        return []
    return [fill("projections", same=same, groups=groups, largest=f"{max(spread):.2f}",
                 median=f"{float(np.median(spread)):.2f}")]


def tolerance_sweep(st):
    """The default solver from tolerance 1e-2 to 1e-10 against the
    discretization error."""
    parts = [fill("tolerance")]
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.2))
    never = fill("never")
    for s, L in sorted({(r["scene"], r["level"]) for r in st.runs if r["group"] == "tolerance"}):
        rs = sorted([r for r in st.runs if r["scene"] == s and r["level"] == L and ok(r)
                     and r["config"].startswith(DEFAULT) and r["stopping"] == "tolerance"
                     and r["config"] in (DEFAULT,) + tuple(f"{DEFAULT}-tol{t}" for t in SWEEP)],
                    key=lambda r: -float(r["tolerance"]))
        if len(rs) < 2:
            continue
        tightest = rs[-1]
        fine = st.get(s, DEFAULT, L + 1) if converged(st.get(s, DEFAULT, L + 1)) else \
            st.get(s, "as", L + 1)
        base = st.get(s, DEFAULT, L)
        key = "force_y"
        disc = abs(fine[key] - base[key]) / abs(fine[key]) if ok(fine) and ok(base) else None
        disc_j = abs(fine["functional"] - base["functional"]) / base["functional"] \
            if ok(fine) and ok(base) else None
        digits = [-math.log10(float(r["tolerance"])) for r in rs]
        algebraic = [abs(r[key] - tightest[key]) / abs(tightest[key]) for r in rs]
        body = []
        for r, alg in zip(rs, algebraic):
            alg_j = abs(r["functional"] - tightest["functional"]) / tightest["functional"]
            body.append([r["tolerance"], int(r["iterations"]), int(r["cycles"]),
                         fmt(r["time_solve_s"], ".2f"), fmt(r["wall_s"], ".2f"),
                         "yes" if converged(r) else "no", fmt(alg, ".1e"), fmt(alg_j, ".1e")])
        cycles_per = float(np.polyfit(digits, [r["cycles"] for r in rs], 1)[0])
        seconds_per = float(np.polyfit(digits, [r["time_solve_s"] for r in rs], 1)[0])
        tenth = next((r for r, a in zip(rs, algebraic) if disc is not None and a <= 0.1 * disc),
                     None)
        equal = next((r for r, a in zip(rs, algebraic) if disc is not None and a <= disc), None)
        parts.append(fill(
            "tolerance_case", scene=s, level=L, dofs=int(rs[0]["dofs"]),
            table=table(["tolerance", "iterations", "cycles", "solve s", "wall s", "converged",
                         "force: algebraic rel. error", "J: algebraic rel. error"], body),
            next=L + 1, force_error=fmt(disc, ".1e"), j_error=fmt(disc_j, ".1e"),
            cycles_per_digit=f"{cycles_per:.2f}", seconds_per_digit=f"{seconds_per:.3f}",
            tenth_tolerance=tenth["tolerance"] if tenth else never,
            tenth_cycles=int(tenth["cycles"]) if tenth else "–",
            tenth_solve=fmt(tenth["time_solve_s"] if tenth else None, ".2f"),
            solve=fmt(base["time_solve_s"], ".2f"),
            equal_tolerance=equal["tolerance"] if equal else never))
        label = f"{s} L{L}"
        axes[0].plot(digits, [r["cycles"] for r in rs], "o-", label=label)
        axes[1].plot(digits, [r["time_solve_s"] for r in rs], "o-", label=label)
        axes[2].semilogy(digits[:-1], [max(a, 1e-17) for a in algebraic[:-1]], "o-",
                         label=f"{label} algebraic")
        if disc:
            axes[2].axhline(disc, ls="--", color=axes[2].lines[-1].get_color(),
                            label=f"{label} discretization")
    for ax, ylabel in zip(axes, ["cycles", "solve time [s]", "relative force error"]):
        ax.set_xlabel("digits = −log10(tolerance)")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3, which="both")
        legend(ax, 7)
    save(fig, "wp_tolerance.png")
    return parts + [fill("tolerance_figure")]


# the phases of a run: name, seconds (summary.json's time_sections_s)
PHASES = [("setup", lambda r: r["t_setup"]), ("assembly", lambda r: r["t_assembly"]),
          ("definiteness check", lambda r: r["t_definiteness"]),
          ("initial guess", lambda r: r["t_initial_guess"]),
          ("Galerkin operators + patches", lambda r: r["t_galerkin"]),
          ("smoothing", lambda r: r["t_smoothing"]), ("coarse solve", lambda r: r["t_coarse"]),
          ("solve, rest",
           lambda r: r["t_solve"] - r["t_galerkin"] - r["t_smoothing"] - r["t_coarse"]),
          ("output + process", lambda r: r["t_output"])]


def phases(st):
    """The default solver's time per phase and level."""
    parts = [fill("phases", startup=f"{st.meta['wall_s']:.2f}")]
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.5))
    for ax, s in zip(axes, ["square", "mms", "cube3d"]):
        rs = st.series(s, DEFAULT)
        if not rs:
            continue
        bottom = np.zeros(len(rs))
        for name, seconds in PHASES:
            v = np.array([max(seconds(r), 0.0) / r["wall_s"] for r in rs])
            ax.bar([str(r["level"]) for r in rs], v, bottom=bottom, label=name)
            bottom += v
        for k, r in enumerate(rs):
            ax.text(k, 1.01, f"{r['wall_s']:.1f}s", ha="center", fontsize=7)
        ax.set_ylim(0, 1.1)
        ax.set_xlabel("level")
        ax.set_ylabel("fraction of wall time")
        ax.set_title(f"{s}, default solver", fontsize=9)
        body = [[r["level"], int(r["dofs"])] + [fmt(seconds(r), ".3f") for _, seconds in PHASES]
                + [fmt(r["wall_s"], ".2f")] for r in rs]
        parts.append(fill("phases_scene", scene=s, table=table(
            ["level", "DoFs"] + [n for n, _ in PHASES] + ["wall"], body)))
    axes[-1].legend(fontsize=7, loc="center left", bbox_to_anchor=(1.0, 0.5))
    save(fig, "wp_phases.png")
    return parts + [fill("phases_figure")]


# the runs with and without an effect: scene, configuration, case
EFFECTS = [("square", DEFAULT, "contact, no body force (scene)"),
           ("square", "mg-W-b-bf0", "contact, body force 0; 0"),
           ("square", "mg-W-b-bf", "contact, body force 0; -0.01"),
           ("square", "mg-W-b-nocontact", "no contact, no body force"),
           ("square", "mg-W-b-nocontact-bf", "no contact, body force 0; -0.01"),
           ("mms", DEFAULT, "mms: body force (scene)"),
           ("mms", "mg-W-b-nobf", "mms: no body force")]


def effects(st):
    """The cost of contact and of a body force."""
    effect_levels = sorted({r["level"] for r in st.runs if r["group"] == "effects"})
    body = []
    for L in effect_levels:
        for s, c, name in EFFECTS:
            r = st.get(s, c, L)
            if not ok(r):
                body.append([L, name, r["status"] if r else "not run"] + [""] * 7)
                continue
            body.append([L, name, int(r["dofs"]), fmt(r["t_setup"], ".3f"),
                         fmt(r["t_assembly"], ".3f"), fmt(r["t_definiteness"], ".3f"),
                         fmt(r["t_initial_guess"], ".3f"), fmt(r["t_solve"], ".3f"),
                         int(r["cycles"]), fmt(r["wall_s"], ".2f")])
    parts = [fill("effects", table=table(["level", "case", "DoFs", "setup", "assembly",
                                          "definiteness", "initial guess", "solve", "cycles",
                                          "wall"], body))]
    findings = []
    for L in effect_levels:
        a, z, b = (st.get("square", c, L) for c in (DEFAULT, "mg-W-b-bf0", "mg-W-b-bf"))
        m, mn = st.get("mms", DEFAULT, L), st.get("mms", "mg-W-b-nobf", L)
        nc = st.get("square", "mg-W-b-nocontact", L)
        if ok(a) and ok(b) and ok(z):
            findings.append(fill("effect_body_force", level=L,
                                 undeclared=f"{a['t_assembly']:.3f}",
                                 zero=f"{z['t_assembly']:.3f}", declared=f"{b['t_assembly']:.3f}",
                                 ratio=f"{a['t_assembly'] / b['t_assembly']:.2f}"))
        if ok(m) and ok(mn):
            findings.append(fill("effect_manufactured", level=L,
                                 with_force=f"{m['t_assembly']:.3f}",
                                 without=f"{mn['t_assembly']:.3f}",
                                 ratio=f"{mn['t_assembly'] / m['t_assembly']:.2f}"))
        if ok(a) and ok(nc):
            findings.append(fill("effect_contact", level=L, setup=f"{nc['t_setup']:.3f}",
                                 setup_contact=f"{a['t_setup']:.3f}",
                                 definiteness=f"{nc['t_definiteness']:.3f}",
                                 definiteness_contact=f"{a['t_definiteness']:.3f}",
                                 solve=f"{nc['t_solve']:.3f}", cycles=int(nc["cycles"]),
                                 solve_contact=f"{a['t_solve']:.3f}",
                                 cycles_contact=int(a["cycles"]), dofs=int(nc["dofs"]),
                                 dofs_contact=int(a["dofs"])))
    if findings:
        parts.append(fill("effects_measured", findings="; ".join(findings)))
    return parts


def failures(st):
    """The runs that did not converge, stopped, failed or were skipped."""
    parts = [fill("failures")]
    stopped = [r for r in st.runs if ok(r) and not converged(r)]
    if stopped:
        parts.append(fill("not_converged", cases="; ".join(
            fill("not_converged_case", case=r["case"], iterations=int(r["iterations"]),
                 wall=f"{r['wall_s']:.1f}", error=fmt(st.error(r))) for r in stopped)))
    bad = [r for r in st.runs if r["status"] in ("skipped", "timeout", "error")]
    parts.append(fill("failures_table", table=table(["case", "status", "reason"],
                                                    [[r["case"], r["status"], r["note"]]
                                                     for r in bad]))
                 if bad else fill("none"))
    return parts


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "doc", "work_precision.csv")
    st = Study(path)
    os.makedirs(FIG, exist_ok=True)
    parts = (answer(st) + reference_accuracy(st) + setup(st) + plots(st) + levels(st)
             + settings(st) + tolerance_sweep(st) + phases(st) + effects(st) + failures(st))
    with open(OUT, "w") as f:
        f.write("\n".join(parts))
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
