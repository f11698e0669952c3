# A run killed (SIGKILL, by tests/solver/fault_injection.cc through
# LD_PRELOAD) before any of the calls that change the directories' entries
# while it publishes its files (link, rename, unlink, rmdir on the paths of
# Output/Directory), and the next run into the same directory: after the
# next run the directory holds the user's file notes.txt and subdirectory
# plots/ (with a file two levels down) with their contents, exactly the
# files that its list .fosls-contact-files names (besides them), all of
# the next run, and nothing is left beside it (README, "How the output
# files appear"). The kill point goes from the first call to the first one
# the run does not reach, with RENAME_EXCHANGE and with the two renames of
# a filesystem without it (killed right after the exchange, the user's
# plots/ is in the hidden staging directory, and the next run must bring it
# back). Then, for the kill right after the
# exchange, the next run is killed too, before each of the calls with
# which it repairs the directory, and a third run checks the directory.
# ctest: timeout=600 cost=40
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, execute, finish, leftovers

exe, source = sys.argv[1], sys.argv[2]
shim = os.environ["FOSLS_FAULT_LIBRARY"]
scene = os.path.join(source, "tests/scenes/square.prm")
directory = "kp_target"
user = {"notes.txt": "the user's notes\n", "plots/p.txt": "a plot\n",
        "plots/deep/q.txt": "two levels down\n"}


def run(levels, fault=None):
    env = {"LD_PRELOAD": shim, "FOSLS_FAULT_PATH": directory}
    env.update(fault or {})
    return execute([exe, scene, "--set", "Output/Directory=" + directory,
                    "--set", "Output/Verbose=false",
                    "--set", "Geometry/Levels=%d" % levels], env=env)[0]


def read(name):
    with open(os.path.join(directory, name)) as f:
        return f.read()


def signature():
    """What the files say about the run that wrote them (None if they do
    not agree on the levels)."""
    try:
        levels = int(re.search(r'"levels": (\d+)', read("summary.json")).group(1))
        used = int(re.search(r"set Levels\s*=\s*(\d+)", read("used_parameters.prm")).group(1))
        cells = int(re.search(r'NumberOfCells="(\d+)"', read("solution_0000.0.vtu")).group(1))
        rows = len(read("contact.csv").splitlines())
        return (levels, cells, rows) if used == levels else None
    except (OSError, AttributeError, ValueError):
        return None


def problems(levels):
    """What is wrong with the directory after a complete run on @p levels
    ("" if nothing)."""
    wrong = []
    try:
        if any(read(n) != c for n, c in user.items()):
            wrong.append("a user's file changed")
    except OSError:
        wrong.append("a user's file missing")
    try:
        listed = set(l for l in read(".fosls-contact-files").splitlines() if l)
        present = set(os.listdir(directory))
        if present != listed | {".fosls-contact-files", "notes.txt", "plots"}:
            wrong.append("files not listed or listed files missing: %s"
                         % " ".join(sorted(present ^ (listed | {".fosls-contact-files",
                                                                "notes.txt", "plots"}))))
    except OSError:
        wrong.append("no list")
    if signature() != reference[levels]:
        wrong.append("not the files of the run on %d levels" % levels)
    if leftovers(directory):
        wrong.append("left beside it: " + " ".join(leftovers(directory)))
    return "; ".join(wrong)


def report(label, levels):
    wrong = problems(levels)
    check(not wrong, label + ": the user's file and directory, the files of one run (its "
          "list), nothing left beside it" + (" (not: %s)" % wrong if wrong else ""))


# the files of a complete run on 2 and on 3 levels
reference = {}
for levels in (2, 3):
    rc = run(levels)
    reference[levels] = signature()
    check(rc == 0 and reference[levels] is not None, "%d levels: exit code 0, its files" % levels)
for name, content in user.items():
    os.makedirs(os.path.dirname(os.path.join(directory, name)), exist_ok=True)
    with open(os.path.join(directory, name), "w") as f:
        f.write(content)

for mode, extra in [("exchange", {}), ("two renames", {"FOSLS_FAULT_NO_EXCHANGE": "1"})]:
    for k in range(1, 60):
        levels = 2 if k % 2 else 3
        rc = run(levels, dict(extra, FOSLS_FAULT_KILL_AT=str(k)))
        if rc != -9:
            print("--- %s: call %d not reached (exit code %s)" % (mode, k, rc))
            report("%s: a run that is not killed" % mode, levels)
            break
        rc = run(5 - levels, extra)
        check(rc == 0, "%s, killed before call %d: the next run: exit code 0" % (mode, k))
        report("%s, killed before call %d: after the next run" % (mode, k), 5 - levels)

# killed right after the exchange (call 1 links notes.txt, call 2 is the
# exchange), then the next run killed before each of its calls until it
# has repaired the directory (what the first run left is gone), then a
# third run
for j in range(1, 60):
    first = run(3, {"FOSLS_FAULT_KILL_AT": "3"})
    left = [n for n in leftovers(directory) if ".staging-" in n]
    rc = run(2, {"FOSLS_FAULT_KILL_AT": str(j)})
    label = "killed after the exchange, the next run before its call %d" % j
    print("--- %s: %s" % (label, "killed" if rc == -9 else "not reached (exit code %s)" % rc))
    check(first == -9, label + ": the first run killed")
    repaired = not set(left) & set(leftovers(directory))
    if rc != -9:
        report(label + ": the next run, not killed", 2)
        break
    rc = run(3)
    check(rc == 0, label + ": a third run: exit code 0")
    report(label + ": after a third run", 3)
    if repaired:
        break
finish()
