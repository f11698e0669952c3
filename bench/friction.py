#!/usr/bin/env python3
"""Friction solved by the monotone multigrid (doc/method.md section 7.7)
against the active set method (the semismooth Newton method of frictional
contact), level by level:

- the square pressed and then moved sideways past its stick limit
  (tests/scenes/square.prm, Tresca, slip bound 0.001, the load path of
  tests/solver/friction: push = 0.01; shift = 0.002; shift = 0.02),
  levels 4 to --square-max-level;
- prm/sliding_block.prm (Coulomb, f = 0.5, five load steps), levels 3 to
  --block-max-level;
- prm/sliding_block_3d.prm (the block in 3D, pushed along (2, 1)), levels
  2 to --block3d-max-level, the multigrid alone (see SOLVERS_3D);
- prm/cattaneo_mindlin.prm (a rigid cylinder pressed into an incompressible
  half-plane, then pulled to Q = 0.5 f P and 0.8 f P), levels 6 to
  --cm-max-level, against Cattaneo and Mindlin's solution: the program's
  own comparison of each step (the screen's "Hertz" and "Cattaneo-Mindlin"
  lines); prm/cattaneo_mindlin_3d.prm, the same with a sphere in 3D,
  levels 2 to --cm3d-max-level (default 2; on 3 levels about eight times
  the DoFs), the multigrid alone, and prm/cattaneo_mindlin_3d_fine.prm (the
  same on a mesh graded to 1/64 at the contact point, four times as fine
  there), levels 2 to --cm3d-fine-max-level (default 2; 0 leaves it out).

For each run: the DoFs, the Tresca problems (one per step for Tresca, the
fixed point's for Coulomb), the Newton steps per Tresca problem (largest
and mean), the linear cycles of the steps' last Tresca problems, the
largest of the steps' residual reductions per linear cycle (the CG
solves of their Newton steps), the wall time of the whole run, the last step's stick vertices and its tangential force against the
law's (Tresca: s times the contact width; Coulomb: f times the normal
force); the active set method's run up to --reference-max-level (the
square) and --block-reference-max-level (the block), with the largest
difference of the steps' forces relative to the normal force. Prints the
tables and writes doc/friction_results.md (the runs' output under
bench/results/friction/).

    friction.py [--square-max-level L] [--block-max-level L] [--cm-max-level L]
                [--block3d-max-level L]
                [--reference-max-level L] [--block-reference-max-level L]
                [--cm-reference-max-level L] [--cm3d-max-level L]
                [--cm3d-fine-max-level L] [--bin PATH]
                [--set "SECTION/NAME=VALUE" ...]
"""
import argparse
import json
import os
import re
import time

import common
from common import BIN, RESULTS, ROOT

RES = os.path.join(RESULTS, "friction")
DOC = os.path.join(ROOT, "doc", "friction_results.md")
# --set: settings for every run (then the tables are printed, not written to
# DOC)
EXTRA_SETTINGS = []
SQUARE = os.path.join("..", "tests", "scenes", "square.prm")
SQUARE_SETTINGS = ["Data/Constants=push=0.01, shift=0", "Data/Dirichlet values=shift; -push",
                   "Data/Load steps=push=0.01; shift=0.002; shift=0.02",
                   "Friction/Law=Tresca", "Friction/Bound=0.001"]
SOLVERS = {"multigrid": "Solver/Type=monotone multigrid", "active set": "Solver/Type=active set"}
# (the active set method is built for the 2D bounds only, and projected
# Gauss-Seidel, 3D friction's reference in tests/solver/friction_3d_reference,
# stops at 200,000 sweeps short of the tolerance in each of the block's
# first Tresca problems on 2 levels, 609 DoFs: the 3D block has no
# reference here)
SOLVERS_3D = {"multigrid": "Solver/Type=monotone multigrid"}


