#!/usr/bin/env python3
# A run stopped by SIGTERM or SIGINT (a batch system's time limit, Ctrl-C)
# keeps what it finished (Interruption, exit code 4).
#  - The adaptive Hertz contact (prm/hertz_adaptive.prm), SIGTERM once the
#    screen says "Adaptive step 2" (steps 0 and 1 finished, step 2 under
#    way), on 1 and on 2 MPI processes (the signal sent to every process,
#    as a batch system's time limit does; where it is heeded, after the
#    next iteration or phase, decides how many steps are finished): exit
#    code 4 with one line on stderr naming the signal; the output directory
#    holds the finished steps as one consistent set: summary.json has
#    "interrupted": "SIGTERM", its adaptive_steps and adaptive_steps.csv
#    the finished steps (at least 2, all converged), contact_000k.csv for
#    exactly those steps, contact.csv equal to the last of them, and
#    convergence.csv that step's iterations; no staging directory is left.
#  - The same with SIGINT on one process.
#  - SIGTERM during the Coulomb fixed point of load step 2 of
#    prm/sliding_block.prm (6 levels): exit code 4, one line naming the
#    signal and the load step, and at most one more Tresca problem finished
#    after the signal (the fixed point stops with the problem it stopped).
#  - SIGTERM before the first solve finished (as soon as the screen shows
#    the first phase): exit code 4, one line saying that nothing was
#    written, and no output directory.
# ctest: sanitize
import json
import os
import signal
import subprocess
import sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, command_line, finish

exe, source = sys.argv[1], sys.argv[2]
scene = os.path.join(source, "prm", "hertz_adaptive.prm")


def interrupted(name, trigger, sig=signal.SIGTERM, processes=1, run_scene=None, settings=(),
                armed_by=None, after=None):
    """Run the adaptive scene (or @p run_scene with @p settings) into ./name,
    send @p sig once a screen line starts with @p trigger (after one that
    starts with @p armed_by, if given); return (exit code, stderr lines).
    The screen lines after the trigger go to the list @p after, if given."""
    command = command_line(exe, run_scene or scene, ["Output/Directory=" + name,
                                                     "Output/Write vtu=false"] + list(settings),
                           processes)
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True, start_new_session=True)
    armed = armed_by is None
    for line in process.stdout:
        armed = armed or line.startswith(armed_by)
        if armed and line.startswith(trigger):
            # on several processes the signal goes to every process, as a
            # batch system sends it (mpirun itself, signalled, ends the job
            # with its own exit code)
            targets = [process.pid]
            if processes > 1:
                children = subprocess.run(["pgrep", "-P", str(process.pid)],
                                          capture_output=True, text=True).stdout
                targets = [int(p) for p in children.split()]
            for pid in targets:
                os.kill(pid, sig)
            break
    rest = process.stdout.read()
    if after is not None:
        after.extend(rest.splitlines())
    err = process.stderr.read()
    try:
        code = process.wait(timeout=300)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        code = process.wait()
    return code, err.strip().splitlines()


def check_finished_steps(name, what, signal_name):
    path = lambda f: os.path.join(name, f)
    try:
        with open(path("summary.json")) as f:
            summary = json.load(f)
    except (OSError, ValueError):
        summary = {}
    steps = summary.get("adaptive_steps") or []
    n = len(steps)
    print("%s: adaptive_stop '%s'" % (what, summary.get("adaptive_stop")))
    check(summary.get("interrupted") == signal_name and n >= 2
          and all(s.get("converged") for s in steps),
          what + ": summary.json says interrupted, with the finished (converged) steps")
    with open(path("adaptive_steps.csv")) as f:
        rows = [l for l in f.read().splitlines()[1:] if l]
    tables = sorted(f for f in os.listdir(name) if f.startswith("contact_0"))
    check(len(rows) == n and tables == ["contact_%04d.csv" % k for k in range(n)],
          what + ": adaptive_steps.csv and contact_000k.csv of exactly the finished steps")
    with open(path("contact.csv")) as f, open(path(tables[-1])) as g:
        same = f.read() == g.read()
    with open(path("convergence.csv")) as f:
        convergence = [l for l in f.read().splitlines()[1:] if l]
    check(same and len(convergence) == steps[-1]["iterations"] + 1
          and summary.get("dofs") == steps[-1]["dofs"],
          what + ": contact.csv, convergence.csv and summary.json are the last finished step's")
    leftovers = [f for f in os.listdir(".") if f.startswith("." + name)]
    check(not leftovers, what + ": no staging directory left")


for processes in (1, 2):
    what = "SIGTERM in step 2, %d process(es)" % processes
    name = "term_%d" % processes
    code, err = interrupted(name, "Adaptive step 2", processes=processes)
    check(code == 4 and len(err) == 1 and "interrupted by SIGTERM in adaptive step" in err[0],
          what + ": exit code 4, one line naming the signal")
    check_finished_steps(name, what, "SIGTERM")

code, err = interrupted("int_1", "Adaptive step 2", signal.SIGINT)
check(code == 4 and len(err) == 1 and "interrupted by SIGINT" in err[0],
      "SIGINT in step 2: exit code 4, one line naming the signal")
check_finished_steps("int_1", "SIGINT in step 2", "SIGINT")

# a Coulomb fixed point stops with the Tresca problem the signal stopped
# (not running its remaining problems one iteration each); the signal may
# reach the program a problem later than the line it follows
screen = []
code, err = interrupted("coulomb", "Coulomb fixed point: Tresca problem 1,",
                        run_scene=os.path.join(source, "prm", "sliding_block.prm"),
                        settings=["Geometry/Levels=6"], armed_by="Load step 2", after=screen)
later = [l for l in screen if l.startswith("Coulomb fixed point: Tresca problem")]
print("SIGTERM in a Coulomb fixed point: %s" % (err[0] if err else "no line on stderr"))
check(code == 4 and len(err) == 1 and "interrupted by SIGTERM in load step 2" in err[0]
      and len(later) <= 1,
      "SIGTERM in a Coulomb fixed point: exit code 4, one line naming the signal, at most one "
      "more Tresca problem finished")

code, err = interrupted("early", "Setup: mesh")
check(code == 4 and len(err) == 1 and "before the first solve finished: no output written"
      in err[0] and not os.path.exists("early"),
      "SIGTERM before the first solve: exit code 4, one line, no output directory")
finish()
