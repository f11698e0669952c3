#!/usr/bin/env python3
# Contact zones that end inside the contact boundary (curved obstacle,
# Hertz). Until Nov 2026 the default solver stagnated here (rate 0.98-0.99
# per cycle, 30 iterations not converged): at most 10 CG steps per Newton
# step were too few, because the truncated linear cycle is a weaker
# preconditioner when the active set ends inside the contact boundary
# (17-38 preconditioned CG steps to a residual reduction of 1e-3 instead
# of 2-3 on the flat square). The CG now stops at that reduction (at most
# Solver/Krylov steps = 50), and a DoF at its bound whose multiplier is
# negative is left free in the Newton problem.
#  - the square (prm/square.prm, 5 levels) on a cylinder of radius 1,
#    Data/Gap = 1 - sqrt(1 - (x - 0.5)^2);
#  - the half disc (prm/hertz.prm, 4 levels, 24962 DoFs): measured 6
#    iterations, about 40 s.
#  - the half disc with 5 levels (99,074 DoFs), without a reference run
#    (the active set solver takes about 30 s there): the contact zone grows
#    by about a vertex per Newton round, and with at most 3 rounds per
#    Newton step the default solver took 20 iterations (264 cycles, 26.6 s;
#    session 4, by hand); with up to 20 rounds 6 iterations (111 cycles,
#    11 s).
# Checks: the first two converge within 30 iterations to the active set
# solver's force (1e-8 relative); the third within 8 iterations with a KKT
# residual below 1e-8.
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, relative_difference

R = Runner(sys.argv)
for label, prm, scene in [
        ("cylinder R = 1, 5 levels", "prm/square.prm",
         ["Geometry/Levels=5", "Data/Gap=1 - sqrt(1 - (x-0.5)^2)"]),
        ("half disc, 4 levels", "prm/hertz.prm", ["Geometry/Levels=4"])]:
    reference = R.run(prm, scene + ["Solver/Type=active set"], "reference")
    run = R.run(prm, scene + ["Solver/Max iterations=30"], "multigrid")
    check(run.ok() and run["converged"] is True and run["iterations"] <= 30,
          label + ": converged within 30 iterations")
    check(relative_difference(run["contact_force"],
                              reference["contact_force"]) <= 1e-8,
          label + ": |F - F_ref| / |F_ref| <= 1e-8")

label = "half disc, 5 levels"
run = R.run("prm/hertz.prm", ["Geometry/Levels=5", "Solver/Max iterations=30"],
            "multigrid_5_levels")
check(run.ok() and run["converged"] is True and run["iterations"] <= 8,
      label + ": converged within 8 iterations")
check(run["kkt_residual"] is not None and run["kkt_residual"] <= 1e-8,
      label + ": KKT residual <= 1e-8")
finish()
