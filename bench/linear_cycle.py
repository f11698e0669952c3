#!/usr/bin/env python3
"""The Newton step's linear truncated cycle, own (MonotoneCycle) against
deal.II's Multigrid with the program's parts (LinearMultigrid), in the
default solver: iterations, cycles, J and the time per cycle per DoF of
both and their ratio deal.II/own, on the square (prm/square.prm, levels 6-8)
and the half disc (prm/hertz.prm, Grading 1, levels 4-5). One process, one
thread, the fastest of --runs runs, the two alternated so that both see the
same spells of the machine (parallel.fastest()).

    bench/linear_cycle.py              # about 10 minutes on an idle core
    bench/linear_cycle.py --runs 5
"""
import argparse
import os
import sys

from common import BIN
from parallel import fastest

SCENES = [("square", "square.prm", {}, (6, 7, 8)),
          ("half disc", "hertz.prm", {"Geometry/Grading": "1"}, (4, 5))]
VARIANTS = {"own": (None, {"Solver/Linear cycle": "own"}),
            "deal.II": (None, {"Solver/Linear cycle": "deal.II"})}


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--runs", type=int, default=3, help="runs per variant and level (default 3)")
    a = p.parse_args()
    if a.runs < 1:
        p.error("--runs must be positive")
    if not os.path.exists(BIN):
        sys.exit("build/fosls-contact missing: build it first")
    rows = []
    for label, scene, settings, levels in SCENES:
        best = fastest(VARIANTS, levels, a.runs, scene, settings, 1, 1, "linear_cycle")
        for level in levels:
            own, dealii = best[("own", level)], best[("deal.II", level)]
            rows.append((label, level, own[1]["dofs"], own, dealii))
    print()
    print(f"default solver, 1 process x 1 thread, the fastest of {a.runs} runs: iterations / "
          "cycles, J, us per cycle per DoF (solve time / cycles / DoFs), the solve time, and "
          "the ratio deal.II/own of the solve time")
    print()
    print("| scene | level | DoFs | own: it / cycles | deal.II: it / cycles | J own | J deal.II | "
          "own us/cycle/DoF | deal.II us/cycle/DoF | own solve s | deal.II solve s | "
          "deal.II/own |")
    print("|" + "---|" * 12)
    for label, level, dofs, (own_t, own), (dealii_t, dealii) in rows:
        print(f"| {label} | {level} | {dofs} | {own['iterations']} / {own['cycles']} | "
              f"{dealii['iterations']} / {dealii['cycles']} | {own['functional']:.10e} | "
              f"{dealii['functional']:.10e} | {own_t:.3f} | {dealii_t:.3f} | "
              f"{own['time_solve_s']:.3f} | {dealii['time_solve_s']:.3f} | "
              f"{dealii['time_solve_s'] / own['time_solve_s']:.3f} |")


if __name__ == "__main__":
    main()
