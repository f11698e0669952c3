#!/usr/bin/env python3
"""Regenerate doc/results.md and doc/figures/*.png from bench/results/
(runs.csv and the per-case output directories written by run_cases.py).
All numbers in the report come from those files; its prose is
bench/results_template.md, whose blocks (`@@ name`) the sections below
fill in and put together in order."""
import csv
import json
import math
import os
import re

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from common import RESULTS as RES, ROOT, load_template  # noqa: E402

FIG = os.path.join(ROOT, "doc", "figures")
OUT = os.path.join(ROOT, "doc", "results.md")
TEMPLATE = os.path.join(ROOT, "bench", "results_template.md")

NUM = ["level", "wall_s", "dofs", "levels", "iterations", "cycles",
       "rate_asymptotic", "rate_per_cycle", "functional", "force_x", "force_y",
       "kkt_residual", "max_violation", "energy_increases", "feasibility_dampings",
       "h_ratio_coarse", "time_setup_s", "time_solve_s", "peak_rss_mb",
       "error_u_h1", "error_sigma_hdiv", "grading", "active"]
LAMBDAS = ["1", "inf"]
# the configurations of paper experiment 1 (section d)
SQUARE_SOLVERS = [("plainV", "plain V(3,3)"), ("plainW", "plain W(3,3)"),
                  ("default", "default (Krylov 50, W(3,3))")]
DISC_SOLVER = {"plain": "plain", "plainzero": "plain, zero start", "default": "default"}


BLOCKS = load_template(TEMPLATE)


def fill(block, **values):
    return BLOCKS[block].substitute(**values)


def load_runs():
    rows = []
    with open(os.path.join(RES, "runs.csv")) as f:
        for r in csv.DictReader(f):
            for k in NUM:
                if r.get(k) not in (None, ""):
                    r[k] = float(r[k])
                else:
                    r[k] = None
            if r["level"] is not None:
                r["level"] = int(r["level"])
            rows.append(r)
    return rows


def read_csv(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def case_file(r, name):
    return os.path.join(RES, r["case"], name)


def g(v, fmt=".3g"):
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "–"
    return format(v, fmt)


def table(header, body):
    lines = ["| " + " | ".join(header) + " |",
             "|" + "|".join("---" for _ in header) + "|"]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in body]
    return "\n".join(lines)


def lam_text(lam):
    return "∞" if lam == "inf" else lam


RUNS = load_runs()


def pick(**kw):
    out = []
    for r in RUNS:
        if all(str(r.get(k)) == str(v) for k, v in kw.items()):
            out.append(r)
    return out


def one(**kw):
    c = pick(**kw)
    return c[-1] if c else None


def ok(r):
    return r is not None and r["status"] == "ok"


def true(value):
    return value in ("True", "true")


def status_text(r):
    if r is None:
        return "not run"
    if r["status"] != "ok":
        return f"{r['status']} ({r['note']})"
    return "ok"


def timing_runs():
    """How many runs the timed cases took the fastest of (bench/run_cases.py,
    TIMING_RUNS), from the notes of runs.csv."""
    counts = sorted({m.group(1) for r in RUNS
                     for m in [re.match(r"fastest of (\d+) runs", r.get("note") or "")] if m})
    return " or ".join(counts) or "?"


def head():
    return [fill("head", timing_runs=timing_runs())]


def solutions():
    parts = [fill("solutions")]
    for name in ["square", "hertz", "steel_cylinder", "ball3d"]:
        if os.path.exists(os.path.join(FIG, f"solution_{name}.png")):
            parts.append(fill("solution_figure", name=name))
    return parts


