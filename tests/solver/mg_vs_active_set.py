#!/usr/bin/env python3
# Monotone multigrid: the
# multigrid result is the KKT point of the active set (reference) solver,
# for each coarse obstacle projection a, b, c, d (Solver/Projection), on
# the square (prm/square.prm, 3 and 4 levels) and on the half disc
# (prm/hertz.prm, 2 levels): relative difference of the contact force
# vector and of J below 1e-8, KKT residual below 1e-8, the same number of
# active constraints. Default solver (Krylov steps = 50) for all; the plain
# cycle (Krylov steps = 0) only on the square (measured: 10 iterations at 3
# and 13 at 4 levels for each projection; on the half disc it does not
# converge: it stalls, test plain_cycle_stall).
# Solver/Tolerance = 1e-10: the stopping criterion is a relative energy
# correction, and with the default 1e-8 the force on the half disc agrees
# only to 5.8e-9; with 1e-10 measured: force <= 6e-11, J <= 3e-10, KKT
# residual <= 3e-16).
# Measured on this scene set: a, b, c, d give identical iterates (the
# coarse-solution start finds the whole contact set at once, so the coarse
# obstacles of the truncated hierarchy are +inf); the zero-start runs of
# mg_monotone_feasible exercise them.
# ctest: cost=9
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, \
    compare_with_reference, describe, finish, rounded

R = Runner(sys.argv)
tolerance = ["Solver/Tolerance=1e-10"]
for scene, prm, levels, plain in [("square", "prm/square.prm", 3, True),
                                  ("square", "prm/square.prm", 4, True),
                                  ("hertz", "prm/hertz.prm", 2, False)]:
    settings = ["Geometry/Levels=%d" % levels] + \
        (["Geometry/Grading=1"] if prm == "prm/hertz.prm" else [])
    print("=== %s, %d levels" % (scene, levels))
    reference = R.run(prm, settings + ["Solver/Type=active set"],
                      "%s%d_active_set" % (scene, levels))
    describe(reference, "active set", ("dofs", "iterations", "converged",
                                       "active"))
    print("active set: contact force |F| = %s, J = %s"
          % (rounded(reference.force), rounded(reference["functional"])))
    for projection in "abcd":
        # the default solver, and the plain cycle (Krylov steps = 0)
        for cycle in (["default", "plain cycle"] if plain else ["default"]):
            label = "projection %s, %s" % (projection, cycle)
            krylov = ["Solver/Krylov steps=0"] if cycle == "plain cycle" else []
            run = R.run(prm, settings + tolerance + krylov
                        + ["Solver/Projection=" + projection],
                        "%s%d_%s_%s" % (scene, levels, projection,
                                        "0" if krylov else "default"))
            describe(run, label)
            check(run["converged"] is True, label + ": converged")
            check_monotone_feasible(run, label)
            compare_with_reference(run, reference, label)
finish()
