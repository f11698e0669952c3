#!/usr/bin/env python3
"""MPI processes and threads: strong scaling (1 process x 1 thread, 1 x 2,
2 x 1 on the same problem), weak scaling (the problem doubled with the
processes), memory per DoF, the communication per cycle, and the 3D run of
more than a million DoFs on two processes. Runs one case at a time (the
machine has 2 cores) and writes doc/parallel_results.md (generated;
doc/parallel.md explains it).

    bench/parallel.py            # about 15 minutes on 2 cores, 12 GB peak
"""
import math
import os
import sys

import common
from common import BIN, RESULTS, ROOT

RES = os.path.join(RESULTS, "parallel")
OUT = os.path.join(ROOT, "doc", "parallel_results.md")

# (name, scene, settings); every case is run as 1 process x 1 thread,
# 1 process x 2 threads and 2 processes x 1 thread
STRONG = [
    ("square, 9 levels", "square.prm", {"Geometry/Levels": "9"}),
    ("cube, 6 levels", "cube3d.prm", {"Geometry/Levels": "6"}),
    ("3D Hertz ball, 5 levels", "ball3d.prm", {"Geometry/Levels": "5"}),
]
CONFIGURATIONS = [(1, 1), (1, 2), (2, 1)]
# weak scaling: the domain (and the coarse mesh) doubled in x for 2 processes
WEAK = [
    ("square, 8 levels", "square.prm", {"Geometry/Levels": "8"},
     {"Geometry/Box upper corner": "2, 1", "Geometry/Box subdivisions": "2, 1"}),
    ("cube, 5 levels", "cube3d.prm", {"Geometry/Levels": "5"},
     {"Geometry/Box upper corner": "2, 1, 1", "Geometry/Box subdivisions": "2, 1, 1"}),
]
MILLION = ("cube 3x3x3 coarse cells, 5 levels", "cube3d.prm",
           {"Geometry/Levels": "5", "Geometry/Box subdivisions": "3, 3, 3"})
PHASES = [("Assembly", "assembly"), ("Setup: solver", "solver set-up"),
          ("Solve: smoothing", "smoothing"),
          ("Solve: Galerkin operators and patch setup", "Galerkin + patch set-up"),
          ("Solve: coarse solve", "coarse solve"),
          ("Solve", "solve")]


def run(scene, settings, processes, threads, out, binary=None):
    """One run of `binary` (default: build/fosls-contact) on prm/`scene` with
    the `settings` ("Subsection/Name": value), without vtu files and screen
    output; its summary.json, with the wall time of the whole run as
    "wall_s"."""
    return common.run(scene, ["Output/Write vtu=false", "Output/Verbose=false",
                              f"Solver/Threads={threads}"]
                      + [f"{k}={v}" for k, v in settings.items()],
                      out, binary, processes, threads)


def fastest(variants, levels, runs, scene, settings, processes, threads, tag, every=None):
    """The time per cycle per DoF (solve time / cycles / DoFs of summary.json,
    the measure of doc/results.md f) of every variant on every level of
    prm/`scene`: the fastest of `runs` runs. `variants` maps a name to
    (binary or None for build/fosls-contact, its own settings), in addition
    to `settings` and Geometry/Levels. The variants run alternately, each
    first in turn, so that all of them see the same spells of the machine
    (single runs of one binary scatter by 10-65% here, doc/performance.md
    section 1). Returns {(name, level): (us per cycle per DoF, summary of
    that run)}; prints every run, and appends it to every[(name, level)]
    if `every` is a dict."""
    names = list(variants)
    best = {}
    for k in range(runs):
        for level in levels:
            shift = (k + level) % len(names)
            for name in names[shift:] + names[:shift]:
                binary, own = variants[name]
                out = os.path.join(RES, f"{tag}_{name}_L{level}_{processes}x{threads}")
                s = run(scene, dict(settings, **own, **{"Geometry/Levels": str(level)}),
                        processes, threads, out, binary=binary)
                per_dof = s["time_solve_s"] / max(s["cycles"], 1) / s["dofs"] * 1e6
                if every is not None:
                    every.setdefault((name, level), []).append((per_dof, s))
                if (name, level) not in best or per_dof < best[(name, level)][0]:
                    best[(name, level)] = (per_dof, s)
                print(f"run {k + 1}/{runs} level {level} {label(processes, threads)} {name}: "
                      f"{per_dof:.3f} us per cycle per DoF, {s['cycles']} cycles", flush=True)
    return best


def label(processes, threads):
    return f"{processes} x {threads}"


def relative(a, b):
    fa, fb = a["contact_force"], b["contact_force"]
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(fa, fb))) / \
        math.sqrt(sum(y * y for y in fb))


