#!/usr/bin/env python3
# Adaptive refinement along a load path: prm/cattaneo_mindlin_adaptive.prm,
# prm/cattaneo_mindlin.prm from 5 uniform levels with Adaptivity/Steps = 8.
# The adaptive loop runs on the first load step (pressed, Q = 0); the
# pulls Q = 0.5 f P and 0.8 f P are solved on its last mesh, each from the
# previous step's solution.
#  - the files: adaptive_steps.csv has the loop's 9 meshes (DoFs growing),
#    load_steps.csv the 3 load steps, each with the time of its files in
#    solution.pvd (8, 9, 10: after the loop's meshes), contact_000N.csv and
#    solution.pvd with a time step per solve; the load steps run on the
#    loop's last mesh (summary.json's DoFs);
#  - against Cattaneo and Mindlin's solution, as tests/solver/
#    cattaneo_mindlin does on 8 uniform levels (198,146 DoFs): the forces
#    are P and Q to 1%, the pressure within 1% of Hertz's at every step,
#    both ends of the stick zone within one vertex spacing of +-c, the
#    tangential traction within 5% of q, on at most 30% of those DoFs
#    (where the uniform mesh's pressure is within 1.5%);
#  - J never increases, every iterate feasible (the last solve);
#  - on 2 processes (from 5 levels, 3 adaptive steps) the same meshes and
#    the same forces at every load step (to 1e-8 of the normal force).
# ctest: mpirun timeout=500 cost=60
import csv
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import (CATTANEO_MINDLIN_LOADS as LOADS, CATTANEO_MINDLIN_P as P, Runner,
                        cattaneo_mindlin_2d, check, check_monotone_feasible, finish, rounded)

R = Runner(sys.argv)
UNIFORM_DOFS = 198146   # 8 uniform levels of the scene (tests/solver/cattaneo_mindlin)
STEPS = 8   # (Adaptivity/Steps of the scene)


def table(run, name):
    with open(os.path.join(run.directory, name)) as f:
        return list(csv.DictReader(f))


run = R.run("prm/cattaneo_mindlin_adaptive.prm", ["Output/Write vtu=true"], "adaptive_path")
check_monotone_feasible(run, "adaptive path")
meshes, steps = table(run, "adaptive_steps.csv"), table(run, "load_steps.csv")
dofs = [int(m["dofs"]) for m in meshes]
print("adaptive path: meshes of %s DoFs; load steps at times %s" % (
    ", ".join(map(str, dofs)), ", ".join(s["step"] for s in steps)))
with open(os.path.join(run.directory, "solution.pvd")) as f:
    pvd = f.read()
n_solves = STEPS + len(LOADS)
check(len(meshes) == STEPS + 1 and all(b > a for a, b in zip(dofs, dofs[1:]))
      and [int(s["step"]) for s in steps] == list(range(STEPS, n_solves))
      and run["dofs"] == dofs[-1]
      and 'timestep="%d"' % (n_solves - 1) in pvd and 'timestep="%d"' % n_solves not in pvd
      and all(os.path.exists(os.path.join(run.directory, "contact_%04d.csv" % k))
              for k in range(n_solves)),
      "the loop's meshes in adaptive_steps.csv, the load steps on its last mesh in "
      "load_steps.csv, a time step of solution.pvd and a contact table per solve")
print("the last mesh: %s of the DoFs of 8 uniform levels" % rounded(dofs[-1] / UNIFORM_DOFS, 3))
check(dofs[-1] <= 0.3 * UNIFORM_DOFS, "the last mesh has at most 30% of the DoFs of 8 uniform "
      "levels")
for Q, step in zip(LOADS, steps):
    with open(os.path.join(run.directory, "contact_%04d.csv" % int(step["step"]))) as f:
        rows = sorted(csv.DictReader(f), key=lambda r: float(r["x"]))
    normal, tangential = float(step["normal_force"]), float(step["tangential_force"])
    r = cattaneo_mindlin_2d(rows, normal, tangential)
    print("Q = %g: %s iterations, P = %s, Q = %s, pressure error %s%%%s" % (
        Q, step["iterations"], rounded(normal, 4), rounded(tangential if Q else 0, 4),
        rounded(100 * r["pressure_error"], 2),
        ", stick zone ends %s and %s vertex spacings from -c and c, traction error %s of |q|"
        % (rounded(r["from_error"], 2), rounded(r["to_error"], 2), rounded(r["of_q"], 2))
        if Q else ""))
    check(step["converged"] == "1" and abs(normal - P) <= 0.01 * P
          and abs(tangential - Q) <= 0.01 * max(Q, 1e-6 * P),
          "Q = %g: converged, the contact force is P and Q to 1%%" % Q)
    check(r["pressure_error"] <= 0.01, "Q = %g: the pressure within 1%% of Hertz's" % Q)
    if Q > 0:
        check(r["from_error"] <= 1 and r["to_error"] <= 1 and r["of_q"] <= 0.05,
              "Q = %g: the stick zone's ends within one vertex spacing of +-c, the tangential "
              "traction within 5%% of q" % Q)

runs = [R.run("prm/cattaneo_mindlin_adaptive.prm", ["Adaptivity/Steps=3"],
              "adaptive_path_%d" % n, processes=n) for n in (1, 2)]
if check(all(r.ok() for r in runs), "1 and 2 processes: both runs succeed"):
    one, two = ([(int(m["dofs"]), int(m["cells"])) for m in table(r, "adaptive_steps.csv")]
                for r in runs)
    rows = [table(r, "load_steps.csv") for r in runs]
    check(one == two and len(rows[0]) == len(rows[1]) == len(LOADS) and all(
        abs(float(a[k]) - float(b[k])) <= 1e-8 * float(a["normal_force"])
        for a, b in zip(*rows) for k in ("force_x", "force_y", "tangential_force")),
        "2 processes: the meshes of 1 and its forces at every load step (to 1e-8)")
finish()
