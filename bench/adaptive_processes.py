#!/usr/bin/env python3
"""Adaptive runs on one and on two MPI processes: the Hertz half disc
(prm/hertz_adaptive.prm) and the 3D ball (prm/ball3d_adaptive.prm) as
shipped, 1 process x 1 thread, 1 x 2 and 2 x 1, each the fastest of --runs
runs (alternated). Prints and writes doc/adaptive_processes_results.md
(generated; doc/parallel.md explains it): the meshes and answers of the
configurations against each other, the wall time of the whole run and of
its phases, and the peak memory, all from the same runs.

An adaptive mesh is held whole by every process
(Discretization::MeshDistribution::replicated): the cells and the work on
them are divided (a process assembles the cells that reach its rows), the
vectors are not (every DoF is a ghost of every process), so every ghost
exchange moves the whole vector. This measures what that costs.

    bench/adaptive_processes.py [--runs N]      # about 4 minutes with N = 2
"""
import argparse
import os
import sys
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from common import RESULTS, ROOT  # noqa: E402
from parallel import label, relative, run  # noqa: E402

RES = os.path.join(RESULTS, "adaptive_processes")
OUT = os.path.join(ROOT, "doc", "adaptive_processes_results.md")
SCENES = [("Hertz half disc", "hertz_adaptive.prm"), ("3D ball", "ball3d_adaptive.prm")]
CONFIGURATIONS = [(1, 1), (1, 2), (2, 1)]
PHASES = [("Assembly", "assembly"), ("Definiteness check", "definiteness check"),
          ("Setup: solver", "solver set-up"), ("Solve", "solve"),
          ("Refinement", "refinement")]


def fastest(scene, runs):
    """The fastest (by wall time) of @p runs runs of every configuration on
    prm/@p scene, run alternately so that all see the same spells of the
    machine."""
    best = {}
    for k in range(runs):
        for processes, threads in CONFIGURATIONS:
            name = f"{os.path.splitext(scene)[0]}_{processes}x{threads}_run{k}"
            s = run(scene, {}, processes, threads, os.path.join(RES, name))
            key = (processes, threads)
            if key not in best or s["wall_s"] < best[key]["wall_s"]:
                best[key] = s
            print(f"{scene} {label(processes, threads)} run {k}: {s['wall_s']:.2f} s, "
                  f"{s['peak_rss_mb']:.0f} MB", flush=True)
    return best


def same_meshes(a, b):
    """The same cells and DoFs at every step."""
    def meshes(s):
        return [(x["cells"], x["dofs"]) for x in s["adaptive_steps"]]
    return meshes(a) == meshes(b)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=2)
    args = parser.parse_args()
    lines = ["# Adaptive runs on one and two processes",
             "",
             f"Generated {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} by "
             "`bench/adaptive_processes.py` on this machine "
             f"({os.cpu_count()} cores), the fastest of {args.runs} alternated runs per "
             "configuration; 'p x t' = MPI processes x threads per process. Wall: the whole "
             "run (start-up, every adaptive step, output); the phases from the run's "
             "timer (summed over the steps); peak memory: resident, summed over the "
             "processes. Every process holds the whole adaptive mesh (doc/parallel.md, "
             "'Adaptive runs').",
             ""]
    for title, scene in SCENES:
        best = fastest(scene, args.runs)
        one = best[(1, 1)]
        steps = one["adaptive_steps"]
        lines += [f"## {title} (`prm/{scene}`)", "",
                  f"{len(steps) - 1} adaptive steps, {steps[-1]['cells']} cells and "
                  f"{steps[-1]['dofs']} DoFs on the last mesh.", "",
                  "| p x t | same meshes as 1 x 1 | force against 1 x 1 | wall (s) | "
                  + " | ".join(f"{name} (s)" for _, name in PHASES)
                  + " | wall / 1 x 1 | peak memory (MB) | memory / 1 x 1 |",
                  "|---|---|---|---|" + "---|" * len(PHASES) + "---|---|---|"]
        for key in CONFIGURATIONS:
            s = best[key]
            sections = s.get("time_sections_s", {})
            lines.append(
                f"| {label(*key)} | {'yes' if same_meshes(s, one) else 'no'} | "
                f"{relative(s, one):.1e} | {s['wall_s']:.2f} | "
                + " | ".join(f"{sections.get(section, 0.0):.2f}" for section, _ in PHASES)
                + f" | {s['wall_s'] / one['wall_s']:.2f} | {s['peak_rss_mb']:.0f} | "
                f"{s['peak_rss_mb'] / one['peak_rss_mb']:.2f} |")
        lines.append("")
    with open(OUT, "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