def forces():
    """a. The square's contact force per level."""
    body = []
    prev = {}
    prevd = {}
    for L in range(2, 10):
        line = [L]
        any_ok = False
        for lam in LAMBDAS:
            r = one(group="square", config="default", level=L, **{"lambda": lam})
            if ok(r):
                any_ok = True
                F = r["force_y"]
                d = F - prev[lam] if lam in prev else None
                q = (d / prevd[lam]) if (d is not None and prevd.get(lam)) else None
                line += [int(r["dofs"]) if lam == "1" else "", g(F, ".6e"), g(d, ".2e"),
                         g(q, ".2f")]
                prev[lam] = F
                if d is not None:
                    prevd[lam] = d
            else:
                line += ["", status_text(r), "", ""]
        if any_ok or L <= 8:
            body.append(line)
    parts = [fill("forces", table=table(
        ["level", "DoFs", "F_y (λ=1)", "Δ", "Δ/Δ_prev", "F_y (λ=∞)", "Δ", "Δ/Δ_prev"],
        [[b[0], b[1], b[2], b[3], b[4], b[6], b[7], b[8]] for b in body]))]
    fx = [abs(r["force_x"]) for r in pick(group="square", config="default") if ok(r)]
    if fx:
        parts.append(fill("forces_horizontal", largest=f"{max(fx):.1e}"))
    return parts


def manufactured_solution():
    """b. Errors against the manufactured solution and their orders."""
    body = []
    pe = None
    for L in range(2, 8):
        r = one(group="mms", level=L)
        if not ok(r):
            body.append([L, "", status_text(r), "", "", ""])
            continue
        eu, es = r["error_u_h1"], r["error_sigma_hdiv"]
        ou = math.log2(pe[0] / eu) if pe else None
        os_ = math.log2(pe[1] / es) if pe else None
        body.append([L, int(r["dofs"]), g(eu, ".4e"), g(ou, ".2f"), g(es, ".4e"),
                     g(os_, ".2f")])
        pe = (eu, es)
    return [fill("mms", table=table(["level", "DoFs", "‖u−u_h‖_H1", "order",
                                     "‖σ−σ_h‖_H(div)", "order"], body))]


def hertz():
    """c. The half disc against Hertz's formulas, with the pressure figure."""
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8))
    body = []
    for ax, lam in zip(axes, LAMBDAS):
        r = one(group="hertz", **{"lambda": lam})
        if not ok(r):
            body.append([lam, status_text(r)] + [""] * 8)
            continue
        mu = 1.0
        if lam == "inf":
            E, nu = 3 * mu, 0.5
        else:
            la = float(lam)
            E = mu * (3 * la + 2 * mu) / (la + mu)
            nu = la / (2 * (la + mu))
        Es = E / (1 - nu ** 2)
        R = 0.5
        F = abs(r["force_y"])
        a = math.sqrt(4 * F * R / (math.pi * Es))
        p0 = 2 * F / (math.pi * a)
        c = read_csv(case_file(r, "contact.csv"))
        c.sort(key=lambda z: z["x"])
        xs = [z["x"] for z in c]
        ps = [-z["sigma_nn"] for z in c]
        act = [z for z in c if z["in_contact"] > 0.5]
        half = max(abs(z["x"]) for z in act) if act else float("nan")
        # first inactive vertex beyond the active zone, on each side: the zone ends in between
        inact = [abs(z["x"]) for z in c if z["in_contact"] <= 0.5 and abs(z["x"]) > half]
        nxt = min(inact) if inact else float("nan")
        peak = max(ps)
        xpk = xs[ps.index(peak)]
        body.append([lam_text(lam), r["level"], g(r["grading"], ".3g"),
                     int(r["dofs"]), g(F, ".4e"), g(a, ".4f"),
                     f"{half:.4f} (next vertex {nxt:.4f})", g(p0, ".4f"), g(peak, ".4f"),
                     g(xpk, ".3f")])
        ax.plot(xs, ps, "o", ms=3, label="computed −σ_nn (contact vertices)")
        xf = [-a + 2 * a * i / 200 for i in range(201)]
        ax.plot(xf, [p0 * math.sqrt(max(0.0, 1 - x * x / (a * a))) for x in xf], "-",
                label="Hertz p(x)")
        ax.set_xlim(-2.5 * a, 2.5 * a)
        ax.set_xlabel("x")
        ax.set_ylabel("contact pressure")
        ax.set_title(f"λ = {lam_text(lam)}, level {r['level']}, "
                     f"grading {r['grading']:g}")
        ax.legend(fontsize=8, loc="upper right")
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(FIG, "hertz_pressure.png"), dpi=110)
    plt.close(fig)
    return [fill("hertz", table=table(["λ", "level", "grading", "DoFs", "F", "Hertz a",
                                       "computed half-width", "Hertz p0", "computed peak",
                                       "x at peak"], body))]


