#!/usr/bin/env python3
# The Newton step's linear truncated cycle run by deal.II's Multigrid
# (`Solver/Linear cycle = deal.II`: LinearMultigrid with the patch smoother
# as MGSmoother, the truncated sign-correct prolongation as MGTransferBase,
# the Galerkin operators as MGMatrixBase and the exact coarse solve as
# MGCoarseGridBase) against the own cycle (`own`, MonotoneCycle) on the same
# scene: the same cycle, so
# - the same iterations and cycles, and the same level visits (per level:
#   W visits level J - k 2^k times per cycle down to the exactly solved
#   level, F k + 1 times, V once),
# - J and the contact force equal to 1e-10 / 1e-9 relative (round-off: the
#   W-cycle's second visit of a level smooths on from the first visit's
#   correction instead of correcting its defect),
# - converged, J never increases, every iterate feasible;
# on the square (prm/square.prm, lambda = 1 and inf, 5 levels) with the W-,
# V- and F-cycle, on two processes (the ghost values of the transfer and
# the smoother), and on the half disc (prm/hertz.prm, 4 levels), where the
# transfer's RT sign corrections matter.
# Measured: square W 3 iterations / 12 cycles either way, half disc 4 levels
# W 3 iterations / 35 cycles; J the same to all printed digits.
# The previous binary refuses `Solver/Linear cycle`.
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, finish, \
    relative_difference, rounded

R = Runner(sys.argv)


def compare(prm, settings, label, processes=1):
    runs = {}
    for linear_cycle in ["own", "deal.II"]:
        run = R.run(prm, settings + ["Solver/Linear cycle=" + linear_cycle],
                    (label + "_" + linear_cycle).replace(" ", "_").replace(",", "")
                    .replace("=", ""), processes=processes, timeout=600)
        runs[linear_cycle] = run
        l = "%s, %s linear cycle" % (label, linear_cycle)
        print("%s: iterations %s, cycles %s, level visits %s, J %s, contact force %s"
              % (l, run["iterations"], run["cycles"], run["level_visits"],
                 rounded(run["functional"], 8), rounded(run.force, 8)))
        check(run["converged"] is True, l + ": converged")
        check_monotone_feasible(run, l)
    own, dealii = runs["own"], runs["deal.II"]
    l = label + ", deal.II against own"
    check(dealii["iterations"] is not None and dealii["iterations"] == own["iterations"],
          l + ": the same iterations")
    check(dealii["cycles"] is not None and dealii["cycles"] == own["cycles"],
          l + ": the same cycles")
    check(dealii["level_visits"] is not None and dealii["level_visits"] == own["level_visits"],
          l + ": the same level visits")
    check(relative_difference(dealii["functional"], own["functional"]) <= 1e-10,
          l + ": J equal to 1e-10")
    check(relative_difference(dealii.force, own.force) <= 1e-9,
          l + ": contact force equal to 1e-9")


for lam in ["1", "inf"]:
    compare("prm/square.prm", ["Geometry/Levels=5", "Material/lambda=" + lam],
            "square, lambda = %s, 5 levels, W" % lam)
for cycle in ["V", "F"]:
    compare("prm/square.prm", ["Geometry/Levels=5", "Solver/Cycle=" + cycle],
            "square, 5 levels, %s" % cycle)
compare("prm/square.prm", ["Geometry/Levels=5"], "square, 5 levels, W, 2 processes",
        processes=2)
compare("prm/hertz.prm", ["Geometry/Grading=1", "Geometry/Levels=4"], "half disc, 4 levels, W")
finish()
