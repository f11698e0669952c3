#!/usr/bin/env python3
# Where double precision cannot resolve what a scene asks, the program says
# so, and names the cause. The square of prm/square.prm (6 levels) made a
# box of 1 x t, its push scaled with t (0.01 t), solved to Solver/Tolerance
# by the default solver and by the active set solver:
#  - t = 1e-2 (cells of 100:1): no warning, round_off_limited false, the
#    solvers' forces within 1e-5;
#  - t = 1e-3 (1000:1): the multigrid reaches the round-off floor of its
#    corrections, where J moves up and down within its round-off; that is
#    no divergence (exit code 0, not "J increased"), and both runs warn in
#    one line that the round-off of J (IterateMeasures::
#    functional_round_off) is past 1e-2 of J, naming the cells' aspect
#    ratio (round_off_limited true, round_off_cause); the forces agree to
#    1e-3;
#  - t = 1e-4 (1e4:1) is refused before the assembly by CellShapeCheck
#    (exit code 1, one line naming the aspect ratio);
#  - C_eq = 1e10 on the square (5 levels, Max iterations 30): J below its
#    own round-off; not "diverged", the warning names the weights.
# Printed: each run's round-off of J over J, rounded to a power of ten.
# ctest: cost=9
import math
import os
import sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_refused, finish

R = Runner(sys.argv)


def decade(x):
    return "1e%d" % round(math.log10(x)) if x and x > 0 else str(x)


def warnings(run):
    return [l for l in run.screen.splitlines() if l.startswith("Warning: the round-off of J")]


for t, limited in [("1e-2", False), ("1e-3", True)]:
    box = ["Geometry/Box upper corner=1, " + t, "Data/Dirichlet values=0; -0.01*" + t]
    forces = []
    for solver in ["monotone multigrid", "active set"]:
        label = "1 x %s, %s" % (t, solver)
        run = R.run("prm/square.prm", box + ["Solver/Type=" + solver],
                    "box_%s_%s" % (t, solver.split()[0]))
        ratio = run["functional_round_off"]
        print("%s: stop_reason %s, round-off of J / J ~ %s"
              % (label, run["stop_reason"], decade(ratio)))
        check(run.ok(), label + ": exit code 0, nothing on stderr")
        check(run["stop_reason"] != "diverged", label + ": not taken for divergence")
        check(run["round_off_limited"] is limited and len(warnings(run)) == (1 if limited else 0),
              label + ": round_off_limited %s, %s warning line"
              % (str(limited).lower(), "one" if limited else "no"))
        if limited:
            check("aspect ratio 1e+03" in (run["round_off_cause"] or "")
                  and "aspect ratio 1e+03" in warnings(run)[0],
                  label + ": the cause named: cells of aspect ratio 1e+03")
        forces.append(run["contact_force"][1])
    bound = 1e-3 if limited else 1e-5
    check(abs(forces[0] - forces[1]) <= bound * abs(forces[1]),
          "1 x %s: the solvers' forces within %g" % (t, bound))

run = R.run("prm/square.prm", ["Geometry/Box upper corner=1, 1e-4",
                               "Data/Dirichlet values=0; -1e-6"], "box_1e-4")
check_refused(run, "1 x 1e-4", "has a cell of aspect ratio 1e+04")

run = R.run("prm/square.prm", ["Geometry/Levels=5", "Functional weights/C_eq=1e10",
                               "Solver/Max iterations=30"], "weights")
print("C_eq = 1e10: stop_reason %s, round-off of J / J ~ %s"
      % (run["stop_reason"], decade(run["functional_round_off"])))
check(run["stop_reason"] != "diverged", "C_eq = 1e10: not taken for divergence")
check(run["round_off_limited"] is True and len(warnings(run)) == 1
      and "'Functional weights' 1e+11 apart" in warnings(run)[0],
      "C_eq = 1e10: one warning line naming the weights")
finish()
