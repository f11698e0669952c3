#!/usr/bin/env python3
# Bad meshes.
#  - Graded half-disc meshes (prm/hertz.prm, 2 levels as in paper section
#    7, lambda = 1 and inf): Geometry/Grading = 1.94779, 2.38882, 3.20853
#    give coarse h_max/h_min (summary.json h_ratio_coarse) = 3.1688,
#    7.0567, 29.794, the paper's 3.1688, 7.0567, 29.7936 (values found by
#    bisection in bench/results/grading_scan.csv, checked here; Grading =
#    1 gives 2.468, 1.5 gives about 2.1, 2.6 gives 10.35).
#  - An anisotropic box: the unit square with Box subdivisions = 10, 1,
#    i.e. coarse cells 0.1 x 1 (aspect ratio 10; h_ratio_coarse is 1, as
#    all cells have the same diameter), contact at the bottom, 3 and 4
#    levels (1138 and 4194 DoFs), lambda = 1 and inf.
# Default solver. Checks per run: converged within the stated bound
# (graded: 25 iterations, measured 3-4 for ratios 3 and 7, 8 (lambda = 1)
# and 9 (inf) for 30; anisotropic: 15, measured 4-5 on 3 and 4-5 on 4
# levels, with more CG steps per iteration on 4 levels: vertex-patch
# smoothing is not robust for anisotropy), no NaN/Inf,
# energy_increases == 0, feasible iterates, and the active set solver's KKT
# point: force to 1e-8 and J to 1e-7 relative (measured <= 2.3e-9 and
# 2.3e-8: the ratio-30 meshes end near their round-off floor), KKT
# residual < 1e-8 (measured <= 3.4e-15), same number of active
# constraints. The definiteness check runs
# on level <= 2 (Solver/Definiteness check max dofs = 2000; on the 4194
# DoF box it costs more than the solve).
# ctest: timeout=600 cost=10
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, \
    compare_with_reference, describe, finish, rounded

R = Runner(sys.argv)
cheap_check = ["Solver/Definiteness check max dofs=2000"]
cases = []
for grading, ratio in [("1.94779", 3.1688), ("2.38882", 7.0567),
                       ("3.20853", 29.7936)]:
    cases.append(("half disc, Grading = " + grading, "prm/hertz.prm",
                  ["Geometry/Levels=2", "Geometry/Grading=" + grading],
                  25, ratio))
for levels in [3, 4]:
    cases.append(("box 10 x 1, %d levels" % levels, "prm/square.prm",
                  ["Geometry/Levels=%d" % levels,
                   "Geometry/Box subdivisions=10, 1"], 15, 1.))
for label, prm, settings, bound, ratio in cases:
    for lam in ["1", "inf"]:
        print("=== %s, lambda = %s" % (label, lam))
        s = settings + ["Material/lambda=" + lam] + cheap_check
        name = "_".join(s[0:2]).replace("Geometry/", "").replace(" ", "") \
            .replace("=", "").replace(",", "x") + "_lambda" + lam
        reference = R.run(prm, s + ["Solver/Type=active set"],
                          name + "_active_set")
        print("active set: dofs %s, h_ratio_coarse %s, contact force "
              "|F| = %s, active %s"
              % (reference["dofs"], rounded(reference["h_ratio_coarse"], 5),
                 rounded(reference.force), reference["active"]))
        check(abs(reference["h_ratio_coarse"] - ratio) <= 1e-3 * ratio,
              "h_ratio_coarse = %s to 1e-3" % ratio)
        run = R.run(prm, s, name)
        describe(run, "multigrid")
        check(run["converged"] is True and run["iterations"] <= bound,
              "converged within %d iterations" % bound)
        check_monotone_feasible(run, "multigrid")
        compare_with_reference(run, reference, "multigrid",
                               functional_tolerance=1e-7)
finish()
