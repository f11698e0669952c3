#!/usr/bin/env python3
# A start that is already the exact solution ends the run at once.
# The square (prm/square.prm, 5 levels) with an initial gap of 0.02 > push
# 0.01 has no contact; its exact solution, the rigid translation by
# (0, -0.01) with zero stress, is discrete, so J* = 0 and the default
# start (the level-1 solution, interpolated) is already exact. Every
# correction is then round-off (~1e-16). A stopping rule that measures
# corrections relative to the first one (itself round-off) is never met
# here ("NOT converged after 200 iterations"); a correction within 10x of
# ConstrainedQP::round_off_correction ends the run: measured 1 iteration
# for each of the three solvers below.
# Reproduction: fosls-contact prm/square.prm --set Geometry/Levels=5
#   --set Data/Gap=0.02
# Checks: default solver, plain cycle (Krylov steps = 0) and nested
# iteration start converge within 10 iterations with force 0.
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish

R = Runner(sys.argv)
scene = ["Geometry/Levels=5", "Data/Gap=0.02", "Solver/Max iterations=30"]
for label, solver in [("default", []),
                      ("plain cycle", ["Solver/Krylov steps=0"]),
                      ("nested iteration start",
                       ["Solver/Initial guess=nested iteration"])]:
    run = R.run("prm/square.prm", scene + solver, label.split()[0])
    check(run.ok(), label + ": exit code 0, nothing on stderr")
    check(run["converged"] is True and run["iterations"] <= 10,
          label + ": converged within 10 iterations")
    check(run.force == 0, label + ": contact force 0")
finish()
