#!/usr/bin/env python3
# Monotone multigrid with `Solver/Cycle = F`: an F-cycle visits its coarser
# level with an F-cycle and then with a V-cycle, so level J - k is visited
# k + 1 times per visit of the finest level J (a W-cycle: 2^k times), down
# to the exactly solved level, which is visited as often as the level above
# it (the linear cycle of the default solver solves the finest level below
# J with at most 200 DoFs exactly, the plain cycle level 0).
# Checked against the W-cycle (the default) on the same scene:
# - default solver, square (prm/square.prm), lambda = 1 and inf, 5 and 6
#   levels: converged (KKT residual < 1e-10), monotone and feasible, the
#   same iterations, at most one cycle more, rate per cycle <= 0.25, J and the contact force equal to
#   the W-cycle's to 1e-10 / 1e-9 relative, and the visits above;
# - plain cycle (Krylov steps = 0), square with 6 levels: the same, with at
#   most one iteration more;
# - default solver on the half disc (prm/hertz.prm) with 4 levels: the same
#   iterations, at most 8 cycles more (no rate bound: W's is 0.15, F's 0.30).
# Measured: on the square the F-cycle took the
# W-cycle's iterations and cycles (default solver: 3 iterations, 12 cycles; plain cycle on 6 levels: 11 iterations, levels
# 1..5 visited 55, 44, 33, 22, 11 times instead of 176, 88, 44, 22, 11).
# On the half disc with 4 levels F took 40 cycles against W's 35 (rate
# 0.30 against 0.15), with 5 levels 74 against 68-69 (bench/cycle_type.py,
# doc/cycle_type_results.md, which also times them: within the machine's
# scatter of each other).
# The previous binary refuses `Cycle = F` (Patterns::Selection("V|W")).
# ctest: cost=8
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, finish, \
    level_visits_follow, relative_difference, rounded

R = Runner(sys.argv)


def compare(prm, settings, label, coarsest_exact, max_more_iterations,
            max_more_cycles, max_rate=0.25):
    runs = {}
    for cycle in ["W", "F"]:
        run = R.run(prm, settings + ["Solver/Cycle=" + cycle],
                    (label + "_" + cycle).replace(" ", "_").replace(",", ""))
        runs[cycle] = run
        print("%s, %s-cycle: iterations %s, cycles %s, rate per cycle %s, "
              "active %s, contact force %s"
              % (label, cycle, run["iterations"], run["cycles"],
                 rounded(run["rate_per_cycle"], 2), run["active"],
                 rounded(run.force)))
        l = "%s, %s-cycle" % (label, cycle)
        check(run["converged"] is True and run["kkt_residual"] is not None
              and run["kkt_residual"] < 1e-10, l + ": converged, KKT residual < 1e-10")
        check_monotone_feasible(run, l)
    w, f = runs["W"], runs["F"]
    l = label + ", F-cycle"
    check(level_visits_follow(f, lambda k: k + 1, coarsest_exact),
          l + ": F-cycle visits level J-k (k+1) times per cycle down to the "
          "coarsest level it visits, which is visited as often as the level "
          "above it")
    check(f["iterations"] is not None and w["iterations"] is not None and
          f["iterations"] <= w["iterations"] + max_more_iterations,
          l + ": at most %d iteration(s) more than the W-cycle" % max_more_iterations)
    check(f["cycles"] is not None and w["cycles"] is not None and
          f["cycles"] <= w["cycles"] + max_more_cycles,
          l + ": at most %d cycle(s) more than the W-cycle" % max_more_cycles)
    if max_rate is not None:
        check(f["rate_per_cycle"] is not None and f["rate_per_cycle"] <= max_rate,
              l + ": rate per cycle <= %g" % max_rate)
    check(relative_difference(f["functional"], w["functional"]) <= 1e-10,
          l + ": J equal to the W-cycle's to 1e-10")
    check(relative_difference(f.force, w.force) <= 1e-9,
          l + ": contact force equal to the W-cycle's to 1e-9")


for lam in ["1", "inf"]:
    for levels in [5, 6]:
        compare("prm/square.prm",
                ["Geometry/Levels=%d" % levels, "Material/lambda=" + lam],
                "square, lambda = %s, %d levels" % (lam, levels), True, 0, 1)
compare("prm/square.prm", ["Geometry/Levels=6", "Solver/Krylov steps=0"],
        "square, plain cycle, 6 levels", False, 1, 1)
# the half disc is harder for the multigrid (doc/method.md section 8): the
# same iterations, a few more cycles with F (measured 40 against 35)
compare("prm/hertz.prm", ["Geometry/Grading=1", "Geometry/Levels=4"], "half disc, 4 levels", True,
        0, 8, None)
finish()