def steel_roller():
    """c3. The steel roller's own Hertz comparison."""
    parts = [fill("steel")]
    r = one(group="steel")
    if not ok(r):
        return parts + [status_text(r) + "\n"]
    with open(case_file(r, "summary.json")) as f:
        hz = json.load(f)["hertz"]
    return parts + [fill("steel_ran", table=table(
        ["DoFs", "F [N/mm]", "Hertz b [mm]", "last vertex in contact [mm]",
         "next vertex [mm]", "Hertz p0 [MPa]", "computed peak [MPa]",
         "pressure l2 error", "solve s"],
        [[int(r["dofs"]), g(hz["force"], ".5g"), g(hz["a"], ".4f"),
          g(hz["edge_inside"], ".4f"), g(hz["edge_outside"], ".4f"),
          g(hz["p0"], ".5g"), g(hz["peak"], ".5g"), g(hz["pressure_error"], ".3f"),
          g(r["time_solve_s"], ".1f")]]))]


def ball3d():
    """c2. The 3D block on the ball against Hertz's sphere."""
    body = []
    for L in [3, 4, 5]:
        r = one(group="ball3d", level=L)
        if not ok(r):
            body.append([L, status_text(r)] + [""] * 9)
            continue
        with open(case_file(r, "summary.json")) as f:
            F = json.load(f)["contact_force"][2]
        E, nu = 2.5, 0.25
        Es = E / (1 - nu ** 2)
        a = (3 * F * 2.0 / (4 * Es)) ** (1 / 3)
        p0 = 3 * F / (2 * math.pi * a * a)
        c = read_csv(case_file(r, "contact.csv"))
        rad = [(math.hypot(z["x"], z["y"]), z) for z in c]
        r_act = max((q for q, z in rad if z["in_contact"] > 0.5), default=float("nan"))
        r_in = min((q for q, z in rad if z["in_contact"] <= 0.5), default=float("nan"))
        peak = max(-z["sigma_nn"] for z in c)
        num = sum((-z["sigma_nn"] - p0 * math.sqrt(max(0.0, 1 - q * q / (a * a)))) ** 2
                  for q, z in rad)
        den = sum(p0 * p0 * max(0.0, 1 - q * q / (a * a)) for q, z in rad)
        body.append([L, int(r["dofs"]), int(r["iterations"]), g(r["time_solve_s"], ".1f"),
                     g(r["peak_rss_mb"] / 1024, ".2f"), g(F, ".4e"), g(a, ".4f"),
                     f"{r_act:.4f} – {r_in:.4f}", g(p0, ".4f"), g(peak, ".4f"),
                     g(math.sqrt(num / den), ".3f")])
    return [fill("ball3d", table=table(["level", "DoFs", "iterations", "solve s",
                                        "peak memory GB", "F", "Hertz a",
                                        "computed edge between", "Hertz p0", "computed peak",
                                        "pressure error"], body))]


