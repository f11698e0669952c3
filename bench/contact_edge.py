#!/usr/bin/env python3
"""Where the computed contact zone ends, against Hertz's radius a, on a small
3D contact (a/R about 0.06): the half ball of prm/half_ball.prm (R = 0.5,
mu = lambda = 1) pushed 0.002 by its flat top, on uniform levels and on an
adaptive run. For each mesh it prints Hertz's a for the computed force, the
radius of the last contact vertex in contact (u.n = g: in_contact of
contact.csv), that of the next one outside, the mesh size there (their
difference), and two figures of the weak complementarity of the functional:
the largest pressure at a vertex outside the zone (relative to the peak) and
the largest remaining gap at a vertex inside Hertz's radius (relative to the
push). Writes doc/contact_edge_results.md.

    bench/contact_edge.py [--exe build/fosls-contact] [--levels 2 3 4]
                          [--adaptive-steps 4] [--output doc/contact_edge_results.md]
"""
import argparse
import csv
import math
import tempfile
from pathlib import Path

import common
from common import BIN, ROOT

PUSH = 0.002


def run(exe, settings, work):
    out = Path(work) / "out"
    summary = common.run("half_ball.prm", ["Output/Write vtu=false",
                                           "Data/Constants=push=%r, R=0.5" % PUSH] + settings,
                         out, exe)
    with open(out / "contact.csv") as f:
        rows = list(csv.DictReader(f))
    return summary, rows


def edge(summary, rows):
    a = summary["hertz"]["a"]
    peak = max(-float(r["sigma_nn"]) for r in rows)
    table = sorted(((math.hypot(float(r["x"]), float(r["y"])), r) for r in rows),
                   key=lambda t: t[0])
    r_in = max(q for q, r in table if r["in_contact"] == "1")
    r_out = min(q for q, r in table if r["in_contact"] == "0" and q > r_in)
    outside_pressure = max((-float(r["sigma_nn"]) for q, r in table if r["in_contact"] == "0"),
                           default=0.)
    inside_gap = max((float(r["remaining_gap"]) for q, r in table if q < a), default=0.)
    return {"dofs": summary["dofs"], "a": a, "r_in": r_in, "r_out": r_out,
            "outside_pressure": outside_pressure / peak, "inside_gap": inside_gap / PUSH,
            "estimate": summary.get("relative_error_estimate", float("nan"))}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exe", default=BIN)
    parser.add_argument("--levels", type=int, nargs="+", default=[2, 3, 4])
    parser.add_argument("--adaptive-steps", type=int, default=4)
    parser.add_argument("--output", default=str(Path(ROOT) / "doc" / "contact_edge_results.md"))
    args = parser.parse_args()
    results = []
    for level in args.levels:
        with tempfile.TemporaryDirectory() as work:
            results.append(("uniform, level %d" % level,
                            edge(*run(args.exe, ["Geometry/Levels=%d" % level], work))))
            print(results[-1])
    if args.adaptive_steps > 0:
        with tempfile.TemporaryDirectory() as work:
            results.append(("adaptive, %d steps from level 2" % args.adaptive_steps,
                            edge(*run(args.exe, ["Geometry/Levels=2", "Adaptivity/Steps=%d"
                                                 % args.adaptive_steps], work))))
            print(results[-1])
    lines = ["# The contact zone's edge against Hertz's radius (3D, a/R about 0.06)", "",
             "Written by `bench/contact_edge.py`: the half ball of `prm/half_ball.prm` (R = "
             "0.5, mu = lambda = 1, graded toward the lowest point) pushed %g by its flat top. "
             "a: Hertz's radius for the computed force; r_in: the radius of the last contact "
             "vertex in contact (u.n = g, `in_contact`), r_out: of the next one; "
             "h = r_out - r_in, the mesh size at the edge; p_out: the largest contact "
             "pressure at a vertex not in contact over the peak pressure; gap_in: the largest "
             "remaining gap at a vertex inside Hertz's radius over the push; the relative "
             "error estimate sqrt(J)/|x|." % PUSH, "",
             "| mesh | DoFs | a | r_in / a | r_out / a | h / a | p_out | gap_in | estimate |",
             "|---|---|---|---|---|---|---|---|---|"]
    for label, e in results:
        lines.append("| %s | %d | %.4f | %.3f | %.3f | %.3f | %.3f | %.2e | %.3f |"
                     % (label, e["dofs"], e["a"], e["r_in"] / e["a"], e["r_out"] / e["a"],
                        (e["r_out"] - e["r_in"]) / e["a"], e["outside_pressure"],
                        e["inside_gap"], e["estimate"]))
    Path(args.output).write_text("\n".join(lines) + "\n")
    print("wrote", args.output)


if __name__ == "__main__":
    main()
