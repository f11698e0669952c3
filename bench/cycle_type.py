#!/usr/bin/env python3
"""W-, V- and F-cycle in the default solver (the Newton step's CG
preconditioned by the linear truncated cycle): cycles, solve time and the
communication per cycle on 1 and 2 processes, on the square, the cube and
the half disc (where the multigrid is weakest, doc/method.md section 8). The
input of the 1,000-process estimate in doc/parallel.md. Runs one case at a
time (single runs: compare solve times that differ by more than the
machine's scatter, 10-50% between runs of one binary here) and writes
doc/cycle_type_results.md.

Second, the time per cycle per DoF of W and F on the square's levels 5 to 9
with 1 and 2 threads (the flatness of issue 3's item 9, doc/results.md f):
the fastest of FLAT_RUNS runs per case, W and F alternated, so that both
see the same spells of the machine, and each first in half of the runs: with
W always first, F's level 5 with 2 threads was 3-17% slower in all 3 runs
(0.545 against 0.500 us at best) although it visits the same levels as W;
with the order alternated, 8 runs each, F and W took 10.1 and 10.6 ms at
best (by hand).

    bench/cycle_type.py          # about 20 minutes on 2 cores
    bench/cycle_type.py --quick  # without the flatness part, about 5
"""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from parallel import ROOT, BIN, RES, run  # noqa: E402

OUT = os.path.join(ROOT, "doc", "cycle_type_results.md")
CASES = [("square, 9 levels", "square.prm", {"Geometry/Levels": "9"}),
         ("cube, 6 levels", "cube3d.prm", {"Geometry/Levels": "6"}),
         ("half disc, 5 levels", "hertz.prm", {"Geometry/Levels": "5"})]
CYCLES = ("W", "V", "F")
FLAT_LEVELS = (5, 6, 7, 8, 9)
FLAT_RUNS = 4


def flatness():
    """The time per cycle per DoF (solve time / cycles / DoFs) of W and F on
    the square, lambda = 1, tolerance 1e-8 (the settings of doc/results.md f),
    levels FLAT_LEVELS, 1 and 2 threads: the fastest of FLAT_RUNS runs."""
    best = {}
    for run_index in range(FLAT_RUNS):
        for level in FLAT_LEVELS:
            for threads in (1, 2):
                for cycle in ("W", "F") if (run_index + level) % 2 == 0 else ("F", "W"):
                    out = os.path.join(RES, f"flat_L{level}_t{threads}_{cycle}")
                    s = run("square.prm", {"Geometry/Levels": str(level), "Solver/Cycle": cycle,
                                           "Solver/Tolerance": "1e-8"}, 1, threads, out)
                    per_dof = s["time_solve_s"] / s["cycles"] / s["dofs"] * 1e6
                    key = (threads, cycle, level)
                    if key not in best or per_dof < best[key][0]:
                        best[key] = (per_dof, s["cycles"])
                    print(f"run {run_index + 1}/{FLAT_RUNS} level {level} {threads} thread(s) "
                          f"{cycle}: {per_dof:.3f} us per cycle per DoF, {s['cycles']} cycles",
                          flush=True)
    lines = ["## Time per cycle per DoF, W against F", "",
             f"The square (`square.prm`, lambda = 1, tolerance 1e-8), one process, the "
             f"fastest of {FLAT_RUNS} runs per case, W and F alternated (each first in half "
             "of the runs); µs per cycle per "
             "DoF (solve time / cycles / DoFs), cycles in parentheses. max/min over "
             f"levels {FLAT_LEVELS[0]}-{FLAT_LEVELS[-1]} is the flatness of issue 3's item "
             "9 (target at most 1.25).", "",
             "| threads | cycle | " + " | ".join(f"level {l}" for l in FLAT_LEVELS) +
             " | max/min |",
             "|" + "---|" * (len(FLAT_LEVELS) + 3)]
    for threads in (1, 2):
        for cycle in ("W", "F"):
            values = [best[(threads, cycle, l)] for l in FLAT_LEVELS]
            times = [v[0] for v in values]
            lines.append(f"| {threads} | {cycle} | " +
                         " | ".join(f"{t:.3f} ({c})" for t, c in values) +
                         f" | {max(times) / min(times):.2f} |")
    lines.append("")
    for line in lines:
        print(line, flush=True)
    return lines


def main():
    if not os.path.exists(BIN):
        sys.exit("build/fosls-contact missing: run scripts/setup.sh")
    rows = []
    for name, scene, settings in CASES:
        for processes in (1, 2):
            for cycle in CYCLES:
                out = os.path.join(RES, f"cycle_{scene[:-4]}_{cycle}_p{processes}")
                s = run(scene, dict(settings, **{"Solver/Cycle": cycle}), processes,
                        2 // processes, out)
                cycles = max(s["cycles"], 1)
                rows.append(f"| {name} | {processes} x {2 // processes} | {cycle} | {s['dofs']} | "
                            f"{s['iterations']} | {s['cycles']} | {s['rate_per_cycle']:.3f} | "
                            f"{s['time_solve_s']:.2f} | {s['solve_exchanges'] / cycles:.0f} | "
                            f"{s['solve_values_sent'] / cycles:.0f} | "
                            f"{s['contact_force'][-1]:.9e} |")
                print(rows[-1], flush=True)
    flat = [] if "--quick" in sys.argv else flatness()
    lines = ["# W-, V- and F-cycle: measured results", "",
             "<!-- generated by bench/cycle_type.py; do not edit by hand -->", "",
             f"Generated {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} on this "
             f"machine ({os.cpu_count()} cores), one case at a time; the default solver "
             "with `Solver/Cycle` = W (the default), V or F. 'p x t' = MPI processes x "
             "threads per process. Exchanges: point-to-point exchanges of the busiest "
             "process per cycle; values: doubles sent by all processes per cycle "
             "(zero on one process). doc/parallel.md uses these for its estimate.", "",
             "| case | p x t | cycle | DoFs | iterations | cycles | rate per cycle | "
             "solve s | exchanges per cycle | values per cycle | contact force (normal) |",
             "|" + "---|" * 11] + rows + [""] + flat
    with open(OUT, "w") as f:
        f.write("\n".join(lines))
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