def square_solver_table(cfg):
    body = []
    for L in range(2, 10):
        line = [L]
        for lam in LAMBDAS:
            r = one(group="square", config=cfg, level=L, **{"lambda": lam})
            if ok(r):
                if lam == "1":
                    line.append(int(r["dofs"]))
                conv = "yes" if true(r["converged"]) else "no"
                if true(r["stopped_at_round_off"]):
                    conv += " (round-off)"
                line += [int(r["iterations"]), int(r["cycles"]), g(r["rate_asymptotic"], ".3f"),
                         g(r["rate_per_cycle"], ".3f"), conv, g(r["time_solve_s"], ".1f")]
            else:
                if lam == "1":
                    line.append("")
                line += [status_text(r), "", "", "", "", ""]
        body.append(line)
    return table(["level", "DoFs", "it (λ=1)", "cycles", "rate_asym", "rate/cycle",
                  "converged", "solve s", "it (λ=∞)", "cycles", "rate_asym",
                  "rate/cycle", "converged", "solve s"], body)


def square_histories_figure():
    """The correction histories at the finest level run, per configuration."""
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.8), sharey=True)
    for ax, lam in zip(axes, LAMBDAS):
        for cfg, name in SQUARE_SOLVERS:
            rs = [r for r in pick(group="square", config=cfg, **{"lambda": lam}) if ok(r)]
            if not rs:
                continue
            r = max(rs, key=lambda z: z["level"])
            h = read_csv(case_file(r, "convergence.csv"))
            h = [z for z in h if z["iteration"] > 0 and z["correction"] > 0]
            ax.semilogy([z["iteration"] for z in h], [z["correction"] for z in h], "o-",
                        ms=3, label=f"{name}, level {r['level']}")
        ax.set_xlabel("iteration")
        ax.set_title(f"square, λ = {lam_text(lam)}")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    axes[0].set_ylabel("correction (energy norm)")
    fig.tight_layout()
    fig.savefig(os.path.join(FIG, "square_history.png"), dpi=110)
    plt.close(fig)


def round_off_floor():
    floor = []
    for r in pick(group="square"):
        if ok(r) and true(r["stopped_at_round_off"]):
            h = read_csv(case_file(r, "convergence.csv"))
            h = [z for z in h if z["iteration"] > 0]
            c0 = h[0]["correction"]
            cmin = min(z["correction"] for z in h)
            k = next(i for i, z in enumerate(h) if z["correction"] <= 3 * cmin)
            floor.append((r["case"], cmin / c0, len(h) - 1 - k, int(r["cycles"])))
    if not floor:
        return []
    return [fill("round_off_floor", count=len(floor), runs="; ".join(
        f"{c}: last correction {q:.1e} of the first ({cy} cycles)" for c, q, n, cy in floor))]


def plain_v_rates():
    """The plain V(3,3)'s rate against the projection and the weight."""
    def rate_range(lam):
        rates = [r["rate_per_cycle"] for r in pick(group="square", config="plainV",
                                                    **{"lambda": lam})
                 if ok(r) and r["level"] >= 6]
        return f"{min(rates):.2f}–{max(rates):.2f}" if rates else "(not run)"

    body = []
    for lam in LAMBDAS:
        line = [lam_text(lam)]
        for proj in "bc":
            for c_compl in ["0", "0.1", "0.2"]:
                r = one(case=f"rates_lam{lam}_{proj}_C{c_compl}")
                line.append(g(r["rate_per_cycle"], ".3f") if ok(r) else status_text(r))
        body.append(line)
    return [fill("plain_v_rates", rates_1=rate_range("1"), rates_inf=rate_range("inf"),
                 table=table(["λ", "b, C_compl 0", "b, 0.1", "b, 0.2", "c, 0", "c, 0.1",
                              "c, 0.2"], body))]


def experiment1():
    """d. The square on levels 2..9 with the plain cycles and the default."""
    parts = [fill("experiment1")]
    for cfg, name in SQUARE_SOLVERS:
        parts.append(fill("experiment1_solver", name=name, table=square_solver_table(cfg)))
    square_histories_figure()
    parts.append(fill("experiment1_histories"))
    return parts + round_off_floor() + plain_v_rates()


