# A monotone solver never increases J, so a run whose J grows over an
# iteration ends there, as not converged (exit code 2, "converged": false,
# stop_reason "diverged"), with one line on stderr that names the iteration
# and both values of J, instead of iterating on towards an overflow.
# The case: the 3D mesh file of prm/quarter_ball_file.prm refined to 4
# levels (zero start), where the multigrid hierarchy's first cycle raises J
# from about 4e-4 to about 1e7, while the projected Gauss-Seidel method
# lowers J on the same mesh. Without the check J grows to 1e81 and beyond.
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish

R = Runner(sys.argv)
common = ["Geometry/Levels=4", "Solver/Initial guess=zero", "Solver/Max iterations=3",
          "Output/Verbose=false"]
run = R.run("prm/quarter_ball_file.prm", common, name="multigrid")
lines = run.stderr.splitlines()
print("multigrid: exit code %s, stop_reason %s, iterations %s"
      % (run.returncode, run["stop_reason"], run["iterations"]))
check(run.returncode == 2 and run["converged"] is False and run["stop_reason"] == "diverged",
      "multigrid: exit code 2, \"converged\": false, stop_reason \"diverged\"")
check(run["iterations"] == 1, "multigrid: stopped after the iteration that raised J")
check(len(lines) == 1 and "J increased in iteration 1 from" in lines[0],
      "multigrid: one line on stderr naming the iteration and the two values of J")

# the same mesh with the projected Gauss-Seidel method: J decreases
pgs = R.run("prm/quarter_ball_file.prm", common + ["Solver/Type=projected gauss seidel"],
            name="pgs")
print("projected Gauss-Seidel: stop_reason %s, iterations %s"
      % (pgs["stop_reason"], pgs["iterations"]))
check(pgs.returncode == 2 and pgs["stop_reason"] == "iteration limit",
      "projected Gauss-Seidel: runs its 3 iterations, J does not increase")
finish()
