#!/usr/bin/env python3
"""What a whole run costs: wall time, solve time, set-up time and peak memory
per DoF, for the square (prm/square.prm, levels 5-9) and the cube
(prm/cube3d.prm, levels 3-7, as far as the machine's memory allows), one
process with all its threads, the fastest of --runs runs, and the cube at
levels 5-7 and the square at levels 9-10 once more with the patch rows read
from the level matrices (Solver/Patch rows = matrix, this build only); with
--base-rev, the same for another revision of the program (built here), run
alternately with this build, and the ratios. Writes doc/scale_results.md
(generated; doc/performance.md explains it), copies its table of the
targets into doc/performance.md (between the markers there; not after a run
with --max-level), and prints it.

    bench/scale.py                                  # this build only
    bench/scale.py --base-rev 93af7be --runs 3      # against an earlier main
    bench/scale.py --copy-targets                   # only the copy, from
                                                    # doc/scale_results.md

Also: the square's contact force against its limit (extrapolated from
levels 7-9, whose differences shrink by a steady factor, doc/results.md a)
and the wall time of the first level within 1.5e-5 of it; and the memory of
the program's structures per DoF (summary.json's memory_mb) where the build
reports it.
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

from common import BIN, RESULTS, ROOT, launch
from parallel import run

RES = os.path.join(RESULTS, "scale")
OUT = os.path.join(ROOT, "doc", "scale_results.md")
PERFORMANCE = os.path.join(ROOT, "doc", "performance.md")
# the block of doc/performance.md that holds the copy of the targets' table
BEGIN = "<!-- the targets of bench/scale.py, copied from scale_results.md: do not edit -->"
END = "<!-- end of the targets of bench/scale.py -->"
# (name, scene, levels, growth per level, settings, also run by the base
# build); "cube, rows from the matrix" is the cube with the patch smoother's
# rows read from the level matrices (Solver/Patch rows = matrix), which
# trades sweep time for memory
MATRIX_ROWS = "cube, rows from the matrix"
SQUARE_MATRIX_ROWS = "square, rows from the matrix"
# the square stopped once the algebraic error is a tenth of the functional's
# estimate of the discretization error (Solver/Stopping criterion), what a
# user who wants the force to the mesh's accuracy runs
SQUARE_DISCRETIZATION = "square, discretization accuracy"
CASES = [("square", "square.prm", range(5, 10), 4.0, {}, True),
         ("cube", "cube3d.prm", range(3, 8), 8.0, {}, True),
         (MATRIX_ROWS, "cube3d.prm", range(5, 8), 8.0, {"Solver/Patch rows": "matrix"}, False),
         (SQUARE_MATRIX_ROWS, "square.prm", range(9, 11), 4.0,
          {"Solver/Patch rows": "matrix"}, False),
         (SQUARE_DISCRETIZATION, "square.prm", range(8, 10), 4.0,
          {"Solver/Stopping criterion": "discretization accuracy"}, False)]
TARGETS = {"wall_over_solve": 1.5,
           "bytes_per_dof": {"square": 1200, "cube": 2500, MATRIX_ROWS: 2500,
                             SQUARE_MATRIX_ROWS: 1200}}


def arguments():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--runs", type=int, default=3, help="runs per case and build (default 3)")
    p.add_argument("--base-rev", help="a git revision to build and compare with")
    p.add_argument("--threads", type=int, default=2, help="threads (default 2)")
    p.add_argument("--max-level", type=int, default=99,
                   help="skip levels above this (both scenes)")
    p.add_argument("--copy-targets", action="store_true",
                   help="only copy the targets' table of doc/scale_results.md into "
                        "doc/performance.md")
    return p.parse_args()


def available_mb():
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemAvailable:"):
                return int(line.split()[1]) / 1024.
    return float("inf")


def build_base(rev):
    """Build revision @p rev in bench/results/scale/base (a git worktree, with
    ccache if there is one); returns its binary."""
    src = os.path.join(RES, "base-src")
    if os.path.isdir(src):
        subprocess.run(["git", "-C", ROOT, "worktree", "remove", "--force", src],
                       capture_output=True)
        shutil.rmtree(src, ignore_errors=True)
    subprocess.run(["git", "-C", ROOT, "worktree", "add", "--detach", src, rev], check=True,
                   capture_output=True)
    build = os.path.join(src, "build")
    os.makedirs(build, exist_ok=True)
    cmake = ["cmake", "-DCMAKE_BUILD_TYPE=Release", ".."]
    if shutil.which("ccache"):
        cmake.insert(1, "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
    subprocess.run(cmake, cwd=build, check=True, capture_output=True)
    subprocess.run(["make", "-j2", "fosls-contact"], cwd=build, check=True, capture_output=True)
    return os.path.join(build, "fosls-contact")


def measure(binaries, scene, level, runs, threads, tag, settings):
    """{build: summary of its fastest run by wall time}, builds alternated."""
    names = list(binaries)
    best = {}
    for k in range(runs):
        shift = k % len(names)
        for name in names[shift:] + names[:shift]:
            slug = tag.replace(", ", "_").replace(" ", "_")
            # (a directory per run: the fastest run's files stay)
            out = os.path.join(RES, f"{slug}_{name}_L{level}_run{k + 1}")
            s = run(scene, dict(settings, **{"Geometry/Levels": str(level)}), 1, threads, out,
                    binary=binaries[name])
            if name not in best or s["wall_s"] < best[name]["wall_s"]:
                best[name] = s
            print(f"  run {k + 1}/{runs} {tag} level {level} {name}: wall {s['wall_s']:.2f} s, "
                  f"solve {s['time_solve_s']:.2f} s, peak {s['peak_rss_mb']:.0f} MB",
                  flush=True)
    return best


def bytes_per_dof(mb, summary):
    """@p mb megabytes per DoF of the run of @p summary, in bytes."""
    return mb * 1024 * 1024 / summary["dofs"]


def file_backed_mb(summary):
    """The file-backed resident memory after the last phase (MB; None where
    the build does not report it)."""
    phases = summary.get("memory_by_phase") or []
    return phases[-1].get("rss_file_mb") if phases else None


def finest(results, tag):
    """The summary of the finest level of @p tag that ran (None if none)."""
    ran = [level for (t, level), best in results.items() if t == tag and best]
    return (max(ran), results[(tag, max(ran))]["this"]) if ran else (None, None)


def square_force(results, tag="square"):
    """The square's contact force against its limit, extrapolated from levels
    7-9 of the default runs (whose differences shrink by a steady factor):
    the limit, that factor, the relative error of every level of @p tag and
    the first level within 1.5e-5 (None if none); None without levels 7-9."""
    def forces_of(t):
        return {level: results[(t, level)]["this"]["contact_force"][1]
                for level in range(5, 10) if results.get((t, level))}
    forces = forces_of("square")
    if not all(level in forces for level in (7, 8, 9)):
        return None
    q = (forces[9] - forces[8]) / (forces[8] - forces[7])
    limit = forces[9] + (forces[9] - forces[8]) * q / (1 - q)
    errors = {level: abs(f - limit) / abs(limit) for level, f in forces_of(tag).items()}
    within = [level for level in sorted(errors) if errors[level] <= 1.5e-5]
    return {"limit": limit, "ratio": q, "errors": errors,
            "within": within[0] if within else None}


def targets(results):
    """The performance targets on whole runs, each with its measured figure
    and whether it is met."""
    rows = []

    def row(target, measured, met):
        rows.append(f"| {target} | {measured} | {'met' if met else 'missed'} |")

    for tag, level in (("square", 9), ("cube", 6)):
        best = results.get((tag, level))
        if best:
            s = best["this"]
            ratio = s["wall_s"] / s["time_solve_s"]
            row(f"wall <= {TARGETS['wall_over_solve']} x solve, {tag} level {level}",
                f"{ratio:.2f} ({s['wall_s']:.2f} s / {s['time_solve_s']:.2f} s)",
                ratio <= TARGETS["wall_over_solve"])
    for tag in ("square", SQUARE_MATRIX_ROWS, "cube", MATRIX_ROWS):
        level, s = finest(results, tag)
        if s:
            per_dof = bytes_per_dof(s["peak_rss_mb"], s)
            limit = TARGETS["bytes_per_dof"][tag]
            row(f"peak memory <= {limit} bytes per DoF, {tag} (finest level measured)",
                f"{per_dof:.0f} (level {level})", per_dof <= limit)
    best = results.get(("cube", 7))
    row("the cube at level 7 in under 20 GB",
        f"{best['this']['peak_rss_mb'] / 1024:.1f} GB, {best['this']['dofs']} DoFs" if best
        else "not run", bool(best) and best["this"]["peak_rss_mb"] < 20 * 1024)
    for tag, stop in (("square", "default tolerance"),
                      (SQUARE_DISCRETIZATION, "stopped at discretization accuracy")):
        force = square_force(results, tag)
        if force:
            within = force["within"]
            wall = results[(tag, within)]["this"]["wall_s"] if within else None
            row(f"the square's contact force to 1.5e-5 in <= 3.5 s wall, {stop}",
                f"level {within} ({force['errors'][within]:.1e}), {wall:.2f} s" if within
                else "no level within 1.5e-5", bool(within) and wall <= 3.5)
    if not rows:
        return []
    return ["## Targets\n", "| target | measured | |", "|---|---|---|"] + rows + [""]


def largest_runs(results):
    """The runs whose wall time and memory the tables break down: the
    square's level 9 and the cube's levels 6 and 7, those that ran."""
    return [(tag, level) for tag, level in (("square", 9), ("cube", 6), ("cube", 7))
            if results.get((tag, level))]


def start_up(binary):
    """The wall time of `binary --version`, the fastest of 5 runs: what
    every run spends before its work (the dynamic loader binding the
    symbols of deal.II and the libraries it brings, MPI_Init)."""
    best = float("inf")
    for _ in range(5):
        t = time.time()
        launch([binary, "--version"], capture_output=True, check=True)
        best = min(best, time.time() - t)
    return best


def phases(results, start):
    """Where the wall time of the largest runs goes: the start-up (@p
    start, seconds), the sections of summary.json's time_sections_s, and
    what is left (the data checks, the output, which is written after
    summary.json, the end of the process)."""
    cases = largest_runs(results)
    if not cases:
        return []
    names = ["Setup: mesh, DoFs, levels", "Assembly", "Definiteness check", "Setup: solver",
             "Solve"]
    lines = ["## Where the wall time goes (seconds)\n",
             "The start-up is the fastest of 5 runs of `fosls-contact --version`: the dynamic "
             "loader binding the symbols of deal.II and the libraries it brings, and "
             "MPI_Init, before any work of the run.\n",
             "| phase | " + " | ".join(f"{t} level {l}" for t, l in cases) + " |",
             "|---|" + "---|" * len(cases)]
    rows = [("start-up", lambda s, sections: start)] + \
        [(name, lambda s, sections, name=name: sections.get(name, 0.)) for name in names] + \
        [("the rest (data checks, output, the end of the process)",
          lambda s, sections: s["wall_s"] - start - sum(sections.get(n, 0.) for n in names))]
    for name, value in rows:
        cells = [f"{value(results[c]['this'], results[c]['this']['time_sections_s']):.2f}"
                 for c in cases]
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    return lines + [""]


def matrix_rows(results):
    """The cube with the patch smoother's rows read from the level matrices
    against copied rows (this build, the same levels): the time of the
    solve and of its smoothing, and the peak memory, with the phase after
    which the resident memory reached it."""
    lines = []
    for level in range(3, 8):
        copied, matrix = results.get(("cube", level)), results.get((MATRIX_ROWS, level))
        if not (copied and matrix):
            continue
        c, m = copied["this"], matrix["this"]
        smoothing = [x["time_sections_s"].get("Solve: smoothing", 0.) for x in (c, m)]
        peak_phase = max(m["memory_by_phase"], key=lambda p: p["rss_mb"])["phase"]
        lines.append(f"| {level} | {c['time_solve_s']:.2f} | {m['time_solve_s']:.2f} | "
                     f"{m['time_solve_s'] / c['time_solve_s']:.2f} | "
                     f"{smoothing[1] / smoothing[0]:.2f} | {m['wall_s'] / c['wall_s']:.2f} | "
                     f"{c['peak_rss_mb']:.0f} | {m['peak_rss_mb']:.0f} | "
                     f"{bytes_per_dof(m['peak_rss_mb'], m):.0f} | {peak_phase} |")
    if not lines:
        return []
    return ["## The cube with the patch rows read from the level matrices\n",
            "`Solver/Patch rows = matrix` against the default `copied` (this build; the same "
            "iterates to the bit). Ratios are matrix / copied; the peak phase is the phase "
            "after which the resident memory of the matrix run was highest.\n",
            "| level | solve s, copied | solve s, matrix | solve ratio | smoothing ratio | "
            "wall ratio | peak MB, copied | peak MB, matrix | bytes per DoF, matrix | "
            "peak phase |",
            "|---|---|---|---|---|---|---|---|---|---|"] + lines + [""]


def memory_by_phase(results):
    """The resident memory after each phase of the largest runs
    (summary.json's memory_by_phase), its file-backed part and the peak."""
    cases = largest_runs(results)
    if not cases:
        return []
    lines = ["## Resident memory after each phase (MB)\n",
             "| phase | " + " | ".join(f"{t} level {l}" for t, l in cases) + " |",
             "|---|" + "---|" * len(cases)]
    runs = [results[c]["this"] for c in cases]
    for i, phase in enumerate(runs[0]["memory_by_phase"]):
        lines.append(f"| {phase['phase']} | " +
                     " | ".join(f"{s['memory_by_phase'][i]['rss_mb']:,.0f}" for s in runs) + " |")
    lines.append("| of it file-backed, after the solve | " +
                 " | ".join(f"{file_backed_mb(s):,.0f}" for s in runs) + " |")
    lines.append("| peak (bytes per DoF) | " +
                 " | ".join(f"{s['peak_rss_mb']:,.0f} ({bytes_per_dof(s['peak_rss_mb'], s):,.0f})"
                            for s in runs) + " |")
    return lines + [""]


def memory_by_level(results):
    """Where the memory of the finest run of each scene goes, level by
    level (summary.json's memory_mb_by_level), in bytes per DoF of the
    finest level: each structure on the finest level and on the coarser
    ones together; what the structures hold together against the resident
    memory after the solve without the file-backed pages; the difference
    is what no structure reports: the solve's temporary vectors and the
    memory the allocator keeps after the set-up freed it."""
    cases = []
    for tag in ("square", SQUARE_MATRIX_ROWS, "cube", MATRIX_ROWS):
        level, s = finest(results, tag)
        if not s or "memory_mb_by_level" not in s or file_backed_mb(s) is None:
            continue
        cases.append((tag, level, s))
    if not cases:
        return []
    names = []
    for _, _, s in cases:
        names += [n for n in ["mesh and DoF handler"] + list(s["memory_mb_by_level"])
                  if n not in names]

    def per_dof(mb, s):
        return f"{bytes_per_dof(mb, s):.0f}"

    lines = ["## Memory by level\n",
             "Bytes per DoF of the finest level (summary.json's `memory_mb_by_level`): each "
             "structure on the finest level, on the coarser levels together, and in all; the "
             "mesh and DoF handler hold all levels at once. The structures together are "
             "compared with the resident memory after the solve, when they are measured, "
             "without the file-backed pages; the difference, not attributed, is what no "
             "structure reports: the solve's vectors of the finest level (the Newton step's "
             "conjugate gradients keep theirs in deal.II's vector pool) and memory the "
             "allocator keeps after the set-up freed it.\n",
             "| structure | " + " | ".join(f"{t} level {l}: finest, coarser, all"
                                             for t, l, _ in cases) + " |",
             "|---|" + "---|" * len(cases)]
    for name in names:
        cells = []
        for _, _, s in cases:
            if name == "mesh and DoF handler":
                cells.append(f"-, -, {per_dof(s['memory_mb'][name], s)}")
                continue
            mb = s["memory_mb_by_level"].get(name)
            cells.append(f"{per_dof(mb[-1], s)}, {per_dof(sum(mb[:-1]), s)}, "
                         f"{per_dof(sum(mb), s)}" if mb else "")
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    together = [sum(s["memory_mb"].values()) for _, _, s in cases]
    after = [s["memory_by_phase"][-1] for _, _, s in cases]
    rest = [p["rss_mb"] - p["rss_file_mb"] for p in after]
    lines.append("| the structures together | " +
                 " | ".join(per_dof(t, s) for t, (_, _, s) in zip(together, cases)) + " |")
    lines.append("| resident after the solve, without the file-backed pages | " +
                 " | ".join(per_dof(r, s) for r, (_, _, s) in zip(rest, cases)) + " |")
    lines.append("| not attributed | " +
                 " | ".join(per_dof(r - t, s) for r, t, (_, _, s) in zip(rest, together, cases))
                 + " |")
    return lines + [""]


def copy_targets(text):
    """Put the section "## Targets" of @p text (scale_results.md) between
    the markers BEGIN and END of doc/performance.md."""
    if "## Targets\n" not in text:
        sys.exit(f"{OUT}: no section '## Targets' to copy")
    section = text.split("## Targets\n", 1)[1].split("\n## ", 1)[0].strip()
    with open(PERFORMANCE) as f:
        doc = f.read()
    if BEGIN not in doc or END not in doc or doc.index(END) < doc.index(BEGIN):
        sys.exit(f"{PERFORMANCE}: the markers of the targets' table are missing")
    head, rest = doc.split(BEGIN, 1)
    tail = rest.split(END, 1)[1]
    with open(PERFORMANCE, "w") as f:
        f.write(head + BEGIN + "\n\n" + section + "\n\n" + END + tail)


def main():
    a = arguments()
    if a.copy_targets:
        with open(OUT) as f:
            copy_targets(f.read())
        return
    os.makedirs(RES, exist_ok=True)
    binaries = {"this": BIN}
    if a.base_rev:
        binaries["base"] = build_base(a.base_rev)
    start = start_up(binaries["this"])
    results = {}
    for tag, scene, levels, growth, settings, with_base in CASES:
        previous_mb = None
        builds = binaries if with_base else {"this": binaries["this"]}
        for level in levels:
            if level > a.max_level:
                continue
            if previous_mb and previous_mb * growth > 0.85 * available_mb():
                print(f"{tag} level {level}: skipped, about {previous_mb * growth / 1024:.1f} GB "
                      f"expected, {available_mb() / 1024:.1f} GB available", flush=True)
                results[(tag, level)] = None
                continue
            best = measure(builds, scene, level, a.runs, a.threads, tag, settings)
            results[(tag, level)] = best
            previous_mb = max(s["peak_rss_mb"] for s in best.values())

    lines = ["# Whole runs: time and memory per DoF\n",
             "<!-- generated by bench/scale.py: change the script, not this file -->\n",
             f"One process, {a.threads} threads, the default solver, the fastest of {a.runs} "
             "runs by wall time" + (f"; `base` is revision {a.base_rev}, built and run "
                                     "alternately with this build" if a.base_rev else "") +
             ". wall = the whole process (start-up, set-up, checks, solve, output); "
             "set-up = mesh, DoFs, levels, assembly, checks and the solver's set-up "
             "(`time_setup_s`); bytes per DoF = peak resident memory / DoFs; file-backed = "
             "the resident pages of the program and its shared libraries after the last "
             "phase (`memory_by_phase`'s `rss_file_mb`), mostly read-only pages that the "
             "kernel can drop and reread; the rest is what the run allocated.\n"]
    header = ["scene", "level", "DoFs", "wall s", "solve s", "set-up s", "wall / solve",
              "peak MB", "bytes per DoF", "file-backed MB", "bytes per DoF, the rest"]
    if a.base_rev:
        header += ["base wall s", "base bytes per DoF", "wall ratio", "memory ratio"]
    lines.append("| " + " | ".join(header) + " |")
    lines.append("|" + "---|" * len(header))
    for (tag, level), best in results.items():
        if best is None:
            lines.append(f"| {tag} | {level} | skipped (memory) |" + " |" * (len(header) - 3))
            continue
        s = best["this"]
        per_dof = bytes_per_dof(s["peak_rss_mb"], s)
        row = [tag, level, s["dofs"], f"{s['wall_s']:.2f}", f"{s['time_solve_s']:.2f}",
               f"{s['time_setup_s']:.2f}", f"{s['wall_s'] / s['time_solve_s']:.2f}",
               f"{s['peak_rss_mb']:.0f}", f"{per_dof:.0f}"]
        file_mb = file_backed_mb(s)
        row += [f"{file_mb:.0f}", f"{bytes_per_dof(s['peak_rss_mb'] - file_mb, s):.0f}"] \
            if file_mb is not None else ["", ""]
        if a.base_rev and "base" not in best:
            row += ["", "", "", ""]
        elif a.base_rev:
            b = best["base"]
            b_per_dof = bytes_per_dof(b["peak_rss_mb"], b)
            row += [f"{b['wall_s']:.2f}", f"{b_per_dof:.0f}", f"{s['wall_s'] / b['wall_s']:.2f}",
                    f"{per_dof / b_per_dof:.2f}"]
        lines.append("| " + " | ".join(str(x) for x in row) + " |")
    lines.append("")

    # the square's force against its limit
    force = square_force(results)
    if force:
        lines.append(f"The square's contact force: limit {force['limit']:.8g} (extrapolated "
                     f"from levels 7-9, ratio of differences {force['ratio']:.2f}); relative "
                     "error by level: " +
                     ", ".join(f"{level} {error:.1e}"
                               for level, error in sorted(force["errors"].items())) + ".")
        if force["within"]:
            s = results[("square", force["within"])]["this"]
            lines.append(f" The first level within 1.5e-5: {force['within']}, "
                         f"{s['wall_s']:.2f} s wall.\n")
        else:
            lines.append(" No level is within 1.5e-5.\n")
        stopped = square_force(results, SQUARE_DISCRETIZATION)
        if stopped and stopped["errors"]:
            lines.append("Stopped at discretization accuracy (`Solver/Stopping criterion`), "
                         "against the same limit: " +
                         ", ".join(f"level {level} {error:.1e} in "
                                   f"{results[(SQUARE_DISCRETIZATION, level)]['this']['wall_s']:.2f}"
                                   f" s wall ({results[(SQUARE_DISCRETIZATION, level)]['this']['iterations']}"
                                   " iterations)"
                                   for level, error in sorted(stopped["errors"].items())) +
                         "; the default tolerance: " +
                         ", ".join(f"level {level} {results[('square', level)]['this']['iterations']}"
                                   " iterations" for level in sorted(stopped["errors"])
                                   if results.get(("square", level))) + ".\n")

    lines += targets(results)
    lines += phases(results, start)
    lines += memory_by_phase(results)
    lines += matrix_rows(results)
    lines += memory_by_level(results)

    # memory by structure, where the build reports it
    for (tag, level), best in results.items():
        if best and "memory_mb" in best["this"]:
            memory = best["this"]["memory_mb"]
            parts = ", ".join(f"{k} {bytes_per_dof(v, best['this']):.0f}" for k, v in
                              sorted(memory.items(), key=lambda kv: -kv[1]))
            lines.append(f"- {tag} level {level}, bytes per DoF by structure: {parts}")
    lines.append("")
    text = "\n".join(lines)
    with open(OUT, "w") as f:
        f.write(text)
    print(text)
    # (a run of some levels only leaves the documented targets as they are)
    if a.max_level >= max(max(levels) for _, _, levels, _, _, _ in CASES):
        copy_targets(text)
    else:
        print(f"(--max-level: {PERFORMANCE} keeps its targets' table)")


if __name__ == "__main__":
    main()
