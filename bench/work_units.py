#!/usr/bin/env python3
"""The solve in work units: what the monotone multigrid does to reach the
discretization accuracy, counted in sweeps over the finest level (Brandt's
work unit: a patch sweep over level l costs level_dofs[l] / level_dofs[finest]
of one over the finest level; summary.json's level_sweeps and work_units).

For the square (prm/square.prm, levels 6-10) and the cube (prm/cube3d.prm,
levels 4-6), each with the default solver and stop (discretization
accuracy) and three starts:
- coarse solution (the default): the exact level-1 solution, interpolated;
- nested iteration: every level solved in turn to its own discretization
  accuracy, from the coarser level's solution (full multigrid's order of
  work), its coarser levels' sweeps in work units too
  (work_units_initial_guess);
- full multigrid: nested iteration with the cheap Newton step, one Krylov
  step (one linear cycle) per Newton step, with F(1,1)-, V(1,1)- and
  F(1,0)-cycles (FULL_MULTIGRID).
Each against the default solver converged to Solver/Tolerance: the contact
force's relative difference and the stop's promise, sqrt(2 (J - J*)) over
Discretization fraction * sqrt(J*) (at most 1 where the stop was right).
Full multigrid also on the curved contacts of the tests (HARD_SCENES).

With --variants also the smoothing: W(3,3) (the default), W(1,1) and
V(1,1) on the square (level 9), the cube (level 6), the ball (prm/ball3d.prm)
and the half ball (prm/half_ball.prm), from the default start: work units,
solve time (the fastest of --runs) and how far J and the contact force move
from the default's.

It prints, per run, the finest level's iterations and cycles, the work units
of the finest level's solve and of the coarser levels, the time of the solve
and of the initial guess, and the contact force; and the targets of issue
"accuracy per second": at most 2 iterations on the finest level, at most 15
work units at the square's level 9. Writes doc/work_units_results.md unless
--no-doc. One process, --threads threads (the counts do not depend on them).

    bench/work_units.py
    bench/work_units.py --square-levels 6-8 --cube-levels 4-5 --no-doc
    bench/work_units.py --variants
"""
import argparse
import math
import os
import sys

import common

RES = os.path.join(common.RESULTS, "work_units")
DOC = os.path.join(common.ROOT, "doc", "work_units_results.md")
# nested iteration with one linear cycle per Newton step (doc/performance.md section 9)
FULL_MULTIGRID = {
    f"full multigrid, {cycle}(1,{post})": {"Solver/Initial guess": "nested iteration",
                                           "Solver/Cycle": cycle, "Solver/Pre smoothing": 1,
                                           "Solver/Post smoothing": post,
                                           "Solver/Krylov steps": 1}
    for cycle, post in (("F", 1), ("V", 1), ("F", 0))}
STARTS = ["coarse solution", "nested iteration"] + list(FULL_MULTIGRID)
FRACTION = 0.1  # Solver/Discretization fraction's default
# the curved contacts, each at its scene's levels
HARD_SCENES = [("half disc", "hertz.prm"), ("half cylinder", "half_cylinder.prm"),
               ("punch", "punch.prm"), ("half ball", "half_ball.prm"),
               ("ball", "ball3d.prm")]
TARGET_ITERATIONS = 2
TARGET_WORK_UNITS = 15.0
TARGET_LEVEL = 9


# (name, scene, settings) of --variants, and the cycles compared there
VARIANT_SCENES = [("square", "square.prm", {"Geometry/Levels": 9}),
                  ("cube", "cube3d.prm", {"Geometry/Levels": 6}),
                  ("ball", "ball3d.prm", {}),
                  ("half ball", "half_ball.prm", {})]
VARIANTS = [("W", 3, 3), ("W", 1, 1), ("V", 1, 1)]


def one_run(scene, level, start, threads, settings=None, tag=""):
    label = "".join(c if c.isalnum() else "_" for c in start)
    out = os.path.join(RES, f"{scene.split('.')[0]}_L{level}_{label}{tag}")
    base = {"Solver/Threads": threads, "Output/Write vtu": "false", "Output/Verbose": "false"}
    base.update(FULL_MULTIGRID.get(start, {"Solver/Initial guess": start}))
    if level is not None:
        base["Geometry/Levels"] = level
    s = common.run(scene, dict(base, **(settings or {})), out, common.BIN, 1, threads,
                   allow_not_converged=True)
    sections = s["time_sections_s"]
    return {"dofs": s["dofs"], "iterations": s["iterations"], "cycles": s["cycles"],
            "work": s["work_units"], "work_coarser": s.get("work_units_initial_guess", 0.0),
            "solve_s": sections["Solve"], "guess_s": sections.get("Initial guess", 0.0),
            "force": s["contact_force"][s["dimension"] - 1], "fine_sweeps": s["level_sweeps"][-1],
            "stop": s["stop_reason"], "converged": s["converged"],
            "linear": s.get("linear_steps"),
            "functional": s["functional"], "rate": s["rate_per_cycle"],
            "coarse_fraction": sections.get("Solve: coarse solve", 0.0) / sections["Solve"]}


