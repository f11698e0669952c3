#!/usr/bin/env python3
# A run that cannot fit into memory is refused before the mesh is refined
# (MemoryBudget), in one line with the estimate, the memory available and
# what limits it, and the number of levels that fits.
#  - prm/hertz.prm with Geometry/Levels = 10 (about 100 million DoFs, some
#    170 GB at the measured bytes per DoF): refused within seconds (not
#    killed by the kernel's out-of-memory killer after minutes),
#    exit code 1, no output directory, the line naming the estimate and
#    'Geometry/Levels'.
#  - Under an address-space limit (ulimit -v 3 GB): the square with 11
#    levels (6.3 million DoFs) is refused naming 'ulimit -v'; the square
#    with 4 levels runs under the same limit.
#  - The adaptive Hertz contact (prm/hertz_adaptive.prm, Max DoFs 200,000)
#    under ulimit -v 1 GB: the loop stops refining before a mesh that
#    might not fit (adaptive_stop says so), with exit code 0, before
#    Adaptivity/Max DoFs.
# Not under the sanitizers: ASan reserves terabytes of address space for its
# shadow memory, and the program cannot start under ulimit -v.
# ctest: no_sanitize cost=12
import json
import os
import subprocess
import sys
import time
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, command_line, finish

exe, source = sys.argv[1], sys.argv[2]


def run(prm, settings, name, limit_kb=None):
    command = command_line(exe, os.path.join(source, "prm", prm),
                           ["Output/Directory=" + name, "Output/Write vtu=false"] + settings)
    if limit_kb:
        command = ["bash", "-c", 'ulimit -v %d && exec "$@"' % limit_kb, "bash"] + command
    start = time.time()
    p = subprocess.run(command, capture_output=True, text=True, timeout=600)
    return p.returncode, p.stderr.strip().splitlines(), time.time() - start


code, err, seconds = run("hertz.prm", ["Geometry/Levels=10"], "hertz_10")
print("hertz, 10 levels: " + (err[0].split(": ", 2)[-1].split(" (")[0] if err else ""))
check(code == 1 and len(err) == 1 and "needs about" in err[0] and "available" in err[0]
      and "'Geometry/Levels' (10) to at most" in err[0] and not os.path.exists("hertz_10")
      and seconds < 60,
      "hertz, 10 levels: refused before the refinement, in one line naming the levels")

limit = 3 * 1024 * 1024
code, err, seconds = run("square.prm", ["Geometry/Levels=11"], "square_11", limit)
check(code == 1 and len(err) == 1 and "ulimit -v" in err[0] and "needs about" in err[0]
      and not os.path.exists("square_11"),
      "square, 11 levels, ulimit -v 3 GB: refused naming the address-space limit")
code, err, seconds = run("square.prm", ["Geometry/Levels=4"], "square_4", limit)
check(code == 0 and not err and os.path.exists(os.path.join("square_4", "summary.json")),
      "square, 4 levels, ulimit -v 3 GB: runs")
code, err, seconds = run("hertz_adaptive.prm", [], "adaptive", 1000 * 1024)
try:
    with open(os.path.join("adaptive", "summary.json")) as f:
        summary = json.load(f)
except (OSError, ValueError):
    summary = {}
print("adaptive, ulimit -v 1 GB: stopped as '%s'" % summary.get("adaptive_stop"))
check(code == 0 and not err and summary.get("adaptive_stop") ==
      "the next mesh might not fit into the memory available"
      and summary.get("dofs", 1e9) < 200000,
      "adaptive, ulimit -v 1 GB: the loop stops before a mesh that might not fit")
finish()
