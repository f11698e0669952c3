#!/usr/bin/env python3
"""What writing the VTU files costs: the process's peak memory and the time
of the output phase of whole runs with Output/Write vtu = true (the
default; bench/scale.py writes none, and summary.json's peak_rss_mb is read
as the output begins), for the square at level 9 and the cube at level 6,
one process with all its threads; with --base-rev the same for another
revision (built as bench/scale.py builds it), run alternately with this
build, and the ratio of their lowest peaks. The peak is the kernel's
high-water mark of the process (wait4's ru_maxrss), in MB of 2^20 bytes as
in summary.json.

    bench/vtu_output.py --base-rev ff2869a --runs 2
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import time

from common import BIN, ENV, RESULTS, command
from scale import build_base

RES = os.path.join(RESULTS, "vtu_output")
CASES = [("square", "square.prm", 9), ("cube", "cube3d.prm", 6)]


def run(binary, scene, level, out):
    """Wall time, output phase time (its line on the screen) and peak MB of
    one run of @p binary (the child waited for with os.wait4, whose rusage
    is that child's alone)."""
    shutil.rmtree(out, ignore_errors=True)
    cmd = command(scene, [f"Geometry/Levels={level}", f"Output/Directory={out}",
                          "Output/Write vtu=true"], binary)
    log = out + ".screen"
    start = time.time()
    with open(log, "w") as screen:
        process = subprocess.Popen(cmd, stdout=screen, stderr=subprocess.STDOUT, env=ENV)
        _, status, usage = os.wait4(process.pid, 0)
    wall = time.time() - start
    code = os.waitstatus_to_exitcode(status)
    with open(log) as f:
        text = f.read()
    if code != 0:
        sys.exit(f"failed ({code}): {' '.join(cmd)}\n{text}")
    output = re.search(r"^Output \.\.\. ([0-9.]+) s", text, re.M)
    return {"wall": wall, "output": float(output.group(1)) if output else float("nan"),
            "peak": usage.ru_maxrss / 1024.}


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--runs", type=int, default=2, help="runs per case and build (default 2)")
    p.add_argument("--base-rev", help="a git revision to build and compare with")
    args = p.parse_args()
    os.makedirs(RES, exist_ok=True)
    binaries = {"this": BIN}
    if args.base_rev:
        binaries["base"] = build_base(args.base_rev)
    print("| scene | level | build | peak MB (min-max) | output phase s (min-max) | "
          "wall s (min-max) |")
    print("|---|---|---|---|---|---|")
    for tag, scene, level in CASES:
        results = {name: [] for name in binaries}
        names = list(binaries)
        for k in range(args.runs):
            shift = k % len(names)
            for name in names[shift:] + names[:shift]:
                results[name].append(run(binaries[name], scene, level,
                                         os.path.join(RES, f"{tag}_{name}")))
        for name in names:
            r = results[name]
            span = lambda key, f: f"{f % min(x[key] for x in r)}-{f % max(x[key] for x in r)}"
            print(f"| {tag} | {level} | {name} | {span('peak', '%.0f')} | "
                  f"{span('output', '%.2f')} | {span('wall', '%.2f')} |", flush=True)
        if "base" in results:
            ratio = (min(x["peak"] for x in results["this"]) /
                     min(x["peak"] for x in results["base"]))
            print(f"| {tag} | {level} | this / base, lowest peaks | {ratio:.3f} | | |")


if __name__ == "__main__":
    main()
