#!/usr/bin/env python3
# Compressible to
# incompressible material. The square (prm/square.prm, 5 levels, 1666
# DoFs) with lambda = 1, 1e4, 1e8 and inf, default solver, from the
# default start (coarse solution) and from a zero start. Checks per run:
# converged within the stated bound (coarse start: 6 iterations, measured
# 3; zero start: 10 iterations, measured 5-6), no NaN/Inf,
# energy_increases == 0, feasible iterates, and the active set solver's
# KKT point to 1e-8 relative in force and J (coarse start; zero start
# with Solver/Tolerance = 1e-10). Then lambda -> inf:
# |F(1e8) - F(inf)| / |F(inf)| <= 1e-6 (measured 1.4e-8, i.e. O(mu/lambda));
# the printed differences of F(1), F(1e4) to F(inf) (2 digits) show the
# O(mu/lambda) approach.
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, \
    compare_with_reference, describe, finish, relative_difference, rounded

R = Runner(sys.argv)
base = ["Geometry/Levels=5"]
forces = {}
for lam in ["1", "1e4", "1e8", "inf"]:
    print("=== lambda = " + lam)
    settings = base + ["Material/lambda=" + lam]
    reference = R.run("prm/square.prm", settings + ["Solver/Type=active set"],
                      "lambda_%s_active_set" % lam)
    print("active set: contact force |F| = %s, J = %s, active %s"
          % (rounded(reference.force), rounded(reference["functional"]),
             reference["active"]))
    forces[lam] = reference["contact_force"]
    for start, extra, bound, force_tolerance in [
            ("coarse start", [], 6, 1e-8),
            ("zero start", ["Solver/Initial guess=zero",
                            "Solver/Tolerance=1e-10"], 10, 1e-8)]:
        run = R.run("prm/square.prm", settings + extra,
                    "lambda_%s_%s" % (lam, start.split()[0]))
        describe(run, start)
        check(run["converged"] is True and run["iterations"] <= bound,
              "%s: converged within %d iterations" % (start, bound))
        check_monotone_feasible(run, start)
        compare_with_reference(run, reference, start,
                               force_tolerance=force_tolerance)
print("=== lambda -> inf")
for lam in ["1", "1e4", "1e8"]:
    print("|F(%s) - F(inf)| / |F(inf)| = %s"
          % (lam, rounded(relative_difference(forces[lam], forces["inf"]),
                          2)))
check(relative_difference(forces["1e8"], forces["inf"]) <= 1e-6,
      "|F(1e8) - F(inf)| / |F(inf)| <= 1e-6")
finish()