def run(binary, scene, settings, name):
    """One run into bench/results/friction/@p name: its summary.json, the
    Newton steps of each solve (from the screen) and the wall time."""
    out = os.path.join(RES, name)
    cmd = common.command(scene, ["Output/Directory=" + out, "Output/Write vtu=false"]
                         + settings + EXTRA_SETTINGS, binary)
    start = time.time()
    p = common.launch(cmd, capture_output=True, text=True)
    wall = time.time() - start
    if p.returncode != 0:
        raise SystemExit("failed: %s\n%s" % (" ".join(cmd), p.stderr))
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    steps, current, continued = [], None, False
    for line in p.stdout.splitlines():
        # (the solver's name, then ": start  J = ..." and ": it  N  J = ...";
        # a Tresca problem the Coulomb fixed point solves on to
        # Solver/Tolerance is one problem in two runs)
        if "solved on to Solver/Tolerance" in line:
            continued = True
        elif re.search(r"^\s+[a-z -]+: start\s+J =", line):
            current = 0
            if not (continued and steps):
                steps.append(0)
            continued = False
        elif re.search(r"^\s+[a-z -]+: it\s+\d+\s+J =", line) and current is not None:
            steps[-1] += 1
    return {"summary": summary, "steps": steps, "wall": wall, "screen": p.stdout}


def law_ratio(summary, law):
    """The last step's tangential force over the law's: s times the contact
    width (Tresca, s = 0.001) or f times the normal force (Coulomb, f =
    0.5)."""
    last = (summary.get("load_steps") or [{}])[-1]
    limit = 0.001 * last.get("contact_width", 0) if law == "Tresca" \
        else 0.5 * last.get("normal_force", 0)
    return last.get("tangential_force", 0) / limit if limit else float("nan")


def force_difference(a, b):
    """The largest difference of the steps' normal and tangential forces,
    relative to the step's normal force."""
    worst = 0.
    for r, s in zip(a.get("load_steps") or [], b.get("load_steps") or []):
        for key in ("normal_force", "tangential_force"):
            worst = max(worst, abs(r[key] - s[key]) / r["normal_force"])
    return worst


def solver_runs(binary, scene, settings, level, reference_levels, tag, solvers=None):
    """The runs of @p scene on @p level levels by solver: the multigrid, and
    the reference (the active set method, or the second of @p solvers) up
    to @p reference_levels."""
    runs = {}
    for solver, setting in (solvers or SOLVERS).items():
        if solver != "multigrid" and level > reference_levels:
            continue
        runs[solver] = run(binary, scene, settings + ["Geometry/Levels=%d" % level, setting],
                           "%s_%d_%s" % (tag, level, solver.replace(" ", "_")))
    return runs


def section(binary, title, scene, settings, law, levels, reference_levels, tag, solvers=None):
    solvers = solvers or SOLVERS
    reference = ([name for name in solvers if name != "multigrid"] or [None])[0]
    rows = ["| level | DoFs | solver | Tresca problems | Newton steps per problem (max, mean) "
            "| cycles | linear rate (max) | rate per Newton step (max) | wall time [s] | last step: stick vertices, Q / law "
            "| forces vs. %s |" % (reference or "a reference (none)"),
            "|---|---|---|---|---|---|---|---|---|---|---|"]
    for level in levels:
        runs = solver_runs(binary, scene, settings, level, reference_levels, tag, solvers)
        for solver, r in runs.items():
            s, steps = r["summary"], r["steps"]
            last = (s.get("load_steps") or [{}])[-1]
            cycles = sum(row.get("cycles", 0) for row in s.get("load_steps") or [])
            rates = [row.get("linear_rate") for row in s.get("load_steps") or []]
            rate = "%.2g" % max(rates) if rates and None not in rates else ""
            # (NaN in a step without an iteration above the round-off floor)
            newton = [row.get("iteration_rate") for row in s.get("load_steps") or []]
            newton = [x for x in newton if x is not None and x == x]
            newton = "%.2g" % max(newton) if newton else ""
            difference = "%.1e" % force_difference(s, runs[reference]["summary"]) \
                if solver == "multigrid" and reference in runs else ""
            rows.append("| %d | %d | %s | %d | %d, %.1f | %s | %s | %s | %.2f | %d, %.4f | %s |" % (
                level, s["dofs"], solver, len(steps), max(steps), sum(steps) / len(steps),
                cycles if solver == "multigrid" else "", rate,
                newton if solver == "multigrid" else "", r["wall"],
                last.get("stick_vertices", -1), law_ratio(s, law), difference))
    text = "## %s\n\n" % title + "\n".join(rows) + "\n"
    print(text)
    return text


