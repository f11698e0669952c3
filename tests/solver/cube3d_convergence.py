#!/usr/bin/env python3
# A 3D problem. The unit
# cube on a rigid foundation (prm/cube3d.prm, pushed down by 0.01), default
# solver, on 4 levels (7371 DoFs) and 5 levels (53907 DoFs; measured 10 s
# wall on 2 cores, so it is part of the default run). The definiteness
# check runs on level 3 (Solver/Definiteness check max dofs = 2000): on
# level 4 it costs about 20 s, ten times the solve.
# Checks: converged within 6 iterations (measured 3 and 3), no NaN/Inf,
# energy_increases == 0, every iterate feasible, KKT residual < 1e-10, all
# (2^(J-1) + 1)^2 bottom vertices in contact, the force vertical; on 4
# levels the active set solver's KKT point (force and J to 1e-8 relative,
# measured <= 3e-10); on 5 levels the force within 0.5% of that of 4
# levels (measured 0.24%; the discretization converges, the square's
# differences shrink by about 0.36 per level).
# ctest: timeout=600 cost=8
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_flat_contact_run, \
    compare_with_reference, finish, rounded

R = Runner(sys.argv)
cheap_check = ["Solver/Definiteness check max dofs=2000"]
forces = {}
for levels in [4, 5]:
    print("=== %d levels" % levels)
    settings = ["Geometry/Levels=%d" % levels] + cheap_check
    run = R.run("prm/cube3d.prm", settings, "level_%d" % levels)
    check_flat_contact_run(run, 6, (2 ** (levels - 1) + 1) ** 2)
    check(run["patch_colors"] == [8] * (levels - 1),
          "8 patch colors on every level (uniform hexahedra)")
    f = run["contact_force"] or [0, 0, 0]
    print("contact force = %s" % " ".join(
        rounded(c, 6) if abs(c) > 1e-12 * (run.force or 1) else "0"
        for c in f))
    check(run.force and abs(f[0]) < 1e-12 * run.force
          and abs(f[1]) < 1e-12 * run.force and f[2] > 0,
          "the contact force is vertical")
    forces[levels] = run.force or 0.
    if levels == 4:
        reference = R.run("prm/cube3d.prm",
                          settings + ["Solver/Type=active set"],
                          "level_4_active_set")
        compare_with_reference(run, reference, "multigrid")
change = abs(forces[5] - forces[4]) / forces[4]
print("|F_5 - F_4| / F_4 = %s" % rounded(change, 2))
check(change < 5e-3, "F_5 within 0.5% of F_4")
finish()
