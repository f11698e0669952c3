#!/usr/bin/env python3
# Friction in 3D: the isotropic disc of the tangential traction and the
# Euclidean norm of the slip (doc/method.md section 7.7), solved by the
# monotone multigrid (the patch smoother's pair blocks, the Newton step's
# pairs, the line search along the norms). tests/solver/friction_3d_reference
# compares it with projected Gauss-Seidel on a smaller mesh.
#  - The unit cube pressed on its bottom (tests/scenes/cube3d.prm, 3 levels)
#    and moved along (2, 1) past its stick limit, Tresca: J never increases
#    in an iteration of any step, every iterate is feasible, and each step
#    satisfies the KKT conditions of its problem (residual <= 1e-10: the
#    minimizer of J, whatever the solver); in full slip Q = s A (to 1e-4).
#    The same steps on 2 processes as on 1 (to 1e-8).
#  - Coulomb (f = 0.3), the same path: a stick zone after the first shift.
#  - Coulomb (f = 0.1) moved far along (2, 1): every contact vertex slips,
#    Q = f P to 1e-5 and Q points along the push to 1e-3 (the slips are
#    parallel to it up to the body's bulge): the friction is isotropic,
#    not a box in the mesh's axes, which would turn Q to (1, 1).
#  - f = 0 gives the frictionless answer (force and J to 1e-8).
#  - prm/sliding_block_3d.prm on 2 levels: every step converges, J never
#    increases, the Newton steps per Tresca problem printed (3 levels:
#    tests/solver/friction_3d_reference).
#  - The error indicators hold the friction terms: their sum is J (to 1e-6).
# ctest: mpirun timeout=900
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import (Runner, check, check_monotone_feasible, finish, monotone, newton_steps,
                        relative_difference, rounded, same_steps, solves)

R = Runner(sys.argv)
CUBE = "tests/scenes/cube3d.prm"
PRESS = ["Data/Constants=push=0.01, sx=0, sy=0", "Data/Dirichlet values=sx; sy; -push",
         "Solver/Tolerance=1e-12"]
PATH = ["Data/Load steps=push=0.01; sx=0.002, sy=0.001; sx=0.02, sy=0.01"]
MULTIGRID = ["Solver/Type=monotone multigrid"]  # (the cube's scene takes the active set)


def print_steps(name, run):
    # (Q / P of the pressed step is round-off: printed as its bound)
    for row in run["load_steps"] or []:
        ratio = row["tangential_force"] / row["normal_force"]
        print("%s step %d: %d stick and %d slip vertices, Q / P = %s" % (
            name, row["step"], row["stick_vertices"], row["slip_vertices"],
            "below 1e-10" if abs(ratio) < 1e-10 else rounded(ratio, 4)))


# --- Tresca: every step is the minimizer of J
tresca = PRESS + ["Friction/Law=Tresca", "Friction/Bound=0.002"] + MULTIGRID
steps = ["push=0.01", "sx=0.002, sy=0.001", "sx=0.02, sy=0.01"]
run = R.run(CUBE, tresca + PATH, "tresca")
print_steps("Tresca", run)
print("Tresca: Newton steps per solve %s" % newton_steps(run))
check(run.ok() and monotone(run) and len(solves(run)) == 3,
      "Tresca: J never increases in an iteration of any step")
check_monotone_feasible(run, "Tresca: the last step")
# (a process without contact faces takes every collective step too)
two = R.run(CUBE, tresca + PATH, "tresca_np2", processes=2)
check(two.ok() and same_steps(two, run, 1e-8),
      "Tresca: the same steps on 2 processes as on 1 (to 1e-8)")
# (the iterations may differ: J's round-off depends on the threads)
one_thread = R.run(CUBE, tresca + PATH + ["Solver/Threads=1"], "tresca_one_thread")
check(one_thread.ok() and same_steps(one_thread, run, 1e-8),
      "Tresca: the same steps on 1 thread as on 2 (to 1e-8)")
# (the KKT residuals of a step, in summary.json for the last one: the
# paths that end at each step; their steps are the whole path's)
rows = run["load_steps"] or []
kkt = []
for k in range(1, 4):
    prefix = run if k == 3 else R.run(CUBE, tresca + ["Data/Load steps=" + "; ".join(steps[:k])],
                                      "tresca_%d_steps" % k)
    kkt.append(prefix["kkt_residual"] if prefix.ok() else None)
    same = prefix.ok() and len(rows) == 3 and relative_difference(
        prefix["contact_force"], rows[k - 1]["contact_force"]) <= 1e-8
    check(same and kkt[-1] is not None and kkt[-1] <= 1e-10,
          "Tresca, step %d: the KKT conditions hold (residual <= 1e-10)" % k)