HERTZ = re.compile(r"pressure error \S+ \(relative l2 at the contact vertices\), (\S+) "
                   r"\(relative L2 on the contact boundary\)")
CATTANEO_MINDLIN = re.compile(
    r"Cattaneo-Mindlin \(f = \S+, Q = \S+, Q/\(f P\) = (\S+)\): stick (?:zone \|x\||disc r) "
    r"< c = (\S+) along Q\n\s+computed: (?:stick zone from (\S+) to (\S+) \((\S+) and (\S+) vertex "
    r"spacings from -c and c\)|no vertex sticks), tangential traction error (?:(\S+) of \|q\|, )?"
    r"(\S+) of \|f p\|")


CM_2D = {"scene": "cattaneo_mindlin.prm", "tag": "cattaneo_mindlin", "spacing": 0.5,
         "title": "## `prm/cattaneo_mindlin.prm`: Cattaneo-Mindlin, Coulomb (f = 0.3)\n\n"
                  "Pressed with P = 0.01 (Hertz's a = 0.080), then pulled to Q = 0.0015 and "
                  "0.0024. "}
CM_3D = {"scene": "cattaneo_mindlin_3d.prm", "tag": "cattaneo_mindlin_3d", "spacing": 0.0625,
         "title": "## `prm/cattaneo_mindlin_3d.prm`: Cattaneo-Mindlin in 3D, a sphere, Coulomb "
                  "(f = 0.3)\n\n"
                  "Pressed with P = 0.001365 (Hertz's a = 0.080), then pulled to Q = 0.5 f P and "
                  "0.8 f P; c = a (1 - Q/(f P))^(1/3), the stick disc's ends measured on the "
                  "contact vertices along Q through the contact point. "}
CM_3D_FINE = dict(CM_3D, scene="cattaneo_mindlin_3d_fine.prm", tag="cattaneo_mindlin_3d_fine",
                  spacing=0.015625,
                  title="## `prm/cattaneo_mindlin_3d_fine.prm`: the same on a mesh graded to "
                        "1/64 at the contact point\n\n" + CM_3D["title"].split("\n\n", 1)[1])