def converged_run(scene, level, threads):
    """The default solver converged to Solver/Tolerance."""
    return one_run(scene, level, STARTS[0], threads,
                   {"Solver/Stopping criterion": "tolerance"}, "_converged")


def accuracy(r, ref):
    """(the force's relative difference, the stop's promise ratio) against @p ref."""
    promise = (math.sqrt(2 * max(r["functional"] - ref["functional"], 0.))
               / (FRACTION * math.sqrt(ref["functional"])))
    return abs(r["force"] - ref["force"]) / abs(ref["force"]), promise


def hard_scenes(threads):
    """Full multigrid on the curved contacts (markdown lines)."""
    lines = ["| scene | DoFs | start | stop | Newton steps | linear cycles | work units, total | "
             "contact force, relative to the converged | sqrt(2 (J - J*)) / (0.1 sqrt(J*)) |",
             "|" + "---|" * 9]
    for name, scene in HARD_SCENES:
        ref = converged_run(scene, None, threads)
        for start in FULL_MULTIGRID:
            r = one_run(scene, None, start, threads)
            force, promise = accuracy(r, ref)
            lines.append(f"| {name} | {r['dofs']:,} | {start} | {r['stop']} | {r['iterations']} | "
                         f"{r['linear']} | {r['work'] + r['work_coarser']:.1f} | {force:.1e} | "
                         f"{promise:.2f} |")
            print(lines[-1], flush=True)
    return lines


