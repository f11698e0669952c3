# Two runs into one Output/Directory at the same time: the second fails at
# once (exit code 1, one line naming Output/Directory), the first ends
# normally with its own files (without the lock both would exit with 0 and
# the directory hold one run's .vtu next to the other's summary.json). The
# first run (the square on 6 levels) is stopped with SIGSTOP as soon as it
# prints its scene, after it locked the directory, and continued after the
# second run ended, so the test does not depend on timing. The same with
# the lock file removed while the first run is stopped: the second run
# finds the first one's staging directory in use and leaves it alone.
# ctest: timeout=120
import os
import re
import signal
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, execute, finish, leftovers, one_error_line

exe, source = sys.argv[1], sys.argv[2]
scene = os.path.join(source, "tests/scenes/square.prm")
directory = "shared"


def command(levels):
    return [exe, scene, "--set", "Output/Directory=" + directory,
            "--set", "Geometry/Levels=%d" % levels]


def levels_written():
    with open(os.path.join(directory, "summary.json")) as f:
        summary = f.read()
    with open(os.path.join(directory, "used_parameters.prm")) as f:
        used = f.read()
    return (int(re.search(r'"levels": (\d+)', summary).group(1)),
            int(re.search(r"set Levels\s*=\s*(\d+)", used).group(1)))


first = subprocess.Popen(command(6), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
for line in iter(first.stdout.readline, b""):
    if line.startswith(b"Scene:"):
        break
os.kill(first.pid, signal.SIGSTOP)
rc, out, err = execute(command(2), timeout=120)
print("--- second run: exit code %s" % rc)
check(rc == 1 and one_error_line(err, "Output/Directory", "another run"),
      "the second run: exit code 1, one line naming Output/Directory")
check("Scene:" not in out, "the second run stopped before its set-up")
os.kill(first.pid, signal.SIGCONT)
out, err = first.communicate()
print("--- first run: exit code %s" % first.returncode)
check(first.returncode == 0 and err == b"", "the first run: exit code 0, nothing on stderr")
check(levels_written() == (6, 6), "the directory holds the first run's files")
rc, out, err = execute(command(2), timeout=120)
check(rc == 0 and levels_written() == (2, 2), "a run after it: exit code 0, its files")
check(leftovers(directory) == [], "no staging directory or lock file left")

# the lock file removed while a run is running: a second run still fails,
# and leaves the running run's staging directory alone
first = subprocess.Popen(command(6), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
for line in iter(first.stdout.readline, b""):
    if line.startswith(b"Scene:"):
        break
os.kill(first.pid, signal.SIGSTOP)
os.unlink("." + directory + ".lock")
rc, out, err = execute(command(2), timeout=120)
print("--- lock file removed, second run: exit code %s" % rc)
check(rc == 1 and one_error_line(err, "Output/Directory", "another run"),
      "lock file removed: the second run: exit code 1, one line naming Output/Directory")
check(os.path.isdir(".%s.staging-%d" % (directory, first.pid)),
      "lock file removed: the first run's staging directory is still there")
os.kill(first.pid, signal.SIGCONT)
out, err = first.communicate()
check(first.returncode == 0 and err == b"" and levels_written() == (6, 6),
      "lock file removed: the first run: exit code 0, its files")
check(leftovers(directory) == [], "lock file removed: no staging directory or lock file left")
finish()
