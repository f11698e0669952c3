# The output directory holds this run's files only: a run into a directory
# an earlier run wrote removes the solution files it does not replace
# (a run on 1 process after one on 2 must not leave solution_0000.1.vtu, a
# piece the new .pvtu does not list, nor Write vtu = false the old solution
# next to the new summary). Runs of the square,
# 2 levels: on 2 processes, then on 1 into the same directory, then with
# Write vtu = false; every time the .pvtu lists exactly the pieces present.
# ctest: timeout=120 mpirun sanitize
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish

R = Runner(sys.argv)
directory = "shared_output"
settings = ["Geometry/Levels=2", "Output/Directory=" + directory, "Output/Write vtu=true"]


def solution_files():
    return sorted(f for f in os.listdir(directory) if f.startswith("solution_"))


def listed_pieces():
    with open(os.path.join(directory, "solution_0000.pvtu")) as f:
        return sorted(re.findall(r'Source="([^"]+)"', f.read()))


for label, processes, extra in [("2 processes", 2, []), ("then 1 process", 1, []),
                                ("then Write vtu = false", 1, ["Output/Write vtu=false"])]:
    run = R.run("tests/scenes/square.prm", settings + extra, processes=processes)
    files = solution_files()
    print("--- %s: %s" % (label, " ".join(files)))
    check(run.returncode == 0 and run.stderr == "", label + ": exit code 0, nothing on stderr")
    if extra:
        check(files == [], label + ": no solution files left")
    else:
        check(files == sorted(listed_pieces() + ["solution_0000.pvtu"]),
              label + ": the solution files are the .pvtu and the pieces it lists")
    check(not any(f.startswith("." + directory + ".") for f in os.listdir(".")),
          label + ": no staging directory or lock file left")
finish()
