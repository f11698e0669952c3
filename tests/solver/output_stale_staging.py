# What a killed run leaves beside Output/Directory is removed by the next
# run into it, whatever output files it holds, and only that (README, "How
# the output files appear"). An adaptive run with .vtu files (the square,
# 2 levels, one refinement: solution_000N.*, contact_surface_000N.*,
# solution.pvd, contact_000N.csv, adaptive_steps.csv, ...) is killed (by
# tests/solver/fault_injection.cc) as it begins to write summary.json, so
# its staging directory holds every other output file and no list of
# them: the next run recognizes the leftovers by the staging directory's
# record, not by a list of output names. A copy of it without the staging directory's record (as an older
# version of the program leaves it) goes too, and so does the old
# directory that an older version left when killed right after its
# exchange; the user's subdirectory in that one is brought back into the
# directory.
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, execute, finish, leftovers

exe, source = sys.argv[1], sys.argv[2]
shim = os.environ["FOSLS_FAULT_LIBRARY"]
scene = os.path.join(source, "tests/scenes/square.prm")
directory = "st_out"


def run(settings, env=None):
    command = [exe, scene, "--set", "Output/Directory=" + directory,
               "--set", "Output/Verbose=false", "--set", "Geometry/Levels=2"]
    for s in settings:
        command += ["--set", s]
    return execute(command, env=env)[0]


rc = run([])
check(rc == 0, "a first run: exit code 0")
rc = run(["Adaptivity/Steps=1"], {"LD_PRELOAD": shim, "FOSLS_FAULT_KILL_AT_WRITE_TO": "summary.json"})
stale = [n for n in os.listdir(".") if n.startswith("." + directory + ".staging-")]
check(rc == -9 and len(stale) == 1, "an adaptive run killed as it writes summary.json: one "
      "staging directory left")
print("its files: " + " ".join(sorted(os.listdir(stale[0]))))
# the same without the record (an older version's), and an older version's
# old directory: its list, an old output file and the user's subdirectory
legacy = "." + directory + ".staging-999999"
shutil.copytree(stale[0], legacy)
if os.path.exists(os.path.join(legacy, ".fosls-contact-staging")):
    os.unlink(os.path.join(legacy, ".fosls-contact-staging"))
old = "." + directory + ".staging-999998"
os.makedirs(os.path.join(old, "plots"))
with open(os.path.join(old, "plots", "p.txt"), "w") as f:
    f.write("a plot\n")
with open(os.path.join(old, "summary.json"), "w") as f:
    f.write("{}\n")
with open(os.path.join(old, ".fosls-contact-files"), "w") as f:
    f.write("summary.json\n")

rc = run([])
check(rc == 0, "the next run: exit code 0")
check(leftovers(directory) == [], "the next run: no staging directory or lock file left")
names = sorted(os.listdir(directory))
with open(os.path.join(directory, ".fosls-contact-files")) as f:
    listed = sorted(l for l in f.read().splitlines() if l)
check(names == sorted(listed + [".fosls-contact-files", "plots"]),
      "the next run: the directory holds its listed files and the user's subdirectory")
try:
    with open(os.path.join(directory, "plots", "p.txt")) as f:
        plot = f.read()
except OSError:
    plot = None
check(plot == "a plot\n", "the user's file in it is there with its content")
finish()