def gradings():
    path = os.path.join(RES, "gradings.csv")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def experiment2_tables(gr):
    """The meshes' table, the projections' table, and per projection
    [converged plain runs, their cycles, their energy increases]."""
    body = []
    for mi, z in enumerate(gr):
        rr = [r for r in pick(group="disc2") if r["case"].startswith(f"disc_m{mi}_")]
        meas = rr[0]["h_ratio_coarse"] if rr and ok(rr[0]) else None
        body.append([mi + 1, z["target"],
                     g(float(z["grading"]) if z["grading"] not in ("", "None") else None,
                       ".5f"), g(meas, ".4f")])
    meshes = table(["mesh", "target h_max/h_min", "Grading", "measured h_ratio_coarse"], body)
    body = []
    score = {p: [0, 0, 0] for p in "abcd"}
    for mi in range(len(gr)):
        for lam in LAMBDAS:
            for solver in ["plain", "plainzero", "default"]:
                line = [mi + 1, lam_text(lam), DISC_SOLVER[solver]]
                for p in "abcd":
                    r = one(case=f"disc_m{mi}_lam{lam}_{solver}_{p}")
                    if not ok(r):
                        line.append(status_text(r))
                        continue
                    conv = true(r["converged"])
                    h = read_csv(case_file(r, "convergence.csv"))
                    last = h[-1]["correction"] / max(h[1]["correction"], 1e-300) \
                        if len(h) > 1 else float("nan")
                    cell = f"{int(r['iterations'])}{'' if conv else '✗'} / " \
                           f"{r['rate_asymptotic']:.2f}"
                    if solver == "plainzero":
                        line.append(cell + f" / {last:.0e} / "
                                    f"{int(r['feasibility_dampings'] or 0)}")
                    elif solver == "plain":
                        line.append(cell + f" / {last:.0e}")
                        score[p][0] += conv
                        score[p][1] += r["cycles"] if conv else 0
                        score[p][2] += r["energy_increases"] or 0
                    else:
                        line.append(cell)
                body.append(line)
    return meshes, table(["mesh", "λ", "solver", "a", "b", "c", "d"], body), score


def disc_mesh_figure(gr, mi):
    fig, axes = plt.subplots(2, 3, figsize=(14, 7), sharey=True)
    for i, lam in enumerate(LAMBDAS):
        for j, solver in enumerate(["plain", "plainzero", "default"]):
            ax = axes[i][j]
            for p in "abcd":
                r = one(case=f"disc_m{mi}_lam{lam}_{solver}_{p}")
                if not ok(r):
                    continue
                h = read_csv(case_file(r, "convergence.csv"))
                h = [z for z in h if z["iteration"] > 0 and z["correction"] > 0]
                ax.semilogy([z["iteration"] for z in h], [z["correction"] for z in h],
                            ["-", "--", "-.", ":"]["abcd".index(p)], marker=".", ms=3,
                            label=f"projection {p}")
            ax.set_title(f"λ = {lam_text(lam)}, {DISC_SOLVER[solver]}")
            ax.grid(alpha=0.3, which="both")
            ax.legend(fontsize=8)
            if i == 1:
                ax.set_xlabel("iteration")
            if j == 0:
                ax.set_ylabel("correction")
    fig.suptitle(f"half disc, two levels, h_max/h_min ≈ {gr[mi]['target']}")
    fig.tight_layout()
    fig.savefig(os.path.join(FIG, f"disc_mesh{mi + 1}.png"), dpi=100)
    plt.close(fig)


