#!/usr/bin/env python3
# The work of a solve in work units (summary.json's level_sweeps and
# work_units; bench/work_units.py): a patch sweep over level l counts
# level_dofs[l] / level_dofs[finest] of a sweep over the finest level.
# Checked on the square (prm/square.prm, 6 levels, pre and post smoothing 3
# each):
# - the sweeps are those of the cycles: every level between the finest
#   and the coarsest level a cycle visits is swept (pre + post) times per
#   visit; the finest level also by the Newton step's projected pre- and
#   post-smoothing, once per iteration (the default solver), or only by the
#   cycles (the plain cycle, Krylov steps = 0); the coarsest level visited
#   and those below it not at all (the coarsest is solved exactly);
# - work_units is the sum of level_sweeps weighted by level_dofs, to 1e-9;
# - W-, F- and V-cycles (default solver, stopped at Solver/Tolerance): a
#   V-cycle costs fewer work units than an F-cycle, an F-cycle fewer than a
#   W-cycle; and the plain W-cycle;
# - with the program's default stop (discretization accuracy), nested
#   iteration (Solver/Initial guess): the finest level needs at most
#   2 iterations, the coarser levels' solves (work_units_initial_guess) cost
#   at most half of the finest level's (a geometric sum: each level has a
#   quarter of the DoFs of the next), and the contact force equals that of
#   the default start to 1e-6 (relative).
# Measured (6 levels, default solver and stop): 2 iterations, 8 cycles, 76.9
# work units; nested iteration 33.2 more on the coarser levels (each solved
# to two measured rates, doc/method.md section 7.5).
# The previous binary writes no level_sweeps.
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, finish, \
    relative_difference, rounded

R = Runner(sys.argv)
SMOOTHING = 6  # Pre smoothing + Post smoothing of prm/square.prm


def check_sweeps(run, label, newton, coarsest_exact=True):
    sweeps, visits, dofs = run["level_sweeps"], run["level_visits"], run["level_dofs"]
    print("%s: iterations %s, cycles %s, level_sweeps %s, work units %s"
          % (label, run["iterations"], run["cycles"], sweeps, rounded(run["work_units"], 4)))
    check_monotone_feasible(run, label)
    J = len(sweeps) - 1
    C = 0
    if coarsest_exact:
        C = max([l for l in range(1, J) if dofs[l] <= 200] or [0])
    fine = (visits[J] + (run["iterations"] if newton else 0)) * SMOOTHING
    check(sweeps[J] == fine and all(sweeps[l] == visits[l] * SMOOTHING for l in range(C + 1, J))
          and all(sweeps[l] == 0 for l in range(C + 1)),
          label + ": every level swept (pre + post) times per visit, the finest level also "
          "by the Newton step's smoothing; the exactly solved levels not at all")
    work = sum(s * d / dofs[J] for s, d in zip(sweeps, dofs))
    check(relative_difference(run["work_units"], work) <= 1e-9,
          label + ": work_units = sum of level_sweeps * level_dofs / finest DoFs")


square = ["Geometry/Levels=6"]
runs = {}
for cycle in ["W", "F", "V"]:
    run = R.run("prm/square.prm", square + ["Solver/Cycle=" + cycle], "cycle_" + cycle)
    runs[cycle] = run
    check_sweeps(run, "square, 6 levels, %s-cycle" % cycle, True)
per_cycle = {c: runs[c]["work_units"] / runs[c]["cycles"] for c in runs}
check(per_cycle["V"] < per_cycle["F"] < per_cycle["W"],
      "square, 6 levels: per cycle a V-cycle costs fewer work units than an F-cycle, an "
      "F-cycle fewer than a W-cycle")
plain = R.run("prm/square.prm", square + ["Solver/Krylov steps=0"], "plain")
check_sweeps(plain, "square, 6 levels, plain W-cycle", False, False)

# the program's default stop (discretization accuracy), with both starts
default = R.run("prm/square.prm", square, "default_stop", stop=None)
check_sweeps(default, "square, 6 levels, default stop", True)
nested = R.run("prm/square.prm", square + ["Solver/Initial guess=nested iteration"], "nested",
               stop=None)
label = "square, 6 levels, default stop, nested iteration"
check_sweeps(nested, label, True)
print("%s: work units on the coarser levels %s, contact force %s (default start %s)"
      % (label, rounded(nested["work_units_initial_guess"], 4), rounded(nested.force, 9),
         rounded(default.force, 9)))
check(nested["iterations"] <= 2, label + ": at most 2 iterations on the finest level")
check(0 < nested["work_units_initial_guess"] <= 0.5 * nested["work_units"],
      label + ": the coarser levels' solves cost more than 0 and at most half the finest "
      "level's work units")
check(relative_difference(nested.force, default.force) <= 1e-6,
      label + ": the contact force of the default start to 1e-6")
check("work_units_initial_guess" not in default.summary,
      "square, 6 levels, coarse solution: no work_units_initial_guess")
finish()