def cattaneo_mindlin_section(binary, levels, reference_levels, case=CM_2D):
    """@p case's scene (prm/cattaneo_mindlin.prm or prm/cattaneo_mindlin_3d.prm)
    level by level: the program's comparison of each pulled step with
    Cattaneo and Mindlin's solution, and the largest pressure error against
    Hertz's of the three steps. (case["spacing"]: the contact vertex spacing
    on one level)"""
    rows = ["| level | DoFs | vertex spacing | wall time [s] | Newton steps per problem (max) "
            "| pressure error (max) | Q/(f P) | c | stick zone | ends from -c, c [spacings] "
            "| traction error of q | forces vs. active set |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for level in levels:
        runs = solver_runs(binary, case["scene"], [], level, reference_levels, case["tag"],
                           SOLVERS if case is CM_2D else SOLVERS_3D)
        r = runs["multigrid"]
        pressure = max(float(m.group(1)) for m in HERTZ.finditer(r["screen"]))
        difference = "%.1e" % force_difference(r["summary"], runs["active set"]["summary"]) \
            if "active set" in runs else ""
        spacing = case["spacing"] / 2 ** (level - 1)
        for k, m in enumerate(m for m in CATTANEO_MINDLIN.finditer(r["screen"])
                              if float(m.group(1)) > 1e-6):
            ratio, c, lo, hi, e_lo, e_hi, of_q, _ = m.groups()
            head = "| %d | %d | %.5f | %.1f | %d | %.4f" % (
                level, r["summary"]["dofs"], spacing, r["wall"], max(r["steps"]), pressure) \
                if k == 0 else "| | | | | |"
            zone, ends = ("%s to %s" % (lo, hi), "%s, %s" % (e_lo, e_hi)) if lo is not None \
                else ("no vertex sticks", "")
            rows.append("%s | %s | %s | %s | %s | %s | %s |" % (
                head, ratio, c, zone, ends, of_q, difference if k == 0 else ""))
    text = (case["title"] + "The pressure error is the largest of the three steps (relative L2 on the contact "
            "boundary); the stick zone's ends lie midway between the outermost stick vertex and "
            "the next one; the traction error is the relative L2 error of the tangential "
            "traction against Cattaneo-Mindlin's q.\n\n" + "\n".join(rows) + "\n")
    print(text)
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--square-max-level", type=int, default=8)
    ap.add_argument("--block-max-level", type=int, default=8)
    ap.add_argument("--reference-max-level", type=int, default=6)
    ap.add_argument("--block-reference-max-level", type=int, default=5)
    ap.add_argument("--block3d-max-level", type=int, default=3)
    ap.add_argument("--cm-max-level", type=int, default=9)
    ap.add_argument("--cm-reference-max-level", type=int, default=6)
    ap.add_argument("--cm3d-max-level", type=int, default=2)
    ap.add_argument("--cm3d-fine-max-level", type=int, default=2)
    ap.add_argument("--bin", default=BIN)
    ap.add_argument("--set", action="append", default=[], metavar="SECTION/NAME=VALUE",
                    help="a setting for every run (e.g. \"Friction/Tresca accuracy=0.01\"); "
                         "the tables are then printed only")
    args = ap.parse_args()
    EXTRA_SETTINGS.extend(args.set)
    os.makedirs(RES, exist_ok=True)
    parts = [
        "# Friction: the monotone multigrid against the active set method\n",
        "Written by `bench/friction.py` (%s). Each run is a whole load path; `cycles` counts "
        "the linear cycles of the multigrid's Newton steps over the last Tresca problem of "
        "each step (`load_steps.csv`), the Newton steps are those of every Tresca problem "
        "(the iterations on the screen); the linear rate is the residual reduction per linear "
        "cycle of the CG solves of a step's Newton steps (`load_steps.csv`'s `linear_rate`, "
        "the geometric mean over their CG steps), the largest of the steps'; the rate per "
        "Newton step is the reduction of the corrections |dx|_A per Newton step over all "
        "Tresca problems of a step (`load_steps.csv`'s `iteration_rate`, the geometric mean "
        "over the Newton steps above the round-off floor), the largest of the steps'. The last column is the largest difference of the "
        "steps' normal and tangential forces from the active set method's, relative to the "
        "normal force. Wall times are of the whole run, on this machine's 2 cores.\n"
        % " ".join("--%s %s" % (k.replace("_", "-"), v) for k, v in vars(args).items()
                   if k not in ("bin", "set")),
        section(args.bin, "Square, Tresca (s = 0.001), pressed and moved past its stick limit",
                SQUARE, SQUARE_SETTINGS, "Tresca", range(4, args.square_max_level + 1),
                args.reference_max_level, "square"),
        section(args.bin, "`prm/sliding_block.prm`, Coulomb (f = 0.5), five load steps",
                "sliding_block.prm", [], "Coulomb", range(3, args.block_max_level + 1),
                args.block_reference_max_level, "block"),
        section(args.bin, "`prm/sliding_block_3d.prm`, 3D, Coulomb (f = 0.5), five load steps",
                "sliding_block_3d.prm", [], "Coulomb", range(2, args.block3d_max_level + 1),
                0, "block3d", SOLVERS_3D),
        cattaneo_mindlin_section(args.bin, range(6, args.cm_max_level + 1),
                                 args.cm_reference_max_level),
    ]
    if args.cm3d_max_level >= 2:
        parts.append(cattaneo_mindlin_section(args.bin, range(2, args.cm3d_max_level + 1), 0,
                                              CM_3D))
    if args.cm3d_fine_max_level >= 2:
        parts.append(cattaneo_mindlin_section(args.bin, range(2, args.cm3d_fine_max_level + 1),
                                              0, CM_3D_FINE))
    if args.set:
        print("\n".join(parts))
        return
    with open(DOC, "w") as f:
        f.write("\n".join(parts))
    print("wrote", DOC)


if __name__ == "__main__":
    main()