def paper_fig3(gr):
    """The paper's Fig. 3: contact displacement and pressure on the three
    meshes."""
    fig, axes = plt.subplots(2, 2, figsize=(11, 7))
    for i, lam in enumerate(LAMBDAS):
        for mi in range(len(gr)):
            r = one(case=f"disc_m{mi}_lam{lam}_default_b")
            if not ok(r):
                continue
            c = read_csv(case_file(r, "contact.csv"))
            c.sort(key=lambda z: z["x"])
            label = f"h_max/h_min = {float(gr[mi]['target']):.4g}"
            style = ["-", "--", ":"][mi]
            axes[i][0].plot([z["x"] for z in c], [z["u_x"] for z in c], style,
                            color="tab:blue", label="u_x, " + label)
            axes[i][0].plot([z["x"] for z in c], [z["u_y"] for z in c], style,
                            color="tab:orange", label="u_y, " + label)
            axes[i][1].plot([z["x"] for z in c], [-z["sigma_nn"] for z in c], style,
                            marker=".", ms=3, label=label)
        axes[i][0].set_title(f"λ = {lam_text(lam)}: displacement on the contact boundary",
                             fontsize=9)
        axes[i][1].set_title(f"λ = {lam_text(lam)}: contact pressure −σ_nn", fontsize=9)
        for ax in axes[i]:
            ax.set_xlabel("x")
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7)
        axes[i][1].set_xlim(-0.2, 0.2)
    fig.tight_layout()
    fig.savefig(os.path.join(FIG, "paper_fig3.png"), dpi=100)
    plt.close(fig)
    return [fill("paper_fig3")]


def disc_histories(mi, lam, solver):
    """(run, history) of projections a-d that ran, the history being
    (iteration, correction, functional) of every iteration."""
    out = {}
    for p in "abcd":
        r = one(case=f"disc_m{mi}_lam{lam}_{solver}_{p}")
        if ok(r):
            out[p] = (r, [(z["iteration"], z["correction"], z["functional"]) for z in
                          read_csv(case_file(r, "convergence.csv"))])
    return out


def projections_observation(gr):
    """How far the projections' iteration histories differ."""
    same, total, differing = 0, 0, []
    same_zero, total_zero, damped_zero = 0, 0, {p: 0 for p in "abcd"}
    iterations_zero = {p: [] for p in "abcd"}
    for mi in range(len(gr)):
        for lam in LAMBDAS:
            runs = disc_histories(mi, lam, "plainzero")
            for p, (r, _) in runs.items():
                damped_zero[p] += int(r["feasibility_dampings"] or 0)
                iterations_zero[p].append(int(r["iterations"]))
            hs = [h for _, h in runs.values()]
            if len(hs) == 4:
                total_zero += 1
                same_zero += all(h == hs[0] for h in hs[1:])
    for mi in range(len(gr)):
        for lam in LAMBDAS:
            for solver in ["plain", "default"]:
                hs = [h for _, h in disc_histories(mi, lam, solver).values()]
                if len(hs) == 4:
                    total += 1
                    same += all(h == hs[0] for h in hs[1:])
                    if not all(h == hs[0] for h in hs[1:]):
                        odd = [p for p, h in zip("abcd", hs) if h != hs[0]]
                        differing.append(
                            f"mesh {mi + 1}, λ = {lam_text(lam)}, {solver}: {', '.join(odd)} "
                            f"{'differs' if len(odd) == 1 else 'differ'} from a")
    if not total:
        return []
    n_groups = min((len(v) for v in iterations_zero.values()), default=0)
    spread_zero = max((max(iterations_zero[p][k] for p in "abcd") -
                       min(iterations_zero[p][k] for p in "abcd") for k in range(n_groups)),
                      default=0)
    return [fill("projections_observation", same=same, total=total,
                 others=fill("projections_others", groups="; ".join(differing))
                 if differing else "",
                 differ_zero=total_zero - same_zero, total_zero=total_zero,
                 iterations_zero=", ".join(
                     f"{p}: {'/'.join(str(i) for i in iterations_zero[p])}" for p in "abcd"),
                 dampings_zero=", ".join(f"{p}: {damped_zero[p]}" for p in "abcd"),
                 spread_zero=spread_zero)]


