#!/usr/bin/env python3
# The weights of
# the functional, on the square (prm/square.prm).
#  - C_eq = 1, 10, 1e2, 1e3, 1e4 (5 levels, C_const = 1, C_compl = 0.1):
#    the default solver and the plain cycle (Krylov steps = 0) converge
#    within the stated bounds (default 10 iterations, measured 3 and 8 for
#    C_eq = 1e4; plain 20, measured 10-14) to the active set solver's KKT
#    point: force to 1e-8 relative (measured <= 5.1e-10), J to
#    max(1e-8, 1e-9 C_eq) (measured 2e-11 .. 6.8e-7: J is evaluated as
#    1/2 x^T A x - b^T x + c, whose terms, and so its round-off, grow with
#    C_eq while J itself does not; for the same reason J may go up along
#    convergence.csv by round-off, by up to 4e-8 J_0 at C_eq = 1e4, so
#    monotonicity is checked there to 1e-8 max(1, C_eq / 100) J_0, next to
#    the solver's own count energy_increases == 0).
#  - C_compl = 0 (no complementarity term; no definiteness check): the
#    default solver converges to the reference as well (measured 4
#    iterations; the plain cycle is not run: without the complementarity
#    term it does not converge in 200 cycles).
#  - The definiteness limit of C_compl (paper eq. 10): at 4 levels with the
#    default C_eq = 1e2, C_const = 1, the program accepts C_compl = 0.297
#    (smallest relative eigenvalue of the contact Schur complement 1.7e-7)
#    and refuses 0.298 (-1.8e-7), measured with --set. Checked with a
#    margin: C_compl = 0.29 (eigenvalue 2.5e-6) converges to the
#    reference; C_compl = 0.3 is refused with exit code 1, exactly one line
#    on stderr mentioning C_compl, and no output directory. The limit
#    falls with the level: C_compl = 0.29 is refused at 5 levels.
#  - A check on a coarser level than the finest adds a margin to C_compl
#    (below): 0.28 is refused, 0.19 accepted and converges.
# ctest: cost=9
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, \
    compare_with_reference, describe, finish, rounded

R = Runner(sys.argv)


def converges(settings, label, bounds, functional_tolerance=1e-8,
              monotone_tolerance=1e-8):
    reference = R.run("prm/square.prm", settings + ["Solver/Type=active set"],
                      label + "_active_set")
    print("active set: contact force |F| = %s, J = %s"
          % (rounded(reference.force), rounded(reference["functional"])))
    for k, bound in zip(["10", "0"][:len(bounds)], bounds):
        solver = "default" if k == "10" else "plain cycle"
        run = R.run("prm/square.prm", settings + ["Solver/Krylov steps=" + k],
                    label + "_krylov_" + k)
        describe(run, solver)
        check(run["converged"] is True and run["iterations"] <= bound,
              "%s: converged within %d iterations" % (solver, bound))
        check_monotone_feasible(run, solver,
                                monotone_tolerance=monotone_tolerance)
        compare_with_reference(run, reference, solver,
                               functional_tolerance=functional_tolerance)


for c_eq in ["1", "10", "1e2", "1e3", "1e4"]:
    print("=== C_eq = " + c_eq)
    converges(["Geometry/Levels=5", "Functional weights/C_eq=" + c_eq],
              "C_eq_" + c_eq, (10, 20), max(1e-8, 1e-9 * float(c_eq)),
              1e-8 * max(1., float(c_eq) / 100))

print("=== C_compl = 0")
converges(["Geometry/Levels=5", "Functional weights/C_compl=0"],
          "C_compl_0", (10,))

print("=== C_compl = 0.29, 4 levels (just below the limit)")
converges(["Geometry/Levels=4", "Functional weights/C_compl=0.29"],
          "C_compl_0.29", (10, 20))

# With the check on a coarser level than the finest (Solver/Definiteness
# check max dofs = 500: level 4 of 450 DoFs for 5 levels), C_compl is
# checked with the margin of ProblemChecks::coarse_level_margin: 0.28 is
# definite on level 4 alone (its limit 0.297) but not on the finest level 5
# (limit 0.269, bench/definiteness_limit.py), and must be refused.
coarse_check = ["Solver/Definiteness check max dofs=500"]
for c_compl, levels, more in [("0.3", 4, []), ("0.29", 5, []), ("0.28", 5, coarse_check)]:
    print("=== C_compl = %s, %d levels (above the limit)%s"
          % (c_compl, levels, ", checked on level 4" if more else ""))
    run = R.run("prm/square.prm", ["Geometry/Levels=%d" % levels,
                                   "Functional weights/C_compl=" + c_compl] + more,
                "C_compl_%s_%d%s" % (c_compl, levels, "_coarse_check" if more else ""))
    lines = run.stderr.splitlines()
    print("exit code %d, %d line(s) on stderr" % (run.returncode, len(lines)))
    check(run.returncode == 1, "refused with exit code 1")
    check(len(lines) == 1 and "C_compl" in lines[0]
          and "indefinite" in lines[0],
          "one line on stderr: indefinite ... C_compl")
    check(not os.path.exists(run.directory), "no output directory written")
print("=== C_compl = 0.19, 5 levels, checked on level 4 with the margin")
converges(["Geometry/Levels=5", "Functional weights/C_compl=0.19"] + coarse_check,
          "C_compl_0.19_coarse_check", (10,))
finish()
