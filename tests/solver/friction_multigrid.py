#!/usr/bin/env python3
# Friction solved by the monotone multigrid (the default solver): its patch
# smoother relaxes the tangential contact DoFs with their bounds and kinks,
# its Newton step holds the DoFs at a bound or kink and moves the others
# with the slope of their side, and its line search minimizes J along the
# direction with the kinks.
#  - The square's load path (tests/scenes/square.prm, 4 levels, pressed and
#    moved sideways past the stick limit), Tresca and Coulomb: the active set
#    method's steps (stick and slip vertices, forces to 1e-6 of the normal
#    force, J to 1e-6), J never increasing in any iteration of any Tresca
#    problem, every iterate feasible.
#  - Pressed only: the same stick zone as the active set method.
#  - The same steps on 2 processes as on 1 (forces to 1e-8).
#  - Adaptive (3 steps, Coulomb): the active set method's stick zone and
#    force, at most 6 Newton steps per Tresca problem.
#  - prm/sliding_block.prm on 3, 4 and 5 levels: the Newton steps per
#    Tresca problem do not grow with the level (at most 6), on 3 levels
#    the active set method's steps, on 4 levels the same steps on 4
#    processes as on 1. The linear cycles of each step's last Tresca
#    problem are printed: they depend on the coarse spaces of the
#    tangential tractions (FluxRerouting::linear_columns(); with the
#    tangential columns cut at held sons, 65 and 95 on 4 and 5 levels).
#    The residual reduction per linear cycle of each step's Newton steps
#    (load_steps' linear_rate, the geometric mean over their CG steps) is
#    at most 0.3 on every level (measured: at most 0.19), and so is the
#    reduction of the corrections per Newton step over each step's Tresca
#    problems (load_steps' iteration_rate, the geometric mean over the
#    Newton steps above the round-off floor; measured: at most 0.005).
# ctest: mpirun sanitize cost=21
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import (Runner, check, check_monotone_feasible, finish, monotone, newton_steps,
                        relative_difference, same_steps, solves)

R = Runner(sys.argv)
SQUARE = "tests/scenes/square.prm"
PRESS = ["Data/Constants=push=0.01, shift=0", "Data/Dirichlet values=shift; -push",
         "Solver/Tolerance=1e-12"]
PATH = ["Data/Load steps=push=0.01; shift=0.002; shift=0.02"]
MULTIGRID = ["Solver/Type=monotone multigrid"]  # (the square's scene takes the active set)
REFERENCE = ["Solver/Type=active set"]


laws = (("Tresca", "Friction/Bound=0.001"), ("Coulomb", "Friction/Coefficient=0.3"))
multigrid = {}
for law, datum in laws:
    settings = PRESS + PATH + ["Friction/Law=" + law, datum]
    run = R.run(SQUARE, settings + MULTIGRID, law + "_multigrid")
    reference = R.run(SQUARE, settings + REFERENCE, law + "_active_set")
    multigrid[law] = run
    for row in run["load_steps"] or []:
        print("%s step %d: %d stick and %d slip vertices" % (
            law, row["step"], row["stick_vertices"], row["slip_vertices"]))
    print("%s: Newton steps per Tresca problem %s" % (law, newton_steps(run)))
    check(run.ok() and reference.ok() and same_steps(run, reference, 1e-6),
          law + ": the active set method's steps (to 1e-6)")
    check(monotone(run) and len(solves(run)) >= 3,
          law + ": J never increases in an iteration of any Tresca problem")
    check_monotone_feasible(run, law + ": the last solve")

pressed = ["Friction/Law=Coulomb", "Friction/Coefficient=0.3"]
run = R.run(SQUARE, PRESS + pressed + MULTIGRID, "pressed_multigrid")
reference = R.run(SQUARE, PRESS + pressed + REFERENCE, "pressed_active_set")
friction, expected = run["friction"] or {}, reference["friction"] or {}
print("pressed, f = 0.3: %d stick and %d slip vertices" % (
    friction.get("stick_vertices", -1), friction.get("slip_vertices", -1)))
check(run.ok() and friction.get("stick_vertices", -1) == expected.get("stick_vertices", -2) > 0
      and relative_difference(run["contact_force"], reference["contact_force"]) <= 1e-6,
      "pressed, f = 0.3: the active set method's stick zone and force (to 1e-6)")

