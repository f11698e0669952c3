#!/usr/bin/env python3
# The Coulomb fixed point with inexact Tresca problems (Friction/Tresca
# accuracy = 0.01, doc/method.md section 7.7) on prm/sliding_block.prm, 4
# levels, against the exact fixed point (the default):
#  - every step converges, J never increases within a Tresca problem (also
#    across the run that solves the accepted problem on to Solver/Tolerance);
#  - the same stick and slip vertices, forces to 1e-7 of the normal force and
#    J to 1e-7 in every step;
#  - as many Tresca problems, and fewer Newton steps in all (measured: 98
#    against 126);
#  - load_steps.csv's iterations are the accepted problem's, both runs.
# ctest: timeout=300 cost=6
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, monotone, newton_steps, same_steps

R = Runner(sys.argv)
SCENE = "prm/sliding_block.prm"
LEVELS = ["Geometry/Levels=4"]
exact = R.run(SCENE, LEVELS, "exact")
inexact = R.run(SCENE, LEVELS + ["Friction/Tresca accuracy=0.01"], "inexact")
for run, name in ((exact, "exact"), (inexact, "inexact")):
    check(run.ok() and monotone(run) and all(r["converged"] for r in run["load_steps"] or []),
          "%s: every step converged, J never increases" % name)
check(same_steps(exact, inexact, 1e-7),
      "inexact: the exact fixed point's stick and slip vertices, forces and J (to 1e-7)")
a, b = newton_steps(exact), newton_steps(inexact)
print("Tresca problems: exact %d, inexact %d; Newton steps in all: exact %d, inexact %d" % (
    len(a), len(b), sum(a), sum(b)))
check(len(a) == len(b) and sum(b) < sum(a),
      "inexact: as many Tresca problems, fewer Newton steps")
continued = inexact.screen.count("solved on to Solver/Tolerance")
check(continued >= 1 and sum((r["iterations"] for r in inexact["load_steps"]), 0) >= 5,
      "inexact: accepted problems solved on to Solver/Tolerance (%d)" % continued)
finish()
