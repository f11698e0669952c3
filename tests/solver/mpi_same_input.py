#!/usr/bin/env python3
# Every process of an MPI run works on the same input (SameInput): started
# with different inputs, the processes stop with one line naming what
# differs and exit code 1 (without the check they wait for each other
# until killed, or, with another output directory or push, run to exit
# code 0 on inconsistent data).
#  - mpirun -np 1 A : -np 1 B with another Geometry/Levels, and with
#    --version on one process only: "another command line";
#  - the same command in two working directories (mpirun -wdir) whose
#    scene files differ: "another scene";
#  (a mesh file that differs between nodes under the same name is compared
#  too: unit/same_input.mpirun=2, as one machine cannot give one path two
#  contents)
# Each run is killed after 120 s (a hang fails the test) and must leave no
# output directory.
import os
import subprocess
import sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, finish

exe, source = sys.argv[1], sys.argv[2]
mpirun = [os.environ.get("MPIRUN", "mpirun"), "--quiet", "--oversubscribe"]


def mpmd(first, second, what, pattern, directories=(".", ".")):
    command = mpirun + ["-np", "1", "-wdir", directories[0], exe] + first + \
        [":", "-np", "1", "-wdir", directories[1], exe] + second
    try:
        p = subprocess.run(command, capture_output=True, text=True, timeout=120)
        code, err = p.returncode, p.stderr.strip().splitlines()
    except subprocess.TimeoutExpired:
        code, err = None, []
    print("%s: %s" % (what, err[0].split(": ", 2)[-1][:60] if err else "(nothing)"))
    check(code == 1 and len(err) == 1 and pattern in err[0]
          and not any(os.path.exists(os.path.join(d, "out")) for d in directories),
          what + ": exit code 1, one line naming it, no output")


square = os.path.join(source, "prm", "square.prm")
base = [square, "--set", "Output/Directory=out", "--set", "Output/Write vtu=false"]
mpmd(base + ["--set", "Geometry/Levels=3"], base + ["--set", "Geometry/Levels=4"],
     "another Levels", "another command line")
mpmd(["--version"], base, "--version on one process", "another command line")

for d, push in (("a", "0.01"), ("b", "0.02")):
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "scene.prm"), "w") as f:
        f.write("include %s\nsubsection Data\n  set Constants = push=%s\n"
                "  set Dirichlet values = 0; -push\nend\n" % (square, push))
scene = ["scene.prm", "--set", "Output/Directory=out", "--set", "Output/Write vtu=false"]
mpmd(scene, scene, "scene files that differ", "another scene", ("a", "b"))

l_shape = os.path.join(source, "prm", "meshes", "l_shape.msh")
finish()
