#!/usr/bin/env python3
"""Adaptive runs on one, two and four MPI processes: the Hertz half disc
(prm/hertz_adaptive.prm) and the 3D ball (prm/ball3d_adaptive.prm) as
shipped, 1 process x 1 thread, 1 x 2, 2 x 1 and 4 x 1, each the fastest of
--runs runs (alternated). Prints and writes doc/adaptive_processes_results.md
(generated; doc/parallel.md explains it): the meshes and answers of the
configurations against each other, the wall time of the whole run and of
its phases, and the peak memory, all from the same runs; then the memory
per process against issue 62's target (the peak of the largest process
within fixed + 1.25/N (peak of one process - fixed), fixed = the resident
memory of one process after the set-up of the scene's uniform level 2) and
each structure of summary.json's `memory_mb` summed over the processes, so
that a structure every process holds whole shows as growing with N. Four
processes on this 2-core machine measure memory, not speed.

An adaptive mesh is held whole by every process
(Discretization::MeshDistribution::replicated): the cells and the work on
them are divided (a process assembles the cells that reach its rows), the
vectors are not (every DoF is a ghost of every process), so every ghost
exchange moves the whole vector. This measures what that costs.

    bench/adaptive_processes.py [--runs N]      # about 7 minutes with N = 2
"""
import argparse
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from common import RESULTS, ROOT  # noqa: E402
from parallel import label, relative, run  # noqa: E402

RES = os.path.join(RESULTS, "adaptive_processes")
OUT = os.path.join(ROOT, "doc", "adaptive_processes_results.md")
SCENES = [("Hertz half disc", "hertz_adaptive.prm"), ("3D ball", "ball3d_adaptive.prm")]
CONFIGURATIONS = [(1, 1), (1, 2), (2, 1), (4, 1)]
MEMORY_CONFIGURATIONS = [(1, 1), (2, 1), (4, 1)]
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


def fixed_memory(scene):
    """The program's fixed resident memory (libraries, start-up): that of one
    process after the set-up of the scene's uniform level 2, as
    bench/adaptive_memory.py measures it."""
    small = run(scene, {"Adaptivity/Steps": "0", "Geometry/Levels": "2"}, 1, 1,
                os.path.join(RES, f"{os.path.splitext(scene)[0]}_fixed"))
    return small["memory_by_phase"][0]["rss_mb"]


def memory_lines(best, fixed):
    """The per-process peak against the target, and summary.json's structures
    summed over the processes, for the configurations with one thread."""
    one = best[(1, 1)]["peak_rss_mb_per_process"]
    lines = ["Peak of the largest process against the target fixed + 1.25/N (peak of 1 x 1 "
             f"- fixed), fixed = {fixed:.0f} MB; structures per process: summary.json's "
             "`memory_mb` summed over the processes, over N; the rest: what the peak holds "
             "beyond the fixed memory and those structures (transient memory of the phases, "
             "data the structures do not count):", "",
             "| p x t | peak per process (MB) | target (MB) | met | beyond fixed, "
             "over 1 x 1's | structures per process (MB) | the rest beyond fixed (MB) |",
             "|---|---|---|---|---|---|---|"]
    for processes, threads in MEMORY_CONFIGURATIONS:
        s = best[(processes, threads)]
        peak = s["peak_rss_mb_per_process"]
        target = fixed + 1.25 / processes * (one - fixed)
        structures = sum(s["memory_mb"].values()) / processes
        lines.append(f"| {label(processes, threads)} | {peak:.0f} | {target:.0f} | "
                     f"{'yes' if peak <= target else 'no'} | "
                     f"{(peak - fixed) / (one - fixed):.2f} | {structures:.0f} | "
                     f"{peak - fixed - structures:.0f} |")
    # per process: fixed + R + P/N; R (held by every process) and P
    # (divided among them) from the peaks of 1 and of the most processes
    most = MEMORY_CONFIGURATIONS[-1][0]
    peak_most = best[(most, 1)]["peak_rss_mb_per_process"]
    divided = (one - peak_most) * most / (most - 1)
    every = one - fixed - divided
    lines += ["", f"Fitted to the peaks of 1 and {most} processes as fixed + R + P/N: "
              f"R = {every:.0f} MB held by every process, P = {divided:.0f} MB divided "
              f"among them; N = 1000 processes would each hold about {fixed + every:.0f} MB "
              "of this mesh.", "",
              "summary.json's structures (`memory_mb`), summed over the processes (MB):", "",
              "| structure | " + " | ".join(label(p, t) for p, t in MEMORY_CONFIGURATIONS)
              + f" | {label(most, 1)} / 1 x 1 |",
              "|---|" + "---|" * len(MEMORY_CONFIGURATIONS) + "---|"]
    sums = [best[key]["memory_mb"] for key in MEMORY_CONFIGURATIONS]
    for name in sums[0]:
        values = [m.get(name, 0.0) for m in sums]
        ratio = f"{values[-1] / values[0]:.2f}" if values[0] > 0 else ""
        lines.append(f"| {name} | " + " | ".join(f"{v:.1f}" for v in values) + f" | {ratio} |")
    totals = [sum(m.values()) for m in sums]
    lines.append("| all | " + " | ".join(f"{v:.1f}" for v in totals)
                 + f" | {totals[-1] / totals[0]:.2f} |")
    return lines


def same_meshes(a, b):
    """The same cells and DoFs at every step."""
    def meshes(s):
        return [(x["cells"], x["dofs"]) for x in s["adaptive_steps"]]
    return meshes(a) == meshes(b)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=2)
    args = parser.parse_args()
    lines = ["# Adaptive runs on one, two and four processes",
             "",
             "Generated by "
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
        fixed = fixed_memory(scene)
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
        lines += memory_lines(best, fixed)
        lines.append("")
    with open(OUT, "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
