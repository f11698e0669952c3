#!/usr/bin/env python3
# The default stop of the monotone multigrid, Solver/Stopping criterion =
# auto: discretization accuracy (the estimated algebraic error below 0.1
# sqrt(J), J the functional's estimate of the squared discretization error),
# unless the scene sets a Tolerance of its own; tolerance for the other
# solvers. Each shipped scene of moderate size runs with the default and with
# Stopping criterion = tolerance (Tolerance 1e-8). Checks per scene:
#  - the default stops by discretization accuracy, converged;
#  - J - J_tol <= 0.1^2 J (the criterion's promise: the algebraic error,
#    squared, below 1% of the squared discretization error);
#  - the contact force differs from the tolerance run's by less than 0.1
#    times the relative error estimate (the force to the accuracy the
#    discretization gives it); measured 1e-8 relative or less;
#  - no more iterations than the tolerance run, whose last iterations sit at
#    the round-off floor on several scenes (the steel cylinder: 8 against 2).
# And: a scene that sets Solver/Tolerance = 1e-10 stops by that tolerance;
# projected Gauss-Seidel, for which discretization accuracy is refused,
# runs with auto (to the tolerance; it converges slowly, so 20 sweeps).
# ctest: cost=21
import os
import sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, relative_difference

R = Runner(sys.argv)
SCENES = [("square", "prm/square.prm"), ("half disc", "prm/hertz.prm"),
          ("punch (Gmsh file)", "prm/punch.prm"), ("cube", "prm/cube3d.prm"),
          ("3D Hertz block", "prm/ball3d.prm"),
          ("steel cylinder", "prm/steel_cylinder.prm")]
for label, prm in SCENES:
    name = prm.split("/")[1].split(".")[0]
    default = R.run(prm, name=name + "_default", stop=None)
    tolerance = R.run(prm, name=name + "_tolerance")
    print("--- %s: %d iterations (tolerance: %d)"
          % (label, default["iterations"] or -1, tolerance["iterations"] or -1))
    check(default.ok() and tolerance.ok(), label + ": both runs exit 0, nothing on stderr")
    check(default["converged"] is True
          and default["stop_reason"] == "discretization accuracy",
          label + ": the default stops by discretization accuracy")
    J, J_tol = default["functional"], tolerance["functional"]
    check(J - J_tol <= 0.1 ** 2 * J, label + ": J - J_tol <= 0.1^2 J")
    estimate = default["relative_error_estimate"]
    check(relative_difference(default.force, tolerance.force) <= 0.1 * estimate,
          label + ": force of the tolerance run to 0.1 x the relative error estimate")
    check(default["iterations"] <= tolerance["iterations"],
          label + ": no more iterations than to the tolerance")

print("--- a Tolerance of the scene's own, projected Gauss-Seidel")
own = R.run("prm/square.prm", ["Solver/Tolerance=1e-10"], "own_tolerance", stop=None)
check(own.ok() and own["stop_reason"] in ("tolerance", "round-off floor"),
      "square, Solver/Tolerance = 1e-10: stops by the tolerance (or its round-off floor)")
pgs = R.run("prm/square.prm", ["Geometry/Levels=2", "Solver/Type=projected gauss seidel",
                               "Solver/Max iterations=20"], "pgs", stop=None)
check(pgs["stop_reason"] in ("tolerance", "iteration limit") and "Stopping" not in pgs.stderr,
      "projected Gauss-Seidel with auto: not refused, runs to the tolerance "
      "(stopped here by Max iterations = 20)")
finish()