def projections_recommendation(gr, score):
    ranked = sorted("abcd", key=lambda p: (-score[p][0], score[p][1]))
    best = ranked[0]
    tie = [p for p in "abcd" if score[p][:2] == score[best][:2]]

    def iterations(config):
        counts = [int(r["iterations"]) for r in pick(group="disc2", config=config) if ok(r)]
        return f"{min(counts)}–{max(counts)}"

    return [fill("projections_recommendation", cases=str(2 * len(gr)),
                 scores=", ".join(f"{p}: {score[p][0]} converged, {int(score[p][1])} "
                                  f"iterations, {int(score[p][2])} energy increases"
                                  for p in "abcd"),
                 ranking=fill("projections_ranked", best=best, rest=", ".join(ranked[1:]))
                 if len(tie) == 1 else fill("projections_tied", tied=", ".join(tie)),
                 default_iterations=iterations("default"),
                 plain_iterations=iterations("plain"))]


def experiment2():
    """e. The half disc on two levels with the projections a-d."""
    gr = gradings()
    meshes, projections, score = experiment2_tables(gr)
    parts = [fill("experiment2", meshes=meshes, table=projections)]
    for mi in range(len(gr)):
        disc_mesh_figure(gr, mi)
        parts.append(fill("experiment2_mesh", mesh=mi + 1))
    if gr:
        parts += paper_fig3(gr)
    parts += projections_observation(gr)
    if gr:
        parts += projections_recommendation(gr, score)
    return parts


def rate_per_cycle():
    rates = []
    body = []
    for L in range(4, 10):
        line = [L]
        for lam in LAMBDAS:
            r = one(group="square", config="default", level=L, **{"lambda": lam})
            if ok(r):
                rates.append((L, lam, r["rate_per_cycle"]))
                line.append(g(r["rate_per_cycle"], ".3f"))
            else:
                line.append(status_text(r))
        body.append(line)
    parts = [fill("performance_rates", table=table(["level", "λ = 1", "λ = ∞"], body))]
    if rates:
        mx = max(rates, key=lambda z: z[2])
        mn = min(rates, key=lambda z: z[2])
        parts.append(fill("performance_rate_target", largest=f"{mx[2]:.3f}", level=mx[0],
                          lam=mx[1], smallest=f"{mn[2]:.3f}",
                          verdict="met" if mx[2] <= 0.25 else "MISSED",
                          first=min(z[0] for z in rates), last=max(z[0] for z in rates)))
    return parts


def time_per_cycle_per_dof():
    """Time per cycle per DoF over the levels, its flatness, figure and
    where it goes."""
    body = []
    variants = [("1", "default"), ("inf", "default"), ("1", "default1t"), ("1", "default2p")]
    variant_text = {"default1t": ", 1 thread", "default2p": ", 2 processes"}
    tpd = {v: [] for v in variants}
    for L in range(5, 10):
        line = [L]
        for lam, config in variants:
            r = one(group="square", config=config, level=L, **{"lambda": lam})
            if ok(r):
                v = r["time_solve_s"] / r["cycles"] / r["dofs"]
                tpd[(lam, config)].append((L, v))
                line.append(g(v * 1e6, ".3f"))
            else:
                line.append(status_text(r))
        body.append(line)
    parts = [fill("performance_time_per_dof", timing_runs=timing_runs(), table=table(
        ["level", "λ = 1 [µs]", "λ = ∞ [µs]", "λ = 1, 1 thread [µs]",
         "λ = 1, 2 processes [µs]"], body))]
    for lam, config in variants:
        if tpd[(lam, config)]:
            vals = [v for _, v in tpd[(lam, config)]]
            ratio = max(vals) / min(vals)
            parts.append(fill("performance_flatness", lam=lam_text(lam),
                              variant=variant_text.get(config, ""), ratio=f"{ratio:.2f}",
                              first=tpd[(lam, config)][0][0], last=tpd[(lam, config)][-1][0],
                              verdict="met" if ratio <= 1.25 else "MISSED"))
    parts.append("")
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    for lam, config in variants:
        if tpd[(lam, config)]:
            ax.plot([L for L, _ in tpd[(lam, config)]], [v * 1e6 for _, v in tpd[(lam, config)]],
                    "o-", label=f"λ = {lam_text(lam)}{variant_text.get(config, '')}")
    ax.set_xlabel("level")
    ax.xaxis.get_major_locator().set_params(integer=True)  # (levels are whole numbers)
    ax.set_ylabel("µs per cycle per DoF")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(FIG, "time_per_cycle_dof.png"), dpi=110)
    plt.close(fig)
    body = []
    for L in range(5, 10):
        r = one(group="square", config="default", level=L, **{"lambda": "1"})
        if not ok(r):
            continue
        path = case_file(r, "summary.json")
        if not os.path.exists(path):
            continue
        with open(path) as f:
            t = json.load(f).get("time_sections_s", {})
        per = 1e6 / r["cycles"] / r["dofs"]
        sm = t.get("Solve: smoothing", 0.)
        ga = t.get("Solve: Galerkin operators and patch setup", 0.)
        co = t.get("Solve: coarse solve", 0.)
        body.append([L, int(r["dofs"]), int(r["cycles"]), g(sm * per, ".2f"),
                     g(ga * per, ".2f"), g(co * per, ".3f"),
                     g((r["time_solve_s"] - sm - ga - co) * per, ".2f"),
                     g(r["time_solve_s"] * per, ".2f"), g(t.get("Setup: solver", 0.), ".2f")])
    return parts + [fill("performance_time_split", table=table(
        ["level", "DoFs", "cycles", "smoothing", "Galerkin", "coarse solve", "other", "total",
         "solver set-up s (not per cycle)"], body))]