def main():
    if not os.path.exists(BIN):
        sys.exit("build/fosls-contact missing: run scripts/setup.sh")
    os.makedirs(RES, exist_ok=True)
    results = []

    def record(name, scene, settings, processes, threads):
        out = os.path.join(RES, f"{len(results):02d}_p{processes}_t{threads}")
        s = run(scene, settings, processes, threads, out)
        s.update(name=name, processes=processes, threads=threads)
        results.append(s)
        print(f"{name}, {label(processes, threads)}: {s['dofs']} DoFs, "
              f"{s['iterations']} iterations, {s['cycles']} cycles, solve "
              f"{s['time_solve_s']:.2f} s, wall {s['wall_s']:.1f} s, peak "
              f"{s['peak_rss_mb'] / 1024:.2f} GB", flush=True)
        return s

    strong = {}
    for name, scene, settings in STRONG:
        for p, t in CONFIGURATIONS:
            strong[(name, p, t)] = record(name, scene, settings, p, t)
    weak = {}
    for name, scene, settings, doubled in WEAK:
        weak[(name, 1)] = record(name + ", 1 x 1 domain", scene, settings, 1, 1)
        weak[(name, 2)] = record(name + ", 2 x 1 domain", scene,
                                 dict(settings, **doubled), 2, 1)
    million = record(MILLION[0], MILLION[1], MILLION[2], 2, 1)

    lines = ["# Processes and threads: measured results", "",
             "<!-- generated by bench/parallel.py: do not edit -->", "",
             "Generated by `bench/parallel.py` on this "
             f"machine ({os.cpu_count()} cores), one case at a time. 'p x t' = MPI "
             "processes x threads per process. Times in seconds (TimerOutput sections and the solver's own `Solve: ...` parts "
             "of `summary.json`, those of the first process); peak memory is the sum "
             "over the processes.", ""]

    lines += ["## Strong scaling: the same problem on 1 x 1, 1 x 2 and 2 x 1", "",
              "| case | DoFs | p x t | iterations | cycles | " +
              " | ".join(l for _, l in PHASES) +
              " | speed-up of the solve vs 1 x 1 | wall | |F - F(1 x 1)| / |F| |",
              "|" + "---|" * (8 + len(PHASES))]
    for name, _, _ in STRONG:
        base = strong[(name, 1, 1)]
        for p, t in CONFIGURATIONS:
            s = strong[(name, p, t)]
            cells = [f"{s['time_sections_s'].get(k, 0):.2f}" for k, _ in PHASES]
            lines.append(f"| {name} | {s['dofs']} | {label(p, t)} | {s['iterations']} | "
                         f"{s['cycles']} | " + " | ".join(cells) +
                         f" | {base['time_solve_s'] / s['time_solve_s']:.2f} | "
                         f"{s['wall_s']:.1f} | {relative(s, base):.1e} |")
    lines.append("")

    lines += ["## Weak scaling: twice the DoFs on twice the processes", "",
              "The domain (and its coarse mesh) doubled in x for 2 processes, the "
              "mesh size the same; efficiency = time per cycle of 1 process / time "
              "per cycle of 2 processes (1 is perfect).", "",
              "| case | p x t | DoFs | DoFs per process | iterations | cycles | solve s | "
              "solve s per cycle | efficiency per cycle | wall s |",
              "|---|---|---|---|---|---|---|---|---|---|"]
    for name, _, _, _ in WEAK:
        a = weak[(name, 1)]
        for p in (1, 2):
            s = weak[(name, p)]
            per_cycle = s["time_solve_s"] / s["cycles"]
            eff = (a["time_solve_s"] / a["cycles"]) / per_cycle
            lines.append(f"| {s['name']} | {label(p, 1)} | {s['dofs']} | {s['dofs'] // p} | "
                         f"{s['iterations']} | {s['cycles']} | {s['time_solve_s']:.2f} | "
                         f"{per_cycle:.3f} | {eff:.2f} | {s['wall_s']:.1f} |")
    lines.append("")

    lines += ["## Memory per DoF and communication per cycle", "",
              "Exchanges: point-to-point exchanges of the busiest process during the "
              "solve (ghost updates, ghost parts to their owners, imported matrix "
              "entries, Galerkin parts); values: doubles sent by all processes; both "
              "per multigrid cycle (summary.json `solve_exchanges`, "
              "`solve_values_sent`, `cycles`).", "",
              "| case | p x t | DoFs | iterations | cycles | solve s | wall s | peak GB "
              "(all) | peak GB per process | KB per DoF | exchanges per cycle | "
              "values per cycle | ghost DoFs on the finest level | contact force (normal) |",
              "|" + "---|" * 14]
    for s in results:
        cycles = max(s["cycles"], 1)
        lines.append(
            f"| {s['name']} | {label(s['processes'], s['threads'])} | {s['dofs']} | "
            f"{s['iterations']} | {s['cycles']} | {s['time_solve_s']:.1f} | "
            f"{s['wall_s']:.1f} | {s['peak_rss_mb'] / 1024:.2f} | "
            f"{s['peak_rss_mb_per_process'] / 1024:.2f} | "
            f"{s['peak_rss_mb'] * 1024 / s['dofs']:.1f} | "
            f"{s['solve_exchanges'] / cycles:.0f} | {s['solve_values_sent'] / cycles:.0f} | "
            f"{s['ghost_dofs_per_level'][-1]} | {s['contact_force'][-1]:.6e} |")
    lines += ["", f"The million-DoF run: {million['dofs']} DoFs on 2 processes, "
              f"{million['iterations']} iterations ({million['cycles']} cycles), solve "
              f"{million['time_solve_s']:.1f} s, wall {million['wall_s']:.1f} s, peak "
              f"{million['peak_rss_mb'] / 1024:.2f} GB "
              f"({million['peak_rss_mb_per_process'] / 1024:.2f} GB per process).", ""]
    with open(OUT, "w") as f:
        f.write("\n".join(lines))
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
