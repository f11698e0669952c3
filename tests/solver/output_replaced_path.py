# The path Output/Directory is changed by someone else while a run computes:
# the run never replaces (or hides) what is there now, unless it is a
# directory the program may replace. It ends with exit code 1 and one line
# naming Output/Directory and the directory in which it keeps its results
# (<name>.results-<pid>, with summary.json), and leaves nothing else
# (README, "How the output files appear"): a regular file made at the
# path during the run must not be exchanged for the results and left in
# the hidden staging directory with exit code 0. The path changes
#  - while the run computes (it is stopped with SIGSTOP after its scene
#    line): a regular file where there was nothing, a directory of the
#    user's (not written by the program) where the program's was, a
#    directory of the user's inside the program's under the name of an
#    output file;
#  - just before the rename that publishes (stopped there by
#    tests/solver/fault_injection.cc, FOSLS_FAULT_STOP_AT): with
#    RENAME_EXCHANGE, with the two renames of a filesystem without it, and
#    for a new directory;
#  - the same, and the run killed as it undoes the rename: the next run
#    puts the file back (and is refused, as the path is a file).
import os
import re
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, execute, finish, leftovers, one_error_line

exe, source = sys.argv[1], sys.argv[2]
shim = os.environ["FOSLS_FAULT_LIBRARY"]
scene = os.path.join(source, "tests/scenes/square.prm")


def command(directory, levels=2):
    return [exe, scene, "--set", "Output/Directory=" + directory,
            "--set", "Geometry/Levels=%d" % levels, "--set", "Output/Write vtu=false"]


def wait_stopped(pid):
    """Wait until process @p pid is stopped (state T); poll /proc."""
    while True:
        with open("/proc/%d/stat" % pid) as f:
            if f.read().rsplit(")", 1)[1].split()[0] in ("T", "t"):
                return
        time.sleep(0.02)


def file_with(path, content):
    with open(path, "w") as f:
        f.write(content)


def content(path):
    try:
        with open(path) as f:
            return f.read()
    except OSError:
        return None


def check_kept(label, run, err, directory):
    """The run refused to publish: exit code 1, one line naming
    Output/Directory and <directory>.results-<pid>, which holds its results."""
    kept = os.path.abspath("%s.results-%d" % (directory, run.pid))
    check(run.returncode == 1 and one_error_line(err, "Output/Directory", kept),
          label + ": exit code 1, one line naming Output/Directory and where the results are")
    check(content(os.path.join(kept, "summary.json")) is not None
          and sorted(os.listdir(kept)) == sorted(["summary.json", "contact.csv", "convergence.csv",
                                                  "used_parameters.prm", ".fosls-contact-files"]),
          label + ": the results are kept there")
    check(leftovers(directory) == [], label + ": no staging directory or lock file left")


def changed_while_computing(label, directory, change, intact):
    run = subprocess.Popen(command(directory, 5), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    for line in iter(run.stdout.readline, b""):
        if line.startswith(b"Scene:"):
            break
    os.kill(run.pid, signal.SIGSTOP)
    change()
    os.kill(run.pid, signal.SIGCONT)
    out, err = run.communicate()
    print("--- %s: exit code %s" % (label, run.returncode))
    check(intact(), label + ": what is there now is intact")
    check_kept(label, run, err.decode(), directory)


def changed_before_rename(label, directory, change, intact, fault):
    env = dict(os.environ, LD_PRELOAD=shim, FOSLS_FAULT_PATH=directory, FOSLS_FAULT_STOP_AT="1")
    env.update(fault)
    run = subprocess.Popen(command(directory), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                           env=env)
    wait_stopped(run.pid)
    change()
    os.kill(run.pid, signal.SIGCONT)
    err = run.communicate()[1]
    print("--- %s: exit code %s" % (label, run.returncode))
    check(intact(), label + ": what is there now is intact")
    check_kept(label, run, err.decode(), directory)


# while the run computes: a regular file where there was nothing
changed_while_computing("a file made while the run computes", "new_path",
                        lambda: file_with("new_path", "the user's file\n"),
                        lambda: content("new_path") == "the user's file\n")


# while the run computes: the program's directory replaced by the user's
def by_users_directory(directory):
    def change():
        os.rename(directory, directory + ".moved")
        os.mkdir(directory)
        file_with(os.path.join(directory, "mine.txt"), "the user's\n")
    return change


rc, out, err = execute(command("written"))
check(rc == 0, "a run into 'written': exit code 0")
changed_while_computing("the directory replaced by the user's while the run computes", "written",
                        by_users_directory("written"),
                        lambda: content("written/mine.txt") == "the user's\n"
                        and sorted(os.listdir("written")) == ["mine.txt"]
                        and content("written.moved/summary.json") is not None)


# while the run computes: a directory of the user's made in the program's
# directory under the name of an output file
rc, out, err = execute(command("taken"))
check(rc == 0, "a run into 'taken': exit code 0")
changed_while_computing("a directory named summary.json made while the run computes", "taken",
                        lambda: (os.remove("taken/summary.json"),
                                 os.mkdir("taken/summary.json"),
                                 file_with("taken/summary.json/mine.txt", "the user's\n")),
                        lambda: content("taken/summary.json/mine.txt") == "the user's\n")


# just before the rename that publishes: the directory moved away and a
# regular file in its place
def by_file(directory):
    def change():
        os.rename(directory, directory + ".moved")
        file_with(directory, "the user's file\n")
    return change


for label, fault in [("with RENAME_EXCHANGE", {}),
                     ("two renames", {"FOSLS_FAULT_NO_EXCHANGE": "1"})]:
    directory = "swap_" + ("exchange" if not fault else "renames")
    rc, out, err = execute(command(directory))
    check(rc == 0, "a run into '%s': exit code 0" % directory)
    changed_before_rename("a file made just before the rename, " + label, directory,
                          by_file(directory),
                          lambda: content(directory) == "the user's file\n"
                          and content(directory + ".moved/summary.json") is not None, fault)

# a new directory: a file made just before the rename
changed_before_rename("a file made just before the first rename", "first",
                      lambda: file_with("first", "the user's file\n"),
                      lambda: content("first") == "the user's file\n", {})

# killed as it undoes the rename (call 1: the exchange, or the exchange
# that fails and call 2 the first of the two renames; the next call undoes
# it), then the next run
for label, fault in [("with RENAME_EXCHANGE", {"FOSLS_FAULT_KILL_AT": "2"}),
                     ("two renames", {"FOSLS_FAULT_NO_EXCHANGE": "1", "FOSLS_FAULT_KILL_AT": "3"})]:
    label = "killed as it undoes the rename, " + label
    directory = "undo_" + ("exchange" if len(fault) == 1 else "renames")
    rc, out, err = execute(command(directory))
    env = dict(os.environ, LD_PRELOAD=shim, FOSLS_FAULT_PATH=directory, FOSLS_FAULT_STOP_AT="1")
    env.update(fault)
    run = subprocess.Popen(command(directory), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                           env=env)
    wait_stopped(run.pid)
    by_file(directory)()
    os.kill(run.pid, signal.SIGCONT)
    run.communicate()
    print("--- %s: exit code %s" % (label, run.returncode))
    rc, out, err = execute(command(directory))
    check(run.returncode == -9 and rc == 1
          and one_error_line(err, "Output/Directory", "exists and is not a directory"),
          label + ": the next run: exit code 1, one line naming Output/Directory")
    check(content(directory) == "the user's file\n"
          and content(directory + ".moved/summary.json") is not None,
          label + ": the file is back, the directory moved away intact")
    check(leftovers(directory) == [], label + ": no staging directory or lock file left")
finish()
