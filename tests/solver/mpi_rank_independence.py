#!/usr/bin/env python3
# Distributed runs: the
# same scene on 1 process and on 2, 3 or 4 (mpirun --oversubscribe, one
# thread each) gives the same answer. Per case and process count N > 1,
# against the run on one process: the contact force agrees to 1e-10
# relative, the iteration count to within 1, the number of active
# constraints and the patch colors per level are the same, the run is
# monotone (energy_increases == 0) and every iterate feasible.
# The cases cover what differs between process counts:
#  - the square (one coarse cell), default solver, 5 levels, 1/2/4
#    processes;
#  - the half disc (many coarse cells), default solver with 3
#    levels, and the paper's plain cycle with 2 levels, whose flux
#    rerouting reads operator entries of other processes, 1/2/3 processes;
#  - the 3D cube, default solver, 3 levels, 1/2/4 processes;
#  - the square with the F-cycle (Solver/Cycle = F), 6 levels, 1/2/3
#    processes: its visits per level (k + 1 for level J - k) on every
#    process count;
#  - the reference solvers on the square: active set + KLU (a distributed
#    Trilinos matrix), and 100 sweeps of projected Gauss-Seidel (gathered on
#    the first process and swept in the order of the support points,
#    Discretization::sweep_order(): the sweeps are those of one process).
# Every level's DoFs are numbered by their support points within each
# process's owned range (LevelDoFNumbering), so the numbering,
# and with it the order of every sum, differs between process counts.
# Measured (the forces as printed in summary.json, 12 digits): the iteration counts are equal in every case;
# the forces agree to every printed digit on the square with 2 processes,
# for projected Gauss-Seidel and with the active set solver, to 4e-12 on
# the square with 4 processes and on the cube, to 7e-12 and 4e-11 with
# the plain cycle on the half disc and to 3e-11 and 7e-11 with the default
# solver there (2 and 3 processes). Only the one-process counts are printed
# (those of N processes are asserted), so the output does not depend on
# round-off.
# ctest: timeout=900 mpirun cost=21
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, describe, \
    finish, level_visits_follow, relative_difference

R = Runner(sys.argv)
cases = [
    ("square, 5 levels", "prm/square.prm", ["Geometry/Levels=5"], [2, 4], True),
    ("half disc, 3 levels", "prm/hertz.prm", ["Geometry/Grading=1", "Geometry/Levels=3"], [2, 3], True),
    ("half disc, 2 levels, plain cycle", "prm/hertz.prm",
     ["Geometry/Grading=1", "Geometry/Levels=2", "Solver/Krylov steps=0"], [2, 3], True),
    ("cube, 3 levels", "prm/cube3d.prm", ["Geometry/Levels=3"], [2, 4], True),
    ("square, 6 levels, F-cycle", "prm/square.prm",
     ["Geometry/Levels=6", "Solver/Cycle=F"], [2, 3], True),
    ("square, 4 levels, active set", "prm/square.prm",
     ["Geometry/Levels=4", "Solver/Type=active set"], [2], False),
    ("square, 4 levels, 100 sweeps of projected Gauss-Seidel",
     "prm/square.prm", ["Geometry/Levels=4",
                        "Solver/Type=projected gauss seidel",
                        "Solver/Max iterations=100"], [2], False),
]
for label, prm, settings, processes, multigrid in cases:
    print("=== " + label)
    one = R.run(prm, settings, "1_process")
    describe(one, label + ", 1 process")
    check(one.ok() and one.finite(), label + ", 1 process: ran")
    for n in processes:
        run = R.run(prm, settings, "%d_processes" % n, processes=n)
        name = "%s, %d processes" % (label, n)
        if multigrid:
            check_monotone_feasible(run, name)
            check(run["patch_colors"] == one["patch_colors"],
                  name + ": the same patch colors per level")
        else:
            check(run.ok() and run.finite(), name + ": ran")
            check(run["energy_increases"] == 0, name + ": energy_increases == 0")
        check(run["converged"] == one["converged"],
              name + ": converged as on 1 process (%s)" % one["converged"])
        check(relative_difference(run["contact_force"],
                                  one["contact_force"]) <= 1e-10,
              name + ": |F - F_1| / |F_1| <= 1e-10")
        check(run["iterations"] is not None and one["iterations"] is not None
              and abs(run["iterations"] - one["iterations"]) <= 1,
              name + ": iterations within 1 of those on 1 process")
        check(run["active"] == one["active"],
              name + ": active constraints as on 1 process")
        if "Solver/Cycle=F" in settings:
            check(level_visits_follow(run, lambda k: k + 1),
                  name + ": level J - k visited k + 1 times per cycle")
finish()
