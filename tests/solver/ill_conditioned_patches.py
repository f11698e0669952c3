# The 3D mesh file of prm/quarter_ball_file.prm refined to 4 levels: its
# cells differ in size by a factor 15, and the vertex patch matrices of the
# smoother are badly conditioned (tests/unit/spd_inverse: condition number
# 1.3e9 scaled to a unit diagonal). The patch inverses come from Cholesky
# factors (invert_spd), which keeps them positive definite; an inverse by
# elimination is indefinite there, and the first cycle raises J by orders
# of magnitude (the run ends as diverged).
#  - the default solver (Newton-accelerated cycle): converges, J never
#    increases, every iterate feasible, and the Hertz pressure error is
#    below the 3-level run's (0.132);
#  - the plain W(3,3) cycle, 3 cycles from a zero start: no energy
#    increase, J decreasing.
# ctest: timeout=600 mpirun cost=45
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, describe, finish, rounded

R = Runner(sys.argv)
common = ["Geometry/Levels=4", "Output/Verbose=false"]

newton = R.run("prm/quarter_ball_file.prm", common, name="newton")
describe(newton, "default solver", keys=("converged",))
check_monotone_feasible(newton, "default solver")
check(newton["converged"] is True, "default solver: converged")
error = newton["hertz"]["pressure_error"]
print("default solver: Hertz pressure error %s" % rounded(error, 2))
check(error < 0.132, "default solver: pressure error below the 3-level run's 0.132")

plain = R.run("prm/quarter_ball_file.prm",
              common + ["Solver/Krylov steps=0", "Solver/Initial guess=zero",
                        "Solver/Max iterations=3"], name="plain")
describe(plain, "plain cycle", keys=("iterations", "stop_reason"))
check(plain["stop_reason"] == "iteration limit", "plain cycle: ran its 3 cycles")
check_monotone_feasible(plain, "plain cycle")
J = [r["functional"] for r in plain.history]
check(len(J) == 4 and all(J[k] < J[k - 1] for k in range(1, 4)),
      "plain cycle: J decreases in every cycle")
finish()
