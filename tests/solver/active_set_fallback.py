#!/usr/bin/env python3
# The square of prm/square.prm touching the obstacle without force: its top
# pushed down by 0.01 onto an obstacle 0.01 below its bottom side (Data/Gap
# = 0.01), so that the constraint u_n <= g holds with equality and a zero
# multiplier at every contact DoF (the body hangs from its top side; the
# solution is the translation u = (0, -0.01), no contact force, J at its
# round-off level), and the primal-dual active set method's decisions are
# round-off. (The primal active set method it falls back to when it comes
# back to an earlier active set, ActiveSetDirect::primal_active_set, is
# checked on its own by unit/active_set_cycling.) Checked, on levels 1, 2
# and 4, default settings, the active set solver, the plain cycle and 2
# processes: every run converges (exit code 0, nothing on stderr) to that
# translation: the contact force is 0 (|F| <= 1e-12, against 0.027 with the
# default gap), u_n - g and sigma_nn vanish at every contact vertex
# (contact.csv, |.| <= 1e-13: 1e-11 of the push 0.01), J is at most 1e-12
# of its value at zero (the first J of the multigrid run from a zero start;
# J at the solution is round-off and differs between runs in its first
# digit) and the KKT residual is below 1e-12.
# ctest: mpirun sanitize
import csv
import os
import sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, describe, finish

R = Runner(sys.argv)
touching = "Data/Gap=0.01"
for levels in [1, 2, 4]:
    scene = [touching, "Geometry/Levels=%d" % levels]
    label = "square, gap 0.01, %d level%s" % (levels, "s" if levels > 1 else "")
    print("=== " + label)
    zero = R.run("prm/square.prm", scene + ["Solver/Initial guess=zero"], "zero_start")
    check(zero.ok() and zero["converged"] is True,
          label + ", multigrid from zero: converged")
    runs = [("default solver", R.run("prm/square.prm", scene, "default")),
            ("active set", R.run("prm/square.prm", scene + ["Solver/Type=active set"],
                                 "active_set")),
            ("plain cycle", R.run("prm/square.prm", scene + ["Solver/Krylov steps=0"],
                                  "plain_cycle")),
            ("default solver, 2 processes",
             R.run("prm/square.prm", scene, "default_2_processes", processes=2))]
    for name, run in runs:
        what = label + ", " + name
        describe(run, what, ("converged",))
        check(run.ok() and run["converged"] is True,
              what + ": exit code 0, nothing on stderr, converged")
        check(run.force is not None and run.force <= 1e-12, what + ": |F| <= 1e-12")
        rows = []
        if os.path.exists(os.path.join(run.directory, "contact.csv")):
            with open(os.path.join(run.directory, "contact.csv")) as f:
                rows = list(csv.DictReader(f))
        check(len(rows) == 2 ** (levels - 1) + 1 and
              all(abs(float(r["u_n"]) - float(r["gap"])) <= 1e-13
                  and abs(float(r["sigma_nn"])) <= 1e-13 for r in rows),
              what + ": u_n - g = sigma_nn = 0 at all %d contact vertices (1e-13)"
              % (2 ** (levels - 1) + 1))
        check(run["functional"] is not None and
              abs(run["functional"]) <= 1e-12 * zero.history[0]["functional"],
              what + ": J <= 1e-12 J(0)")
        check(run["kkt_residual"] is not None and run["kkt_residual"] <= 1e-12,
              what + ": KKT residual <= 1e-12")
finish()
