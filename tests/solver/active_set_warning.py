# Solver/Type = active set warns in one line on the screen, before the
# solve, where its sparse direct solves will take long
# (SolverChoice::active_set_warning: above 75,000 DoFs in 2D and 9,000 in
# 3D), and says nothing below. The square on 7 levels (25,090 DoFs) runs
# without the warning; on 8 levels (99,330 DoFs) the warning comes in the
# phase "Setup: solver", and the run is killed there (its solve takes 12 to
# 30 s); the cube on 3 levels (1,095 DoFs) runs without it, on 5 levels
# (53,000 DoFs, a solve of minutes) it warns and is killed.
import os
import signal
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, finish

exe, source = sys.argv[1], sys.argv[2]


def warning_of(scene, levels, complete):
    """The warning line of a run (or None); the run goes to its end if
    @p complete, else it is killed at the warning or as the phase
    'Setup: solver' ends (the warning comes before that line)."""
    command = [exe, os.path.join(source, "tests/scenes", scene), "--set",
               "Geometry/Levels=%d" % levels, "--set", "Solver/Type=active set", "--set",
               "Output/Directory=out_%s_%d" % (scene[:-4], levels)]
    p = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    warning = None
    for line in p.stdout:
        text = line.decode()
        if text.startswith("Warning: Solver/Type = active set"):
            warning = text.strip()
        if not complete and (warning or text.startswith("Setup: solver ...")):
            p.kill()
            break
    p.wait()
    if complete:
        check(p.returncode == 0, "%s on %d levels: runs to its end" % (scene, levels))
    return warning


for scene, levels, warns in [("square.prm", 7, False), ("square.prm", 8, True),
                             ("cube3d.prm", 3, False), ("cube3d.prm", 5, True)]:
    warning = warning_of(scene, levels, not warns)
    print("--- %s, %d levels: %s" % (scene, levels, warning))
    if warns:
        check(warning is not None and " DoFs in " in warning and " s per iteration" in warning,
              "%s on %d levels: one line of warning, with the DoFs and the time per iteration"
              % (scene, levels))
    else:
        check(warning is None, "%s on %d levels: no warning" % (scene, levels))
finish()
