#!/usr/bin/env python3
# Obstacles and
# starting guesses, on the square (prm/square.prm, 5 levels, 1666 DoFs,
# pushed down by 0.01), default solver, each compared with the active set
# solver (the reference) or a formula:
#  - initial gap 0.005 (Data/Gap = 0.005): contact, with about half the
#    force of gap 0 (the body is compressed by 0.005 instead of 0.01);
#  - initial gap 0.02 > 0.01: no contact at all; the contact force must be
#    exactly 0 and no contact vertex active (zero start; the default
#    coarse-solution start, which is already exact, is test
#    mg_exact_start);
#  - a penetrating start (Solver/Initial guess = expression, Data/Initial
#    displacement = "0; -0.05"): the note "Initial guess violates the
#    contact constraints by 5.000e-02: projected onto the feasible set" is
#    printed, and the run converges to the reference;
#  - a tilted obstacle, normal (0.3, -1) (normalized by the program): the
#    force is parallel to the normal (direction printed);
#  - curved obstacles: Gap = 0.02 (x - 0.5)^2 (contact where the parabola
#    is below the push), and a Hertz-like cylinder of radius R = 0.5 below
#    the square, Gap = R - sqrt(R^2 - (x - 0.5)^2) (contact in the middle
#    only; R = 1 on 5 levels and the half disc on 4 levels are test
#    partial_contact_zones).
# Checks per run: converged within 20 iterations (measured 4-5), no NaN/Inf, energy_increases == 0, every
# iterate feasible, and the reference's KKT point: force and J to 1e-8
# relative (measured <= 3.8e-9), KKT residual < 1e-8, same number of
# active constraints. The penetrating start uses Solver/Tolerance = 1e-10
# (at the default 1e-8 J is 1.03e-8 off), the curved obstacles 1e-11
# (they end at the round-off floor; at 1e-8 their slow rate leaves the
# force 7.9e-9 and 9e-8 off, at 1e-10 1.1e-8).
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, \
    compare_with_reference, describe, finish, rounded

R = Runner(sys.argv)
base = ["Geometry/Levels=5"]
tight = ["Solver/Tolerance=1e-10"]
tighter = ["Solver/Tolerance=1e-11"]
cases = [
    ("gap 0.005", ["Data/Gap=0.005"], []),
    ("gap 0 (for comparison)", [], []),
    ("penetrating start", [], ["Solver/Initial guess=expression",
                               "Data/Initial displacement=0; -0.05"]
     + tight),
    ("tilted obstacle", ["Data/Obstacle normal=0.3; -1"], []),
    ("parabolic gap", ["Data/Gap=0.02*(x-0.5)^2"], tighter),
    ("cylinder below", ["Data/Constants=R=0.5",
                        "Data/Gap=R - sqrt(R^2 - (x-0.5)^2)"], tighter),
]
forces = {}
for label, scene, solver in cases:
    print("=== " + label)
    name = label.split(" (")[0].replace(" ", "_")
    reference = R.run("prm/square.prm", base + scene
                      + ["Solver/Type=active set"], name + "_active_set")
    print("active set: contact force |F| = %s, active %s"
          % (rounded(reference.force), reference["active"]))
    run = R.run("prm/square.prm", base + scene + solver, name)
    describe(run, "multigrid")
    check(run["converged"] is True and run["iterations"] <= 20,
          "converged within 20 iterations")
    check_monotone_feasible(run, "multigrid")
    compare_with_reference(run, reference, "multigrid")
    forces[label] = run.force
    if label == "penetrating start":
        check("Initial guess violates the contact constraints by 5.000e-02: "
              "projected onto the feasible set" in run.screen,
              "the projection of the start is reported")
    if label == "tilted obstacle":
        f = run["contact_force"]
        print("force direction = %s %s" % (rounded(f[0] / run.force, 4),
                                           rounded(f[1] / run.force, 4)))
        check(abs(f[0] / run.force + 0.3 / 1.09 ** 0.5) < 1e-8
              and abs(f[1] / run.force - 1 / 1.09 ** 0.5) < 1e-8,
              "force parallel to the obstacle normal to 1e-8")
ratio = forces["gap 0.005"] / forces["gap 0 (for comparison)"]
print("F(gap 0.005) / F(gap 0) = %s" % rounded(ratio, 4))
check(abs(ratio - 0.5) < 1e-3, "F(gap 0.005) / F(gap 0) = 0.5 (linear "
      "elasticity, full contact in both)")

print("=== gap 0.02 (no contact), zero start")
scene = base + ["Data/Gap=0.02"]
reference = R.run("prm/square.prm", scene + ["Solver/Type=active set"],
                  "gap_0.02_active_set")
for label, solver in [("default", []), ("plain cycle",
                                        ["Solver/Krylov steps=0"])]:
    run = R.run("prm/square.prm", scene + solver
                + ["Solver/Initial guess=zero"], "gap_0.02_" + label[0:5])
    describe(run, label)
    check(run["converged"] is True and run["iterations"] <= 15,
          label + ": converged within 15 iterations")
    check_monotone_feasible(run, label)
    check(run.force == 0 and reference.force == 0,
          label + ": contact force exactly 0 (and in the reference)")
    with open(os.path.join(run.directory, "contact.csv")) as f:
        rows = [r.split(",") for r in f.read().splitlines()[1:] if r]
    check(len(rows) == 17 and all(r[-1].strip() == "0" for r in rows),
          label + ": no contact vertex active (17 in contact.csv)")
    # J* = 0: the exact solution, a rigid translation by (0, -0.01), is
    # discrete; J is 1e-17, i.e. round-off
    check(run["functional"] < 1e-14, label + ": J < 1e-14 (exact: 0)")
finish()
