#!/usr/bin/env python3
# The Newton step's linear truncated cycle (MonotoneCycle with
# linear = true: no obstacles, the truncation of the DoFs the Newton step
# holds fixed, coarse faces with a truncated son removed instead of their
# flux rerouted, the finest level below the finest with at most 200 DoFs
# solved exactly) with each cycle type:
# - the level visits of the cycle type (per visit of the finest level J,
#   level J - k W: 2^k times, V: once, F: k + 1 times, down to the
#   exactly solved level, which is visited as often as the level above
#   it);
# - converged, J never increases, every iterate feasible;
# on the square (prm/square.prm, lambda = 1 and inf, 5 levels) with the W-,
# V- and F-cycle, on two processes (the ghost values of the transfer and
# the smoother: the same iterations, cycles and visits as on one, the
# contact force equal to 1e-10 relative as in mpi_rank_independence, J to
# 1e-8: the sums run in another order, and J of the last iterate follows
# the round-off of the CG steps), and on the half disc (prm/hertz.prm, 4
# levels), where the transfer's RT sign corrections matter.
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, finish, \
    level_visits_follow, relative_difference, rounded

R = Runner(sys.argv)
VISITS = {"W": lambda k: 2 ** k, "V": lambda k: 1, "F": lambda k: k + 1}


def run(prm, settings, label, cycle="W", processes=1):
    settings = settings + ["Solver/Cycle=" + cycle]
    result = R.run(prm, settings, label.replace(" ", "_").replace(",", "").replace("=", ""),
                   processes=processes, timeout=600)
    print("%s: iterations %s, cycles %s, level visits %s, J %s, contact force %s"
          % (label, result["iterations"], result["cycles"], result["level_visits"],
             rounded(result["functional"], 8), rounded(result.force, 8)))
    check(result["converged"] is True, label + ": converged")
    check_monotone_feasible(result, label)
    check(result["level_visits"] is not None and level_visits_follow(result, VISITS[cycle]),
          label + ": the level visits of the %s-cycle down to the exactly solved level" % cycle)
    return result


square = ["Geometry/Levels=5"]
one = run("prm/square.prm", square + ["Material/lambda=1"], "square, lambda = 1, 5 levels, W")
run("prm/square.prm", square + ["Material/lambda=inf"], "square, lambda = inf, 5 levels, W")
for cycle in ["V", "F"]:
    run("prm/square.prm", square, "square, 5 levels, %s" % cycle, cycle)
two = run("prm/square.prm", square, "square, 5 levels, W, 2 processes", processes=2)
l = "square, 5 levels, W, 2 processes against 1"
for key in ["iterations", "cycles", "level_visits"]:
    check(two[key] is not None and two[key] == one[key],
          "%s: the same %s" % (l, key.replace("_", " ")))
check(relative_difference(two.force, one.force) <= 1e-10, l + ": contact force equal to 1e-10")
check(relative_difference(two["functional"], one["functional"]) <= 1e-8, l + ": J equal to 1e-8")
run("prm/hertz.prm", ["Geometry/Grading=1", "Geometry/Levels=4"], "half disc, 4 levels, W")
finish()