def against_active_set():
    """The default multigrid against the active set reference, levels 8 and 9."""
    body = []
    speed = None
    for L in [8, 9]:
        a = one(group="square", config="activeset", level=L, **{"lambda": "1"})
        m = one(group="square", config="default", level=L, **{"lambda": "1"})
        if a is None and m is None:
            continue
        row = [L, int(m["dofs"]) if ok(m) else ""]
        row += [g(m["time_solve_s"], ".2f") if ok(m) else status_text(m),
                g(m["wall_s"], ".2f") if ok(m) else "",
                g(a["time_solve_s"], ".2f") if ok(a) else status_text(a),
                g(a["wall_s"], ".2f") if ok(a) else ""]
        if ok(a) and ok(m):
            s1 = a["time_solve_s"] / m["time_solve_s"]
            s2 = a["wall_s"] / m["wall_s"]
            row += [g(s1, ".2f"), g(s2, ".2f"),
                    g(abs(a["force_y"] - m["force_y"]) / abs(a["force_y"]), ".1e")]
            speed = (L, s1, s2)
        else:
            row += ["", "", ""]
        body.append(row)
    parts = [fill("performance_reference", table=table(
        ["level", "DoFs", "MG solve s", "MG wall s", "active set solve s",
         "active set wall s", "speed-up (solve)", "speed-up (wall)",
         "rel. force difference"], body))]
    if speed:
        parts.append(fill("performance_speed_up", level=speed[0], solve=f"{speed[1]:.2f}",
                          wall=f"{speed[2]:.2f}",
                          verdict="met" if speed[1] >= 5 else "MISSED"))
    return parts


def skipped():
    runs = [r for r in RUNS if r["status"] != "ok"]
    listing = table(["case", "status", "reason"],
                    [[r["case"], r["status"], r["note"]] for r in runs]) if runs else "None."
    total = sum(r["wall_s"] or 0 for r in RUNS)
    return [fill("skipped", table=listing, minutes=f"{total / 60:.1f}")]


def main():
    os.makedirs(FIG, exist_ok=True)
    # section order of doc/results.md (c3 before c2)
    parts = (head() + solutions() + forces() + manufactured_solution() + hertz()
             + steel_roller() + ball3d() + experiment1() + experiment2() + rate_per_cycle()
             + time_per_cycle_per_dof() + against_active_set() + [fill("adaptive")]
             + skipped())
    with open(OUT, "w") as f:
        f.write("\n".join(parts))
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
