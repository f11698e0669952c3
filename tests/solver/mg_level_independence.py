#!/usr/bin/env python3
# Monotone multigrid: the
# iteration count of the default solver (Krylov steps = 50, W(3,3),
# projection b, coarse-solution start, tolerance 1e-8) does not grow with
# the level: the square (prm/square.prm) with lambda = 1 and lambda = inf on
# levels 3, 4, 5, 6 (130 to 6402 DoFs). Prints iterations and cycles per
# level and asserts max - min <= 2 iterations and at most 6 iterations
# per level; every run converged to a KKT residual < 1e-10 with
# energy_increases == 0 and feasible iterates; summary.json's level costs
# (level_visits, level_time_s) have the visits of a W-cycle and times that
# fit in the solve time.
# The counts per level are in mg_level_independence.output. The square's
# contact set is found by the coarse start, so the problem is linear after the first smoothing
# (paper section 7). The patch order (MultilevelHierarchy, VertexKey)
# puts the vertices of the uniformly refined square into 4 colors on every
# level (old vertices, midpoints of x and of y lines, cell centers).
# ctest: sanitize
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, finish, \
    level_visits_follow, rounded

R = Runner(sys.argv)
for lam in ["1", "inf"]:
    print("=== lambda = " + lam)
    iterations = []
    for levels in [3, 4, 5, 6]:
        run = R.run("prm/square.prm", ["Geometry/Levels=%d" % levels,
                                       "Material/lambda=" + lam],
                    "lambda_%s_level_%d" % (lam, levels))
        print("level %d: dofs %s, iterations %s, cycles %s, active %s, "
              "contact force %s"
              % (levels, run["dofs"], run["iterations"], run["cycles"],
                 run["active"], rounded(run.force)))
        label = "level %d" % levels
        check(run["converged"] is True and run["kkt_residual"] is not None
              and run["kkt_residual"] < 1e-10,
              label + ": converged, KKT residual < 1e-10")
        check_monotone_feasible(run, label)
        check(run["patch_colors"] == [4] * (levels - 1),
              label + ": 4 patch colors on every level (MultilevelHierarchy)")
        # summary.json's level costs (bench/level_costs.py): a W-cycle
        # visits level l 2^(J-l) times per visit of the finest level J down
        # to the level above the coarsest it reaches, C, and that one once
        # per visit of level C + 1: the linear cycle solves the finest level
        # below J with at most 200 DoFs exactly (level 2 of 130 DoFs, prm
        # level 3, from J = 3 on; level 1 of 42 DoFs for J = 2), and does
        # not visit the levels below it. The times are those of the levels
        # without the coarser ones, so they add up to at most the solve time.
        seconds = run["level_time_s"]
        check(run["level_dofs"][-1] == run["dofs"] and
              level_visits_follow(run, lambda k: 2 ** k) and
              min(seconds) >= 0 and sum(seconds) <= run["time_solve_s"],
              label + ": W-cycle visits level l 2^(J-l) times per cycle down to "
              "the exactly solved level (the finest below J with <= 200 DoFs), "
              "level times >= 0 and within the solve time")
        iterations.append(run["iterations"] or 1000)
    print("iterations over levels 3..6: min %d, max %d"
          % (min(iterations), max(iterations)))
    check(max(iterations) - min(iterations) <= 2,
          "max - min iterations <= 2")
    check(max(iterations) <= 6, "at most 6 iterations on every level")
finish()
