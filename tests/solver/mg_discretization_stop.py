#!/usr/bin/env python3
# The stopping criterion "discretization accuracy": stop when the
# estimated algebraic error rho/(1-rho) |dx|_A / sqrt(2) is below
# Discretization fraction (0.1) times sqrt(J), J estimating the squared
# discretization error. The criterion holds only once the active set stayed
# the same for an iteration, with the largest rate since it last changed
# (with the rate of the last iterations whatever the active set did, the
# half disc, prm/hertz.prm, 4 levels, Grading 2, stopped after 2
# iterations with J = 6.45e-6 against 6.41e-7 at convergence): measured 3 iterations (4 to Tolerance 1e-8), J equal to
# the converged J to 6 digits.
# Checks, for the half disc and the square (5 levels) against the active
# set solver: converged; J <= (1 + 0.1^2) J_ref (the criterion's promise:
# J - J* = |e|_A^2 / 2 <= 0.1^2 J / 2, with margin); the stop came before the
# tolerance run's (fewer or as many iterations).
# ctest: cost=10
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, describe, finish

R = Runner(sys.argv)
for label, prm, scene in [
        ("half disc, 4 levels", "prm/hertz.prm", ["Geometry/Grading=1", "Geometry/Levels=4"]),
        ("square, 5 levels", "prm/square.prm", ["Geometry/Levels=5"])]:
    print("--- " + label)
    reference = R.run(prm, scene + ["Solver/Type=active set"],
                      label.split(",")[0].replace(" ", "_") + "_active_set")
    tolerance = R.run(prm, scene, label.split(",")[0].replace(" ", "_") + "_tolerance")
    run = R.run(prm, scene + ["Solver/Stopping criterion=discretization accuracy"],
                label.split(",")[0].replace(" ", "_") + "_discretization")
    describe(run, "discretization stop")
    check(run.ok() and reference.ok() and tolerance.ok(),
          label + ": exit code 0, nothing on stderr (3 runs)")
    check(run["converged"] is True, label + ": converged")
    check(run["functional"] <= (1 + 0.1 ** 2) * reference["functional"],
          label + ": J <= (1 + 0.1^2) J of the active set solver")
    check(run["iterations"] <= tolerance["iterations"],
          label + ": no more iterations than with Tolerance = 1e-8 (%d)"
          % tolerance["iterations"])
finish()
