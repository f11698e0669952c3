# A run that does not converge exits with code 2 (README, "Exit codes"),
# writes its files with "converged": false in summary.json and prints one
# line on stderr saying so. The square with
# Solver/Max iterations = 1, on one process and on two; a converged run
# exits with 0 and prints nothing on stderr.
# ctest: timeout=120
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, command_line, execute, finish

exe, source = sys.argv[1], sys.argv[2]
scene = os.path.join(source, "tests/scenes/square.prm")
files = ["contact.csv", "convergence.csv", "solution_0000.pvtu", "summary.json",
         "used_parameters.prm"]

for label, processes, settings in [
        ("Max iterations = 1", 1, ["Solver/Type=monotone multigrid", "Solver/Max iterations=1"]),
        ("Max iterations = 1, 2 processes", 2,
         ["Solver/Type=monotone multigrid", "Solver/Max iterations=1"]),
        ("converged", 1, [])]:
    directory = "out_%d_%d" % (processes, len(settings))
    rc, out, err = execute(command_line(
        exe, scene, ["Output/Directory=" + directory, "Geometry/Levels=4",
                     "Output/Verbose=false"] + settings, processes))
    with open(os.path.join(directory, "summary.json")) as f:
        converged = json.load(f)["converged"]
    print("--- %s: exit code %s, converged %s" % (label, rc, json.dumps(converged)))
    check(all(os.path.isfile(os.path.join(directory, f)) for f in files),
          label + ": every output file written")
    if settings:
        lines = err.splitlines()
        check(rc == 2 and converged is False, label + ": exit code 2, \"converged\": false")
        check(len(lines) == 1 and "not converged" in lines[0]
              and "'Solver/Max iterations' = 1" in lines[0],
              label + ": one line on stderr saying so")
    else:
        check(rc == 0 and converged is True and err == "",
              label + ": exit code 0, nothing on stderr")
finish()