two = R.run(SQUARE, PRESS + PATH + ["Friction/Law=Coulomb", "Friction/Coefficient=0.3"]
            + MULTIGRID, "coulomb_2", processes=2)
check(two.ok() and same_steps(two, multigrid["Coulomb"], 1e-8),
      "Coulomb: the same steps on 2 processes as on 1 (to 1e-8)")

# adaptive: each mesh's Coulomb fixed point starts from the last mesh's
# solution (its pressure), not from a frictionless problem
adaptive = PRESS[1:] + ["Data/Constants=push=0.01, shift=0.002", "Adaptivity/Steps=3",
                        "Friction/Law=Coulomb", "Friction/Coefficient=0.3"]
run = R.run(SQUARE, adaptive + MULTIGRID, "adaptive_multigrid")
reference = R.run(SQUARE, adaptive + REFERENCE, "adaptive_active_set")
friction, expected = run["friction"] or {}, reference["friction"] or {}
print("adaptive, 3 steps: %s DoFs, %d stick and %d slip vertices, Newton steps per Tresca "
      "problem %s" % (run["dofs"], friction.get("stick_vertices", -1),
                      friction.get("slip_vertices", -1), newton_steps(run)))
check(run.ok() and reference.ok() and monotone(run)
      and (friction.get("stick_vertices"), friction.get("slip_vertices"))
      == (expected.get("stick_vertices", -1), expected.get("slip_vertices", -1))
      and relative_difference(run["contact_force"], reference["contact_force"]) <= 1e-6
      and max(newton_steps(run), default=99) <= 6,
      "adaptive, 3 steps: the active set method's stick zone and force (to 1e-6), J never "
      "increases, at most 6 Newton steps per Tresca problem")

steps = {}
for levels in (3, 4, 5):
    block = R.run("prm/sliding_block.prm", ["Geometry/Levels=%d" % levels],
                  "sliding_block_%d" % levels)
    steps[levels] = newton_steps(block)
    print("prm/sliding_block.prm, %d levels: %d Tresca problems, at most %d Newton steps each; "
          "linear cycles of the steps' last Tresca problems %s" % (
              levels, len(steps[levels]), max(steps[levels], default=0),
              [row["cycles"] for row in block["load_steps"] or []]))
    check(block.ok() and monotone(block), "sliding block, %d levels: J never increases" % levels)
    rates = [row["linear_rate"] for row in block["load_steps"] or []]
    print("prm/sliding_block.prm, %d levels: residual reduction per linear cycle of the steps' "
          "Newton steps %s" % (levels, [round(rate, 2) for rate in rates]))
    check(len(rates) == 5 and max(rates) <= 0.3,
          "sliding block, %d levels: the linear cycle reduces the residual of CG's linear "
          "problems by at most 0.3 per step" % levels)
    newton = [row["iteration_rate"] for row in block["load_steps"] or []]
    print("prm/sliding_block.prm, %d levels: reduction of the corrections per Newton step of "
          "the steps' Tresca problems %s" % (levels, [rate if rate is None else round(rate, 3)
                                                    for rate in newton]))
    check(len(newton) == 5 and None not in newton and max(newton) <= 0.3,
          "sliding block, %d levels: the Newton steps reduce the corrections by at most 0.3 "
          "per step" % levels)
    if levels == 3:
        reference = R.run("prm/sliding_block.prm", ["Geometry/Levels=3"] + REFERENCE,
                          "sliding_block_3_active_set")
        check(same_steps(block, reference, 1e-6),
              "sliding block, 3 levels: the active set method's steps (to 1e-6)")
    if levels == 4:
        # (4 processes on a coarse mesh of 2 cells: some own no DoF of the
        # coarsest levels and no contact face)
        spread = R.run("prm/sliding_block.prm", ["Geometry/Levels=4"], "sliding_block_4_np4",
                       processes=4)
        check(spread.ok() and same_steps(spread, block, 1e-8),
              "sliding block, 4 levels: the same steps on 4 processes as on 1 (to 1e-8)")
check(all(steps[l] and max(steps[l]) <= 6 for l in steps),
      "sliding block: at most 6 Newton steps per Tresca problem on 3, 4 and 5 levels")
finish()