last = rows[-1] if rows else {}
print("Tresca, last step: Q / (s A) = %s" % rounded(last.get("tangential_force", 0) / 0.002, 6))
check(last.get("stick_vertices") == 0 and abs(last.get("tangential_force", 0) / 0.002 - 1) <= 1e-4,
      "Tresca, last step: every contact vertex slips, Q = s A (to 1e-4)")

# --- Coulomb: partial stick, then full slip along the push
coulomb = PRESS + PATH + ["Friction/Law=Coulomb", "Friction/Coefficient=0.3"] + MULTIGRID
run = R.run(CUBE, coulomb, "coulomb")
print_steps("Coulomb", run)
check(run.ok() and monotone(run) and len(run["load_steps"] or []) == 3
      and (run["load_steps"] or [{}])[1].get("stick_vertices", 0) > 0,
      "Coulomb, f = 0.3: a stick zone after the first shift; J never increases")

# full slip: the slips are parallel to the push only up to the body's own
# deformation (its bulge), so |Q| = f P and Q's direction hold in the limit
# of a large shift; a box of friction bounds in the mesh's axes would give
# Q along (1, 1)
slide = PRESS + ["Data/Load steps=push=0.01; sx=0.04, sy=0.02", "Friction/Law=Coulomb",
                 "Friction/Coefficient=0.1"] + MULTIGRID
run = R.run(CUBE, slide, "coulomb_full_slip")
rows = run["load_steps"] or []
last = rows[-1] if rows else {}
force = run["contact_force"] or [0, 0, 0]
ratio = last.get("tangential_force", 0) / (0.1 * last.get("normal_force", 1))
direction = force[1] / force[0] if force[0] else 0
print("Coulomb, f = 0.1, moved along (2, 1): Q / (f P) = %s, Q_y / Q_x = %s" % (
    rounded(ratio, 6), rounded(direction, 4)))
check(run.ok() and len(rows) == 2 and last.get("stick_vertices") == 0
      and last.get("slip_vertices", 0) == 25 and abs(ratio - 1) <= 1e-5
      and abs(direction - 0.5) <= 1e-3,
      "Coulomb, f = 0.1, full slip: every contact vertex slips, Q = f P (to 1e-5) and Q is "
      "along (2, 1) (to 1e-3)")

# --- f = 0 is frictionless
still = PRESS + ["Data/Constants=push=0.01, sx=0.002, sy=0.001"] + MULTIGRID
zero = R.run(CUBE, still + ["Friction/Law=Coulomb", "Friction/Coefficient=0"], "f_zero")
none = R.run(CUBE, still, "frictionless")
check(zero.ok() and none.ok()
      and relative_difference(zero["contact_force"], none["contact_force"]) <= 1e-8
      and relative_difference(zero["functional"], none["functional"]) <= 1e-8,
      "f = 0: the frictionless force and J (to 1e-8)")

# --- the 3D sliding block
for levels in (2,):
    block = R.run("prm/sliding_block_3d.prm", ["Geometry/Levels=%d" % levels],
                  "sliding_block_3d_%d" % levels)
    steps = newton_steps(block)
    rows = block["load_steps"] or []
    print("prm/sliding_block_3d.prm, %d levels: %s DoFs, %d Tresca problems, at most %d "
          "Newton steps each; stick vertices %s" % (
              levels, block["dofs"], len(steps), max(steps, default=0),
              [r["stick_vertices"] for r in rows]))
    check(block.ok() and monotone(block) and len(rows) == 5,
          "sliding block 3D, %d levels: every step converged, J never increases" % levels)

# --- the error indicators hold the friction terms (the disc's |slip| too)
for case, label in ((two, "Tresca path on 2 processes"), (run, "Coulomb, full slip"),
                    (block, "sliding block 3D")):
    total = (case["error_indicators"] or {}).get("sum", 0)
    check(case.ok() and relative_difference(total, case["functional"]) <= 1e-6,
          "%s: the cellwise parts of J (error indicators) sum to J, friction terms included "
          "(to 1e-6)" % label)
finish()
