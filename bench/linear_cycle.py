#!/usr/bin/env python3
"""The Newton step's linear truncated cycle two ways, in a build of commit
2ec8097, the last with the parameter `Solver/Linear cycle`: the program's
own (`own`, MonotoneCycle with linear = true, the cycle the program keeps)
against deal.II's Multigrid run with the program's parts (`deal.II`,
LinearMultigrid with the patch smoother, the truncated prolongation, the
Galerkin operators and the exact coarse solve as its MGSmoother,
MGTransferBase, MGMatrixBase and MGCoarseGridBase). The default solver,
one process, one thread, the two alternated so that both see the same
spells of the machine:
- on the square (prm/square.prm, levels 6-8) and the half disc
  (prm/hertz.prm, Grading 1, levels 4-5): iterations, cycles, J and the
  solve time of the fastest of --runs runs (parallel.fastest()), and,
  since a single fast run can decide the fastest, the median over the
  runs of the ratio deal.II/own of two runs made one after the other;
- on the adaptive half disc of prm/hertz_small_contact.prm (every mesh's
  solve): the same, summed over the meshes.
doc/performance.md, section 7, has the table and why the program keeps
its own cycle.

    git worktree add ../linear-cycles 2ec8097
    (cd ../linear-cycles && scripts/setup.sh)
    bench/linear_cycle.py --bin ../linear-cycles/build/fosls-contact    # about 20 minutes
"""
import argparse
import os
import statistics

from common import RESULTS
from parallel import fastest, run

UNIFORM = [("square", "square.prm", {}, (6, 7, 8)),
           ("half disc", "hertz.prm", {"Geometry/Grading": "1"}, (4, 5))]
ADAPTIVE = ("adaptive half disc", "hertz_small_contact.prm")


def adaptive(variants, runs):
    """The whole adaptive run of ADAPTIVE with each variant, alternated:
    ((DoFs of the last mesh, best own, best deal.II, median ratio),
    where a best is (summary of the fastest run, iterations, cycles)."""
    label, scene = ADAPTIVE
    every = {name: [] for name in variants}
    for k in range(runs):
        names = list(variants)
        for name in names[k % 2:] + names[:k % 2]:
            binary, settings = variants[name]
            out = os.path.join(RESULTS, f"linear_cycle_adaptive_{name}_{k}")
            s = run(scene, settings, 1, 1, out, binary=binary)
            steps = s["adaptive_steps"]
            every[name].append((s, sum(t["iterations"] for t in steps),
                                sum(t["cycles"] for t in steps)))
            print(f"run {k + 1}/{runs} {label} {name}: solve {s['time_solve_s']:.2f} s, "
                  f"{every[name][-1][2]} cycles", flush=True)
    best = {name: min(every[name], key=lambda e: e[0]["time_solve_s"]) for name in variants}
    median = statistics.median(d[0]["time_solve_s"] / o[0]["time_solve_s"]
                               for o, d in zip(every["own"], every["deal.II"]))
    return best["own"][0]["dofs"], best["own"], best["deal.II"], median


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--bin", required=True, metavar="PATH",
                   help="a build of commit 2ec8097 (it has both linear cycles)")
    p.add_argument("--runs", type=int, default=10,
                   help="runs per variant and level (default 10)")
    p.add_argument("--adaptive-runs", type=int, default=4,
                   help="runs per variant of the adaptive scene (default 4)")
    a = p.parse_args()
    if a.runs < 1 or a.adaptive_runs < 1:
        p.error("--runs and --adaptive-runs must be positive")
    if not (os.path.isfile(a.bin) and os.access(a.bin, os.X_OK)):
        p.error(f"--bin {a.bin}: not an executable file")
    binary = os.path.abspath(a.bin)
    variants = {"own": (binary, {"Solver/Linear cycle": "own"}),
                "deal.II": (binary, {"Solver/Linear cycle": "deal.II"})}
    rows = []
    for label, scene, settings, levels in UNIFORM:
        every = {}
        best = fastest(variants, levels, a.runs, scene, settings, 1, 1, "linear_cycle", every)
        for level in levels:
            own, dealii = best[("own", level)][1], best[("deal.II", level)][1]
            median = statistics.median(d["time_solve_s"] / o["time_solve_s"] for (_, o), (_, d)
                                       in zip(every[("own", level)], every[("deal.II", level)]))
            rows.append((label, level, own["dofs"], (own, own["iterations"], own["cycles"]),
                         (dealii, dealii["iterations"], dealii["cycles"]), median))
    dofs, own, dealii, median = adaptive(variants, a.adaptive_runs)
    rows.append((ADAPTIVE[0], "adaptive", dofs, own, dealii, median))
    print()
    print(f"default solver, 1 process x 1 thread, the fastest of {a.runs} runs ({a.adaptive_runs} "
          "of the adaptive scene, summed over its meshes): iterations / cycles, J, the solve "
          "time, and the ratio deal.II/own of the solve time: of the fastest runs, and the "
          "median of the runs made one after the other")
    print()
    print("| scene | level | DoFs | own: it / cycles | deal.II: it / cycles | J own | J deal.II | "
          "own solve s | deal.II solve s | deal.II/own | median deal.II/own |")
    print("|" + "---|" * 11)
    for label, level, dofs, (own, own_it, own_cycles), (dealii, dealii_it, dealii_cycles), \
            median in rows:
        print(f"| {label} | {level} | {dofs} | {own_it} / {own_cycles} | "
              f"{dealii_it} / {dealii_cycles} | {own['functional']:.10e} | "
              f"{dealii['functional']:.10e} | {own['time_solve_s']:.3f} | "
              f"{dealii['time_solve_s']:.3f} | "
              f"{dealii['time_solve_s'] / own['time_solve_s']:.3f} | {median:.3f} |")


if __name__ == "__main__":
    main()
