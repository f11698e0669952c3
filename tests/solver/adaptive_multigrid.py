#!/usr/bin/env python3
# The monotone multigrid on adaptively refined meshes (LevelMeshes: one
# level per mesh level, each below the adaptive mesh the one above with
# every family coarsened once, meshes with hanging nodes of their own).
# Every step of every run solves its problem
# a second time with the active set method (Solver/Cross check). Checked:
# - every step converges; J never goes up within a solve (no energy
#   increase) and the last solution is feasible;
# - the multigrid solution is the active set method's on the same mesh: J
#   to 1e-10 relative (measured 1e-13 on the Hertz half disc, 1e-11 on the
#   L-shape after 10 steps), every DoF value to 1e-6 of the largest
#   (measured 2e-7 on the Hertz half disc after 4 steps and 5e-8 on the
#   L-shape with 12 levels: the round-off floor of the corrections grows
#   with the depth of the mesh; a wrong prolongation, a missing hanging
#   node master or a coarse obstacle that is not one stops far above);
# - the number of cycles does not grow with the adaptive steps: no step
#   above 1.6 times the first (uniform) mesh's (measured on the half disc
#   47, 44, 38, 62, 43 over 4 steps, 7 levels; on the L-shape 8 to 11
#   over 8 steps, 11 levels, where uniform meshes take 10 on every level;
#   a hierarchy whose coarse levels miss the refined region would take
#   more cycles with every level);
# - the default (Newton-accelerated) cycle and the plain cycle (Krylov
#   steps = 0) on the square, 2D and the cube, 3D (hanging faces and
#   edges);
# - the plain cycle with 1 and 2 threads (the patch colors include the
#   couplings through eliminated hanging nodes): the same meshes and
#   cycles at every step, J to 1e-7 (measured 8e-9: the assembled
#   matrices differ in their last digits with the thread count, and J, a
#   small difference of O(1) terms, magnifies that; each run's J is its
#   active set solution's to 2e-16).
# ctest: sanitize cost=19
import os
import sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, relative_difference, rounded

R = Runner(sys.argv)
multigrid = ["Solver/Type=monotone multigrid", "Solver/Cross check=true"]


def check_run(run, label, n_steps, cycle_growth=True):
    check(run.ok() and run["converged"] is True, label + ": exit code 0, converged")
    steps = run["adaptive_steps"] or []
    for s in steps:
        print("%s, step %d: %d DoFs, %d iterations, %d cycles, J %s" % (
            label, s["step"], s["dofs"], s["iterations"], s["cycles"],
            rounded(s["functional"])))
    check(len(steps) == n_steps and all(s["converged"] for s in steps),
          label + ": %d steps, each converged" % n_steps)
    check(all(s["energy_increases"] == 0 for s in steps),
          label + ": J never increased within a solve")
    check(run["max_violation"] is not None and run["max_violation"] <= 1e-12,
          label + ": the last solution is feasible (1e-12)")
    worst_J = max((s["cross_check_functional"] for s in steps), default=1)
    worst_x = max((s["cross_check_solution"] for s in steps), default=1)
    check(worst_J <= 1e-10, label + ": J is the active set method's to 1e-10 at every step")
    check(worst_x <= 1e-6,
          label + ": every DoF value the active set method's to 1e-6 of the largest")
    if cycle_growth and steps:
        first = steps[0]["cycles"]
        check(all(s["cycles"] <= 1.6 * first for s in steps),
              label + ": the cycles do not grow with the steps (at most 1.6 times the "
              "first mesh's)")
    return steps


label = "hertz_adaptive, 4 steps"
run = R.run("prm/hertz_adaptive.prm", multigrid + ["Adaptivity/Steps=4"], "hertz")
check_run(run, label, 5)
levels = run["level_dofs"] or []
print(label + ": %d levels, DoFs %s" % (len(levels), ", ".join(str(n) for n in levels)))
check(len(levels) == 7 and all(b >= a for a, b in zip(levels, levels[1:])),
      label + ": 7 levels (3 uniform, 3 between, the adaptive mesh), nested")
# every family coarsened at once from level to level: the levels between
# shrink toward the uniform ones and together hold fewer DoFs than twice
# the adaptive mesh (measured 1.25 times; all levels 2.7 times, the uniform
# base being a third of the finest; a sequence capped at each mesh level
# would hold about the adaptive mesh's DoFs on every level between)
check(sum(levels[3:-1]) < 2 * levels[-1] and all(b > a for a, b in zip(levels[2:], levels[3:])),
      label + ": the levels between the uniform ones and the adaptive mesh hold fewer DoFs "
      "than twice the adaptive mesh's, each more than the one below")
# memory by level on the adaptive hierarchy: the discretization's level data
# on the uniform levels and the adaptive mesh (the finest), none on the
# levels between, whose meshes (LevelMeshes' own, with their level data)
# and prolongations are on their levels; the assembled problem on the
# finest level only
by_level = run["memory_mb_by_level"] or {}
level_data = by_level.get("level data (coupling patterns, DoF tables, roles, bounds)", [])
meshes = by_level.get("multigrid: meshes of the adaptive levels", [])
problem = by_level.get("assembled problem (A, parts of J, vectors)", [])
check(all(len(v) == len(levels) for v in by_level.values())
      and len(level_data) == 7 and all(mb > 0 for mb in level_data[1:3] + level_data[6:])
      and all(mb == 0 for mb in level_data[3:6])
      and len(meshes) == 7 and all(mb == 0 for mb in meshes[:3]) and all(mb > 0 for mb in meshes[3:])
      and len(problem) == 7 and problem[-1] > 0 and all(mb == 0 for mb in problem[:-1]),
      label + ": memory_mb_by_level has a list per level of the hierarchy; the level data "
      "on the uniform levels and the adaptive mesh, the meshes between on theirs, the "
      "assembled problem on the finest")

label = "l_shape_singular, 8 steps"
run = R.run("prm/l_shape_singular.prm", multigrid + ["Adaptivity/Steps=8"], "l_shape")
check_run(run, label, 9)

label = "square, 4 levels, 3 steps"
square = ["prm/square.prm", multigrid + ["Geometry/Levels=4", "Adaptivity/Steps=3"]]
run = R.run(square[0], square[1], "square")
check_run(run, label, 4)

label = "square, plain cycle"
run = R.run(square[0], square[1] + ["Solver/Krylov steps=0"], "square_plain")
check_run(run, label, 4, cycle_growth=False)

label = "cube, 3 levels, 2 steps"
run = R.run("prm/cube3d.prm", multigrid + ["Geometry/Levels=3", "Adaptivity/Steps=2"], "cube")
check_run(run, label, 3)

label = "square, plain cycle, 1 and 2 threads"
plain = square[1] + ["Solver/Krylov steps=0"]
one = R.run(square[0], plain + ["Solver/Threads=1"], "square_1")
two = R.run(square[0], plain + ["Solver/Threads=2"], "square_2")
a, b = one["adaptive_steps"] or [], two["adaptive_steps"] or []
check(len(a) == 4 and len(b) == 4 and
      all(s["dofs"] == t["dofs"] and s["cycles"] == t["cycles"] and
          relative_difference(s["functional"], t["functional"]) <= 1e-7 for s, t in zip(a, b)),
      label + ": the same meshes, cycles, and J to 1e-7 at every step")

finish()
