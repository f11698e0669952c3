#!/usr/bin/env python3
# Known problem (DISABLED in tests/CMakeLists.txt until the library is
# fixed; the .output is what a fixed library must print): the round-off
# floor detection of Monitor::report() ends slowly converging runs early
# and reports them converged. It stops when the last 4 corrections are
# all below 1e-6 of the first and none is below half of the smallest
# before them, which a steady decrease slower than 2x per 4 iterations
# also satisfies.
#  - The square on the tilted obstacle (prm/square.prm, 5 levels, Data/
#    Obstacle normal = 0.3; -1) from a zero start (Solver/Initial guess =
#    zero), default solver: measured "Converged after 51 iterations
#    (corrections at their round-off floor)" while the corrections still
#    fell steadily (rate 0.97 per cycle, 0.88 per iteration); the force is
#    7.7e-6 off the active set solver's, the KKT residual 1.1e-10.
#  - The square (5 levels, lambda = 1) from a zero start with
#    Solver/Tolerance = 1e-10: stopped at the "floor" after 23 iterations
#    with the force 1.8e-7 off (from the coarse start the same solver
#    reaches 1e-11).
#  - (Also the half disc, 3 levels, zero start: 109 iterations, force
#    4.7e-5 off; not run here, 160 s.)
# Reproduction: fosls-contact prm/square.prm --set Geometry/Levels=5
#   --set "Data/Obstacle normal=0.3; -1" --set "Solver/Initial guess=zero"
# Checks: a run that reports convergence has the force of the active set
# solver to 1e-7 relative (tolerance 1e-8 resp. 1e-10).
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
finish()
