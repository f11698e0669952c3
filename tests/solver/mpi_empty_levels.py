#!/usr/bin/env python3
# Distributed runs where processes own nothing on the coarse levels: every
# MPI collective must be reached by every process, also by one that owns no
# DoF of a level (the square and the cube have one coarse cell, so on 2 or 3
# processes all but one own nothing on level 1, and on level 2 of the
# square some own nothing either), and by one without a contact face. Per
# case, the run on 1 process and on 2 and 3 (mpirun --oversubscribe, each
# run killed after 120 s, so that a deadlock fails the test instead of
# hanging it; a run takes 1 to 3 s): each ends by itself with exit code 0
# and nothing on stderr, with the same number of iterations and the same
# converged flag as on 1 process, and the contact force and J within
# 1e-10 relative of the 1-process run. (Measured: the forces agree to all
# 12 printed digits except 1 to 4 units of the 12th for the 3D cube and
# the square with the plain cycle, J likewise.)
# The cases: the square (one coarse cell) with 1, 2 and 3 levels, default
# solver; with 2 levels, the plain cycle (Krylov steps = 0), the active set
# solver, projected Gauss-Seidel (50 sweeps), the zero start and nested
# iteration; the 3D cube (one coarse cell), 2 levels, default solver and
# plain cycle; the elasticity benchmark without contact, 2 levels,
# default solver and plain cycle.
# ctest: timeout=900 mpirun cost=33
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, describe, finish, relative_difference

R = Runner(sys.argv)
plain = "Solver/Krylov steps=0"
cases = [
    ("square, 1 level", "prm/square.prm", ["Geometry/Levels=1"]),
    ("square, 2 levels", "prm/square.prm", ["Geometry/Levels=2"]),
    ("square, 3 levels", "prm/square.prm", ["Geometry/Levels=3"]),
    ("square, 2 levels, plain cycle", "prm/square.prm", ["Geometry/Levels=2", plain]),
    ("square, 3 levels, plain cycle", "prm/square.prm", ["Geometry/Levels=3", plain]),
    ("square, 2 levels, active set", "prm/square.prm",
     ["Geometry/Levels=2", "Solver/Type=active set"]),
    ("square, 2 levels, projected Gauss-Seidel", "prm/square.prm",
     ["Geometry/Levels=2", "Solver/Type=projected gauss seidel",
      "Solver/Max iterations=50"]),
    ("square, 2 levels, zero start", "prm/square.prm",
     ["Geometry/Levels=2", "Solver/Initial guess=zero"]),
    ("square, 3 levels, nested iteration", "prm/square.prm",
     ["Geometry/Levels=3", "Solver/Initial guess=nested iteration"]),
    ("cube, 2 levels", "prm/cube3d.prm", ["Geometry/Levels=2"]),
    ("cube, 2 levels, plain cycle", "prm/cube3d.prm", ["Geometry/Levels=2", plain]),
    ("elasticity benchmark, 2 levels", "prm/elasticity_mms.prm", ["Geometry/Levels=2"]),
    ("elasticity benchmark, 2 levels, plain cycle", "prm/elasticity_mms.prm",
     ["Geometry/Levels=2", plain]),
]
for label, prm, settings in cases:
    print("=== " + label)
    one = R.run(prm, settings, "1_process", timeout=120)
    describe(one, label + ", 1 process", ("iterations", "converged", "active"))
    check(one.ok() and one.finite(), label + ", 1 process: ran")
    for n in [2, 3]:
        run = R.run(prm, settings, "%d_processes" % n, processes=n, timeout=120)
        name = "%s, %d processes" % (label, n)
        check(run.returncode is not None, name + ": ended within 120 s (no deadlock)")
        check(run.ok() and run.finite(), name + ": exit code 0, nothing on stderr")
        check(run["iterations"] == one["iterations"] and
              run["converged"] == one["converged"],
              name + ": iterations and converged as on 1 process")
        check(relative_difference(run["contact_force"], one["contact_force"]) <= 1e-10,
              name + ": |F - F_1| / |F_1| <= 1e-10")
        check(relative_difference(run["functional"], one["functional"]) <= 1e-10,
              name + ": |J - J_1| / J_1 <= 1e-10")
finish()
