# An Output/Directory that cannot be used is found before the set-up, in
# one line naming Output/Directory (not after the solve, as "filesystem
# error: cannot remove all: Permission denied"). The tests
# run as root, whom permission bits do not stop, so the directories are
# unusable otherwise: a path under a regular file, a directory in /proc
# (where no file can be made), the current directory (the run would move
# it), a directory holding a directory under the name of an output file
# (which the run could neither keep beside its file nor remove). Each run
# must fail with exit code 1 and one line on stderr, without
# printing the scene (the first line of the set-up), and make nothing.
# ctest: timeout=120
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, execute, finish

exe, source = sys.argv[1], sys.argv[2]
scene = os.path.join(source, "tests/scenes/square.prm")
with open("a_file", "w") as f:
    f.write("not a directory\n")
os.mkdir("work")
# a directory of the user's under the name of an output file
os.makedirs("taken/summary.json")
before = sorted(os.listdir("."))

for label, directory, cause in [
        ("under a regular file", "../a_file/out", "is not a directory"),
        ("in /proc", "/proc/fosls-contact-test-output", "cannot create"),
        ("the current directory", ".", "contains the current directory"),
        ("a regular file", "../a_file", "is not a directory"),
        ("holding a directory named summary.json", "../taken",
         "holds a directory 'summary.json' under the name of an output file")]:
    os.chdir("work")
    rc, out, err = execute([exe, scene, "--set", "Output/Directory=" + directory],
                           timeout=120)
    os.chdir("..")
    lines = err.splitlines()
    print("--- %s: exit code %s" % (label, rc))
    check(rc == 1 and len(lines) == 1 and "parameter 'Output/Directory' = '%s'" % directory
          in lines[0] and cause in lines[0],
          label + ": exit code 1, one line naming Output/Directory and the cause")
    check("Scene:" not in out, label + ": found before the set-up")
    check(sorted(os.listdir(".")) == before and os.listdir("work") == []
          and os.listdir("taken") == ["summary.json"], label + ": nothing made")
finish()
