# The output set of a run appears all at once or not at all (README,
# "Output files"). Runs of the square on 2 and 3 levels go into one
# directory; a run is killed (SIGKILL, by tests/solver/fault_injection.cc
# through LD_PRELOAD) before its first rename, then before its second, ...
# until a run makes fewer renames than that. After every run the directory
# holds the files of one run only: summary.json, used_parameters.prm,
# contact.csv, convergence.csv and the vtu piece agree on the number of
# levels (files renamed into place one at a time, killed before the third
# rename, would leave the new solution next to the old summary.json). A
# write that fails with ENOSPC: exit code 1, one line naming
# Output/Directory, the directory unchanged, no staging directory or lock
# file left. A
# filesystem without RENAME_EXCHANGE: the fallback (two renames) publishes
# the files and keeps the user's file.
# ctest: sanitize
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, execute, finish, leftovers, one_error_line

exe, source = sys.argv[1], sys.argv[2]
shim = os.environ["FOSLS_FAULT_LIBRARY"]
scene = os.path.join(source, "tests/scenes/square.prm")
directory = "out"


def run(levels, fault=None):
    env = {"LD_PRELOAD": shim}
    env.update(fault or {})
    return execute([exe, scene, "--set", "Output/Directory=" + directory,
                    "--set", "Output/Verbose=false",
                    "--set", "Geometry/Levels=%d" % levels], env=env)


def read(name):
    with open(os.path.join(directory, name)) as f:
        return f.read()


def signature():
    """What the files in the directory say about the run that wrote them:
    one tuple per file (levels, or a count that depends on the levels)."""
    try:
        summary = read("summary.json")
        levels = int(re.search(r'"levels": (\d+)', summary).group(1))
        iterations = int(re.search(r'"iterations": (\d+)', summary).group(1))
        used = int(re.search(r"set Levels\s*=\s*(\d+)", read("used_parameters.prm")).group(1))
        contact = len(read("contact.csv").splitlines()) - 1
        convergence = len(read("convergence.csv").splitlines()) - 1
        cells = int(re.search(r'NumberOfCells="(\d+)"', read("solution_0000.0.vtu")).group(1))
        pieces = re.findall(r'Source="([^"]+)"', read("solution_0000.pvtu"))
        return (levels, used, contact, convergence - iterations, cells, tuple(pieces))
    except (OSError, AttributeError, ValueError):
        return None


def snapshot():
    return {n: open(os.path.join(directory, n), "rb").read()
            for n in sorted(os.listdir(directory))}


# the files of a complete run on 2 and on 3 levels
reference = {}
for levels in (2, 3):
    rc, out, err = run(levels)
    check(rc == 0 and err == "", "%d levels: exit code 0, nothing on stderr" % levels)
    reference[levels] = signature()
    check(reference[levels] is not None and reference[levels][0] == levels
          and reference[levels][1] == levels and reference[levels][3] == 1,
          "%d levels: the files agree on the levels" % levels)
check(reference[2][2:5] != reference[3][2:5], "the files of 2 and 3 levels differ")

for k in range(1, 20):
    levels = 2 if k % 2 else 3
    rc, out, err = run(levels, {"FOSLS_FAULT_KILL_AT_RENAME": str(k)})
    killed = rc == -9
    print("--- killed before rename %d: %s" % (k, "yes" if killed else "no (exit code %s)" % rc))
    check(signature() in (reference[2], reference[3]),
          "killed before rename %d: the directory holds the files of one run" % k)
    if not killed:
        check(rc == 0 and signature() == reference[levels],
              "rename %d not reached: the run ended with exit code 0 and its files" % k)
        break

# a run after the killed ones removes their staging directories
rc, out, err = run(2)
check(rc == 0 and signature() == reference[2], "then a run: exit code 0, its files")
check(leftovers(directory) == [], "no staging directory or lock file left")

# the disk fills up while the files are written
before = snapshot()
rc, out, err = run(3, {"FOSLS_FAULT_ENOSPC_AFTER": "2000"})
print("--- no space left: exit code %s" % rc)
check(rc == 1 and one_error_line(err, "Output/Directory", "No space left on device"),
      "no space left: exit code 1, one line naming Output/Directory and the cause")
check(snapshot() == before, "no space left: the directory is unchanged")
check(leftovers(directory) == [], "no space left: no staging directory or lock file left")

# a filesystem without RENAME_EXCHANGE
with open(os.path.join(directory, "notes.txt"), "w") as f:
    f.write("the user's notes\n")
rc, out, err = run(3, {"FOSLS_FAULT_NO_EXCHANGE": "1"})
check(rc == 0 and err == "" and signature() == reference[3],
      "without RENAME_EXCHANGE: exit code 0, the new files")
check(read("notes.txt") == "the user's notes\n", "without RENAME_EXCHANGE: the user's file kept")
check(leftovers(directory) == [], "without RENAME_EXCHANGE: nothing left beside the directory")
finish()
