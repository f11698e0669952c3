# Two runs at the same time, one into a directory inside the other's
# Output/Directory: the later one is refused at once (exit code 1, one line
# naming Output/Directory and the other run's directory), the earlier one
# ends normally with its files; both orders (the inner run first, the
# outer run first). (Without the check a run into out/sub while a run into
# out runs ends with exit code 0, and the outer run's publication, which
# replaces out, takes out/sub with it.) The running run
# (the square on 6 levels) is stopped with SIGSTOP as soon as it prints its
# scene, after it locked its directory, and continued after the other run
# ended, so the test does not depend on timing. Runs one after the other
# into such directories are fine: the inner directory is carried over as
# a directory of the user's.
import os
import re
import signal
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, execute, finish, leftovers, one_error_line

exe, source = sys.argv[1], sys.argv[2]
scene = os.path.join(source, "tests/scenes/square.prm")


def command(directory, levels):
    return [exe, scene, "--set", "Output/Directory=" + directory,
            "--set", "Geometry/Levels=%d" % levels, "--set", "Output/Write vtu=false"]


def levels_written(directory):
    try:
        with open(os.path.join(directory, "summary.json")) as f:
            return int(re.search(r'"levels": (\d+)', f.read()).group(1))
    except (OSError, AttributeError):
        return None


def stopped_run(directory):
    """A run on 6 levels into @p directory, stopped after its scene line."""
    run = subprocess.Popen(command(directory, 6), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    for line in iter(run.stdout.readline, b""):
        if line.startswith(b"Scene:"):
            break
    os.kill(run.pid, signal.SIGSTOP)
    return run


for label, running, later, cause in [
        ("the outer run first", "outer", "outer/sub", "lies inside"),
        ("the inner run first", "inner/sub", "inner", "holds"),
        ("the inner run first, deeper", "deep/a/b/sub", "deep", "holds")]:
    first = stopped_run(running)
    rc, out, err = execute(command(later, 2), timeout=120)
    print("--- %s: the later run: exit code %s" % (label, rc))
    check(rc == 1 and one_error_line(err, "Output/Directory", cause, "still running"),
          label + ": the later run: exit code 1, one line naming Output/Directory")
    check("Scene:" not in out, label + ": the later run stopped before its set-up")
    os.kill(first.pid, signal.SIGCONT)
    out, err = first.communicate()
    check(first.returncode == 0 and err == b"" and levels_written(running) == 6,
          label + ": the running run: exit code 0, its files")
    check(leftovers(running) == [] and leftovers(later) == [],
          label + ": no staging directory or lock file left")

# one after the other: the inner directory is kept by the outer run
for directory in ("outer/sub", "outer"):
    rc, out, err = execute(command(directory, 2), timeout=120)
    check(rc == 0 and levels_written(directory) == 2, "then a run into %s: exit code 0, its "
          "files" % directory)
check(levels_written("outer/sub") == 2, "the inner directory is kept by the outer run")
finish()
