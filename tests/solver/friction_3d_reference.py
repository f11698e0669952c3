#!/usr/bin/env python3
# 3D friction: the monotone multigrid against projected Gauss-Seidel, whose
# 2x2 pair blocks relax each face's tangential traction in its disc and each
# vertex's slip with its Euclidean norm (TangentialPair), one pair at a
# time: a reference that shares neither the patches nor the Newton step.
# The unit cube (tests/scenes/cube3d.prm) on 2 levels (189 DoFs: projected
# Gauss-Seidel's sweeps stall on finer meshes), pressed and moved along (2, 1),
# Tresca (s = 0.002): the same stick and slip vertices, forces to 1e-6 of
# the normal force and J to 1e-6 in both steps.
# prm/sliding_block_3d.prm on 3 levels (3,903 DoFs, five load steps of
# Coulomb friction): every step converges and J never increases; the
# Newton steps per Tresca problem printed.
# ctest: timeout=900 cost=153
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, monotone, newton_steps, relative_difference, solves

R = Runner(sys.argv)
CUBE = "tests/scenes/cube3d.prm"
SETTINGS = ["Geometry/Levels=2", "Data/Constants=push=0.01, sx=0, sy=0",
            "Data/Dirichlet values=sx; sy; -push", "Data/Load steps=push=0.01; sx=0.002, sy=0.001",
            "Friction/Law=Tresca", "Friction/Bound=0.002", "Solver/Tolerance=1e-10"]
multigrid = R.run(CUBE, SETTINGS + ["Solver/Type=monotone multigrid"], "multigrid")
reference = R.run(CUBE, SETTINGS + ["Solver/Type=projected gauss seidel",
                                    "Solver/Max iterations=200000"], "pgs")
a, b = multigrid["load_steps"] or [], reference["load_steps"] or []
for r in a:
    print("step %d: %d stick and %d slip vertices" % (r["step"], r["stick_vertices"],
                                                     r["slip_vertices"]))
check(multigrid.ok() and reference.ok() and len(a) == len(b) == 2 and all(
    (r["stick_vertices"], r["slip_vertices"]) == (s["stick_vertices"], s["slip_vertices"])
    and abs(r["normal_force"] - s["normal_force"]) <= 1e-6 * r["normal_force"]
    and abs(r["tangential_force"] - s["tangential_force"]) <= 1e-6 * r["normal_force"]
    and relative_difference(r["functional"], s["functional"]) <= 1e-6
    for r, s in zip(a, b)),
      "2 levels, Tresca: projected Gauss-Seidel's steps (to 1e-6)")

block = R.run("prm/sliding_block_3d.prm", ["Geometry/Levels=3"], "sliding_block_3d_3")
rows = block["load_steps"] or []
print("prm/sliding_block_3d.prm, 3 levels: %s DoFs, %d Tresca problems, at most %d Newton steps "
      "each; stick vertices %s" % (block["dofs"], len(solves(block)),
                                   max(newton_steps(block), default=0),
                                   [r["stick_vertices"] for r in rows]))
check(block.ok() and len(rows) == 5 and len(solves(block)) >= 5 and monotone(block),
      "sliding block 3D, 3 levels: every step converged, J never increases")
finish()
