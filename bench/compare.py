#!/usr/bin/env python3
"""Two or more builds of fosls-contact side by side: the time per cycle per
DoF of each on the same levels, the fastest of --runs runs, the builds
alternated so that every one of them sees the same spells of the machine
(single runs of one binary scatter by 10-65% here, doc/performance.md
section 1), and each first in turn. This is how the changes in
doc/performance.md sections 3 and 4 are measured; with this script they can
be measured again.

    bench/compare.py --bin main=build/fosls-contact --bin dev=../devbuild/fosls-contact
    bench/compare.py --bin main=... --bin dev=... --levels 5,7,9 --threads 2 --runs 6
    bench/compare.py --bin a=... --bin b=... --scene cube3d.prm --levels 4,5 \\
                     --set Solver/Cycle=F

The time per cycle per DoF is the solve time / cycles / DoFs of
summary.json, the measure of doc/results.md f. The table also gives the
cycles and flags a level whose builds differ in cycles or in J beyond 1e-10
(relative): a change meant to keep the iterates should not differ there.
Exit status 1 if a run fails, 2 for bad arguments.
"""
import argparse
import os
import sys

from common import scene_file
from parallel import fastest


def arguments():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--bin", action="append", required=True, metavar="NAME=PATH",
                   help="a build to compare (at least two); the first is the reference")
    p.add_argument("--levels", default="5,6,7,8,9", help="Geometry/Levels values (default 5-9)")
    p.add_argument("--threads", type=int, default=1, help="threads per process (default 1)")
    p.add_argument("--processes", type=int, default=1, help="MPI processes (default 1)")
    p.add_argument("--runs", type=int, default=4,
                   help="runs per build and level (default 4; at least the number of builds "
                   "for each to go first in turn)")
    p.add_argument("--scene", default="square.prm", help="a file of prm/ (default square.prm)")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                   help="a further parameter, e.g. Material/lambda=inf")
    a = p.parse_args()

    def pair(text, what):
        if "=" not in text or not text.split("=", 1)[0] or not text.split("=", 1)[1]:
            p.error(f"{what} '{text}': expected NAME=VALUE")
        return text.split("=", 1)

    a.bins = {}
    for text in a.bin:
        name, path = pair(text, "--bin")
        path = os.path.abspath(path)
        if not all(c.isalnum() or c in "-_." for c in name):
            p.error(f"--bin '{text}': a name of letters, digits, '-', '_' and '.' only")
        if name in a.bins:
            p.error(f"--bin '{text}': the name '{name}' is given twice")
        if not (os.path.isfile(path) and os.access(path, os.X_OK)):
            p.error(f"--bin '{text}': {path} is not an executable file")
        a.bins[name] = path
    if len(a.bins) < 2:
        p.error("--bin: give at least two builds")
    try:
        a.levels = sorted(set(int(x) for x in a.levels.split(",")))
    except ValueError:
        p.error(f"--levels '{a.levels}': expected integers separated by commas")
    if min(a.levels) < 1 or a.threads < 1 or a.processes < 1 or a.runs < 1:
        p.error("--levels, --threads, --processes and --runs must be positive")
    if not os.path.isfile(scene_file(a.scene)):
        p.error(f"--scene '{a.scene}': no such file in {os.path.dirname(scene_file(a.scene))}")
    a.settings = dict(pair(s, "--set") for s in a.set)
    for key in a.settings:
        # (these the script sets itself: the levels per run, the output it
        # reads back, the threads of --threads)
        if key == "Geometry/Levels" or key == "Solver/Threads" or key.startswith("Output/"):
            p.error(f"--set '{key}': set by the script (use --levels or --threads)")
    return a


def main():
    a = arguments()
    names = list(a.bins)
    try:
        best = fastest({n: (a.bins[n], {}) for n in names}, a.levels, a.runs, a.scene,
                       a.settings, a.processes, a.threads, "compare")
    except SystemExit as e:  # a failed run: its command and error
        print(e, file=sys.stderr)
        sys.exit(1)

    print()
    print(f"{a.scene}, {a.processes} process(es) x {a.threads} thread(s), "
          f"{' '.join(a.set) or 'its own settings'}; the fastest of {a.runs} runs: "
          f"us per cycle per DoF (cycles), and the ratio to {names[0]}")
    print()
    print("| level | DoFs | " + " | ".join(names) + " | " +
          " | ".join(f"{n}/{names[0]}" for n in names[1:]) + " | same iterates |")
    print("|" + "---|" * (2 + 2 * len(names)))
    for level in a.levels:
        ref = best[(names[0], level)]
        def same_as_reference(n):
            s, r = best[(n, level)][1], ref[1]
            return (s["cycles"] == r["cycles"] and None not in (s["functional"], r["functional"])
                    and abs(s["functional"] - r["functional"]) <= 1e-10 * abs(r["functional"]))
        differ = [n for n in names[1:] if not same_as_reference(n)]
        print(f"| {level} | {ref[1]['dofs']} | " +
              " | ".join(f"{best[(n, level)][0]:.3f} ({best[(n, level)][1]['cycles']})"
                         for n in names) + " | " +
              " | ".join(f"{best[(n, level)][0] / ref[0]:.3f}" for n in names[1:]) +
              f" | {'NO: ' + ', '.join(differ) if differ else 'yes'} |")
    if len(a.levels) > 1:
        print("| max/min | | " + " | ".join(
            f"{max(best[(n, l)][0] for l in a.levels) / min(best[(n, l)][0] for l in a.levels):.2f}"
            for n in names) + " |" + " |" * (len(names) - 1) + " |")


if __name__ == "__main__":
    main()
