#!/usr/bin/env python3
# The round-off floor detection must not end slowly converging runs
# early. A rule that stops when the last 4 corrections are all below 1e-6
# of the first and none below half of the smallest before them is also met
# by a steady slow decrease:
#  - the square on the tilted obstacle (prm/square.prm, 5 levels, Data/
#    Obstacle normal = 0.3; -1) from a zero start: "converged" after 51
#    iterations with the force 7.7e-6 off the active set solver's;
#  - the square (5 levels, lambda = 1) from a zero start with
#    Solver/Tolerance = 1e-10: stopped after 23 iterations, force 1.8e-7 off.
# The floor is therefore an estimate from the iterate (ConstrainedQP::
# round_off_correction), stagnation counts only within 1000x of it, and
# the CG of the default solver runs to a residual reduction of 1e-3:
# measured 5 iterations each, forces within 1e-9.
# A slow steady creep must not end as "converged" by the tolerance (the
# correction, not the error, below it) or by the stagnation check: the
# plain W-cycle (Krylov steps = 0) from a zero start on the square with
# contact at one end (gap 0.02 (1 - x), 4 levels) creeps at about 0.99 per
# cycle; judged by the correction alone it would stop after 1070
# iterations with the force 8.5e-6 off. Both stops take the rate into account (the
# error is about rho/(1-rho) times the correction) and stagnation needs a
# correction that went up: measured 1368 iterations, J equal to all
# digits, force 1.2e-7.
# Checks: a run that reports convergence has the force of the active set
# solver to 1e-7 relative (tolerance 1e-8 resp. 1e-10); the creeping run
# J to 1e-10 and the force to 1e-6.
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, relative_difference

R = Runner(sys.argv)
for label, scene in [
        ("tilted, zero start", ["Geometry/Levels=5",
                                "Data/Obstacle normal=0.3; -1",
                                "Solver/Initial guess=zero"]),
        ("square, zero start, tolerance 1e-10",
         ["Geometry/Levels=5", "Solver/Initial guess=zero",
          "Solver/Tolerance=1e-10"])]:
    reference = R.run("prm/square.prm", scene + ["Solver/Type=active set"],
                      "reference")
    run = R.run("prm/square.prm", scene, "multigrid")
    check(run.ok() and run["converged"] is True, label + ": converged")
    check(relative_difference(run["contact_force"],
                              reference["contact_force"]) <= 1e-7,
          label + ": |F - F_ref| / |F_ref| <= 1e-7")

label = "plain W-cycle creeping at 0.99, zero start"
scene = ["Geometry/Levels=4", "Data/Gap=0.02*(1 - x)"]
reference = R.run("prm/square.prm", scene + ["Solver/Type=active set"], "reference")
run = R.run("prm/square.prm", scene + ["Solver/Krylov steps=0", "Solver/Cycle=W",
                                       "Solver/Initial guess=zero",
                                       "Solver/Max iterations=3000"], "plain_creep")
check(run.ok() and run["converged"] is True, label + ": converged")
check(relative_difference(run["functional"], reference["functional"]) <= 1e-10,
      label + ": |J - J_ref| / J_ref <= 1e-10")
check(relative_difference(run["contact_force"], reference["contact_force"]) <= 1e-6,
      label + ": |F - F_ref| / |F_ref| <= 1e-6")
finish()