def variants(threads, runs):
    """The smoothing variants' table (markdown lines)."""
    lines = ["| scene | DoFs | cycle | iterations | cycles | rate per cycle | work units | "
             "solve s | J, relative to W(3,3)'s | contact force, relative to W(3,3)'s | "
             "contact force, relative to the converged |", "|" + "---|" * 11]
    for name, scene, settings in VARIANT_SCENES:
        # the converged answer: W(3,3) stopped at Solver/Tolerance (1e-8)
        converged = one_run(scene, settings.get("Geometry/Levels"), STARTS[0], threads,
                            dict(settings, **{"Solver/Stopping criterion": "tolerance"}),
                            "_converged")["force"]
        base = None
        for cycle, pre, post in VARIANTS:
            v = {"Solver/Cycle": cycle, "Solver/Pre smoothing": pre,
                 "Solver/Post smoothing": post}
            r = min((one_run(scene, settings.get("Geometry/Levels"), STARTS[0], threads,
                             dict(settings, **v), f"_{cycle}{pre}{post}")
                     for _ in range(runs)), key=lambda r: r["solve_s"])
            base = base or r
            lines.append(f"| {name} | {r['dofs']:,} | {cycle}({pre},{post}) | {r['iterations']} | "
                         f"{r['cycles']} | {r['rate']:.2f} | {r['work']:.1f} | "
                         f"{r['solve_s']:.2f} | "
                         f"{abs(r['functional'] - base['functional']) / base['functional']:.1e} | "
                         f"{abs(r['force'] - base['force']) / abs(base['force']):.1e} | "
                         f"{abs(r['force'] - converged) / abs(converged):.1e} |")
            print(lines[-1], flush=True)
    return lines


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--square-levels", type=common.levels, default=common.levels("6-10"))
    p.add_argument("--cube-levels", type=common.levels, default=common.levels("4-6"))
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--variants", action="store_true",
                   help="also W(1,1) and V(1,1) against the default W(3,3)")
    p.add_argument("--runs", type=int, default=2, help="runs per variant (the fastest counts)")
    p.add_argument("--no-doc", action="store_true", help="print the table only")
    a = p.parse_args()
    if not os.path.exists(common.BIN):
        sys.exit(f"{common.BIN} missing: build it (scripts/setup.sh) or set FOSLS_CONTACT_BIN")
    os.makedirs(RES, exist_ok=True)

    rows, runs = [], {}
    for name, scene, ls in [("square", "square.prm", a.square_levels),
                            ("cube", "cube3d.prm", a.cube_levels)]:
        for level in ls:
            ref = converged_run(scene, level, a.threads)
            for start in STARTS:
                r = one_run(scene, level, start, a.threads)
                runs[(name, level, start)] = r
                force, promise = accuracy(r, ref)
                rows.append(f"| {name} | {level} | {r['dofs']:,} | {start} | {r['iterations']} | "
                            f"{r['linear']} | {r['cycles']} | {r['fine_sweeps']} | "
                            f"{r['work']:.1f} | "
                            f"{r['work_coarser']:.1f} | {r['work'] + r['work_coarser']:.1f} | "
                            f"{r['guess_s']:.2f} | {r['solve_s']:.2f} | "
                            f"{r['solve_s'] / r['work'] * 1e3:.1f} | {r['force']:.10f} | "
                            f"{force:.1e} | {promise:.2f} |")
                print(rows[-1], flush=True)

    lines = ["| scene | level | DoFs | start | iterations | linear cycles | cycles | sweeps of "
             "the finest level | work units, finest level | work units, coarser levels' solves | "
             "work units, total | initial guess s | solve s | solve ms per work unit | "
             "contact force | force, relative to the converged | sqrt(2 (J - J*)) / (0.1 "
             "sqrt(J*)) |", "|" + "---|" * 17] + rows
    # the targets, from the runs made
    targets = ["| target | measured | |", "|---|---|---|"]
    worst = {}
    for (name, level, start), r in runs.items():
        worst[(name, start)] = max(worst.get((name, start), 0), r["iterations"])
    for (name, start), it in sorted(worst.items()):
        lv = [l for (n, l, s) in runs if n == name and s == start]
        targets.append(f"| at most {TARGET_ITERATIONS} iterations on the finest level, {name} "
                       f"(levels {min(lv)}-{max(lv)}), {start} | at most {it} | "
                       f"{'met' if it <= TARGET_ITERATIONS else 'missed'} |")
        cycles = max(r["linear"] or 0 for (n, l, s), r in runs.items()
                     if n == name and s == start)
        targets.append(f"| at most {TARGET_ITERATIONS} linear cycles on the finest level, "
                       f"{name} (levels {min(lv)}-{max(lv)}), {start} | at most {cycles} | "
                       f"{'met' if cycles <= TARGET_ITERATIONS else 'missed'} |")
    for start in STARTS:
        r = runs.get(("square", TARGET_LEVEL, start))  # noqa
        if r:
            total = r["work"] + r["work_coarser"]
            targets.append(f"| at most {TARGET_WORK_UNITS:g} work units, square level "
                           f"{TARGET_LEVEL}, {start} | {total:.1f} | "
                           f"{'met' if total <= TARGET_WORK_UNITS else 'missed'} |")
    hard = hard_scenes(a.threads)
    text = ("<!-- generated by bench/work_units.py: do not edit -->\n\n"
            "# The solve in work units\n\n"
            f"Generated by `bench/work_units.py`: one process, {a.threads} threads, the default "
            "solver (the truncated nonsmooth Newton multigrid, W-cycles with 3 pre- and 3 "
            "post-smoothing sweeps) stopped at discretization accuracy, from the coarse solution "
            "(the default) and by nested iteration; and full multigrid: nested iteration with "
            "one Krylov step per Newton step and F(1,1)-, V(1,1)- or F(1,0)-cycles (Solver/Cycle "
            "= F or V, Pre smoothing = 1, Post smoothing = 1 or 0, Krylov steps = 1). A work "
            "unit is one "
            "patch "
            "sweep over the finest level; a sweep over level l counts level_dofs[l] / "
            "level_dofs[finest] of one (the exact solves of the coarsest level a cycle reaches "
            "are not counted: their time is at most "
            f"{100 * max(r['coarse_fraction'] for r in runs.values()):.2f}% of the solve's in "
            "these runs). `iterations` and `cycles` "
            "are the finest level's; `coarser levels' solves` is the nested iteration's solves "
            "on levels 2 .. finest - 1 (zero for the coarse solution, whose level-1 solve is "
            "exact); `linear cycles` the Newton steps' CG steps, one linear cycle each, and "
            "`cycles` those plus one per Newton step for its projected smoothing. The last two "
            "columns compare with the default solver converged to Solver/Tolerance (1e-8): the "
            "contact force (its last component), and the stop's promise, the algebraic error "
            "sqrt(2 (J - J*)) over Discretization fraction (0.1) times sqrt(J*), at most 1 "
            "where the stop was right.\n\n" + "\n".join(lines) + "\n\n"
            "## Full multigrid on curved contacts\n\nThe scenes' own levels; `stop` is "
            "summary.json's stop_reason (`stalled`: the run ends as not converged).\n\n"
            + "\n".join(hard) + "\n\n## Targets\n\n" + "\n".join(targets) + "\n")
    if a.variants:
        text += ("\n## Fewer smoothing sweeps\n\nW(3,3) (the default), W(1,1) and V(1,1) "
                 "(Solver/Cycle, Pre smoothing, Post smoothing), the default start and stop; "
                 f"the solve time is the fastest of {a.runs} runs. The last three columns: how far "
                 "J and the contact force (its last component) stop from W(3,3)'s, and the "
                 "force from the converged one (W(3,3) with Solver/Stopping criterion = "
                 "tolerance).\n\n"
                 + "\n".join(variants(a.threads, a.runs)) + "\n")
    print("\n".join(targets))
    if not a.no_doc:
        with open(DOC, "w") as f:
            f.write(text)
        print(f"wrote {DOC}")


if __name__ == "__main__":
    main()
