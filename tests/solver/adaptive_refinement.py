#!/usr/bin/env python3
# The adaptive loop (Adaptivity/Steps > 0) with the active set solver on
# meshes with hanging nodes, in 2D and 3D. Checked:
# - every step converges, to a feasible KKT point (its summary);
# - the DoFs grow from step to step, and a step never goes past
#   Adaptivity/Max DoFs (the loop stops before, and says so);
# - nested spaces: on a flat obstacle the previous solution, carried over
#   to the refined mesh, is feasible and has the same J there (relative
#   difference <= 1e-7; measured 5e-9 on the square, 9e-11 on the cube,
#   1e-11 with a body force: the round-off of J; a wrong hanging-node
#   elimination or RT sign gives 1e-1 and more), and
#   J never increases from one mesh to the next (the minimum over a larger
#   feasible set);
# - on the half disc (curved contact boundary, RT faces of both
#   orientations) the carried start has J within 10% of the previous
#   solution's (measured: at most 5%; the stresses carried without the RT
#   signs gave 1e4 times J), and the Hertz pressure error falls from the
#   first mesh to the third step by more than half at the contact vertices
#   (measured 0.0929 to 0.0351) and by more than 3/4 in L2 on the contact
#   boundary (0.128 to 0.0304);
# - with a body force (constant, linear data) the same; on the
#   manufactured solution J and the H1 and H(div) errors fall with every
#   step;
# - the files: one VTU per step, solution.pvd with every step as a time
#   step, a contact table per step, adaptive_steps.csv with one row per
#   step, summary.json's "adaptive_steps".
# ctest: sanitize cost=9
import csv
import os
import re
import sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, rounded

R = Runner(sys.argv)
active_set = "Solver/Type=active set"


def step_table(run, label):
    steps = run["adaptive_steps"] or []
    for s in steps:
        print("%s, step %d: %d cells, %d DoFs, %d iterations, J %s" % (
            label, s["step"], s["cells"], s["dofs"], s["iterations"],
            rounded(s["functional"])))
    return steps


def check_files(run, label, n_steps, contact=True):
    d = run.directory
    rows = []
    if os.path.exists(os.path.join(d, "adaptive_steps.csv")):
        with open(os.path.join(d, "adaptive_steps.csv")) as f:
            rows = list(csv.DictReader(f))
    check(len(rows) == n_steps, label + ": adaptive_steps.csv has %d rows" % n_steps)
    pvd = ""
    if os.path.exists(os.path.join(d, "solution.pvd")):
        pvd = open(os.path.join(d, "solution.pvd")).read()
    bodies = re.findall(r'timestep="(\d+)"[^>]*name="body" file="(solution_\d{4}\.pvtu)"', pvd)
    check([int(t) for t, _ in bodies] == list(range(n_steps)) and
          all(os.path.exists(os.path.join(d, f)) for _, f in bodies),
          label + ": solution.pvd lists the %d steps, their files exist" % n_steps)
    if contact:
        surfaces = re.findall(r'name="contact surface" file="(contact_surface_\d{4}\.pvtu)"', pvd)
        check(len(surfaces) == n_steps and
              all(os.path.exists(os.path.join(d, f)) for f in surfaces),
              label + ": solution.pvd lists %d contact surfaces" % n_steps)
        tables = [os.path.join(d, "contact_%04d.csv" % s) for s in range(n_steps)]
        check(all(os.path.exists(t) for t in tables) and
              open(tables[-1]).read() == open(os.path.join(d, "contact.csv")).read(),
              label + ": a contact table per step, the last one is contact.csv")


def check_steps(run, label, n_steps):
    check(run.ok() and run["converged"] is True, label + ": exit code 0, converged")
    steps = step_table(run, label)
    check(len(steps) == n_steps and all(s["converged"] for s in steps),
          label + ": %d steps, each converged" % n_steps)
    check(all(b["dofs"] > a["dofs"] for a, b in zip(steps, steps[1:])),
          label + ": the DoFs grow from step to step")
    check(run["max_violation"] is not None and run["max_violation"] <= 1e-12 and
          run["kkt_residual"] is not None and run["kkt_residual"] <= 1e-10,
          label + ": the last solution is feasible (1e-12), KKT residual <= 1e-10")
    return steps


def check_nested(steps, label):
    worst = max(abs(b["functional_start"] - a["functional"]) / a["functional"]
                for a, b in zip(steps, steps[1:]))
    check(worst <= 1e-7,
          label + ": the carried solution keeps its J on the refined mesh (1e-7)")
    check(all(b["functional"] <= a["functional"] * (1 + 1e-12)
              for a, b in zip(steps, steps[1:])),
          label + ": J never increases from one mesh to the next")


# the square, 2D, flat obstacle
label = "square, 4 levels, 3 steps"
vtu = "Output/Write vtu=true"
run = R.run("prm/square.prm", [active_set, "Geometry/Levels=4", "Adaptivity/Steps=3", vtu],
            "square")
steps = check_steps(run, label, 4)
check_nested(steps, label)
check_files(run, label, 4)
check(run["adaptive_stop"] == "Adaptivity/Steps = 3 done", label + ": stopped after 3 steps")

# the DoF budget stops the loop before a mesh beyond it
label = "square, Max DoFs = 620"
run = R.run("prm/square.prm", [active_set, "Geometry/Levels=4", "Adaptivity/Steps=5",
                               "Adaptivity/Max DoFs=620"], "square_budget")
steps = step_table(run, label)
check(run.ok() and 1 <= len(steps) < 6 and all(s["dofs"] <= 620 for s in steps) and
      "Max DoFs" in (run["adaptive_stop"] or ""),
      label + ": no mesh beyond 620 DoFs, the loop says why it stopped")

# fixed-fraction marking
label = "square, fixed fraction 0.1"
run = R.run("prm/square.prm", [active_set, "Geometry/Levels=4", "Adaptivity/Steps=2",
                               "Adaptivity/Marking=fixed fraction",
                               "Adaptivity/Fraction=0.1"], "square_fraction")
steps = check_steps(run, label, 3)
check_nested(steps, label)

# a body force: the equilibrium term couples the eliminated DoFs through
# div sigma (measured: a wrong elimination of the equilibrium matrix gave
# the carried start 9.5 against J = 0.13 before)
label = "unit square, body force (1, 1), linear Dirichlet data"
run = R.run("prm/elasticity_mms.prm", [active_set, "Geometry/Levels=3", "Adaptivity/Steps=2",
                                       "Data/Dirichlet values=x; y", "Data/Body force=1; 1",
                                       "Data/Traction=0; 0"], "body_force")
steps = check_steps(run, label, 3)
check_nested(steps, label)

# the manufactured solution: the errors fall with every step
label = "manufactured solution, 3 levels, 4 steps"
run = R.run("prm/elasticity_mms.prm", [active_set, "Geometry/Levels=3", "Adaptivity/Steps=4"],
            "mms")
steps = check_steps(run, label, 5)
for s in steps:
    print("%s, step %d: |u - u_h|_H1 %s, |sigma - sigma_h|_Hdiv %s" % (
        label, s["step"], rounded(s["error_u_h1"], 4), rounded(s["error_sigma_hdiv"], 4)))
check(all(b["error_u_h1"] < a["error_u_h1"] and b["error_sigma_hdiv"] < a["error_sigma_hdiv"]
          and b["functional"] < a["functional"] for a, b in zip(steps, steps[1:])),
      label + ": J and both errors fall with every step")

# the cube, 3D: hanging vertices, edges and faces (RT0 face constraints)
label = "cube, 3 levels, 2 steps"
run = R.run("prm/cube3d.prm", [active_set, "Geometry/Levels=3", "Adaptivity/Steps=2", vtu],
            "cube")
steps = check_steps(run, label, 3)
check_nested(steps, label)
check_files(run, label, 3)

# the Hertz half disc: curved contact boundary, error indicators at the
# edge of the contact zone
label = "hertz_adaptive, 3 steps"
run = R.run("prm/hertz_adaptive.prm", [active_set, "Adaptivity/Steps=3", "Adaptivity/Max DoFs=0", vtu],
            "hertz")
steps = check_steps(run, label, 4)
check(all(abs(b["functional_start"] - a["functional"]) <= 0.1 * a["functional"]
          for a, b in zip(steps, steps[1:])),
      label + ": the carried start's J within 10% of the previous solution's")
errors = [s["hertz_pressure_error"] for s in steps]
print(label + ": pressure errors (l2 at the vertices) " + ", ".join(rounded(e, 3) for e in errors))
check(errors[-1] < 0.5 * errors[0], label + ": the vertex pressure error falls by more than half")
errors = [s["hertz_pressure_error_boundary"] for s in steps]
print(label + ": pressure errors (L2 on the boundary) " +
      ", ".join(rounded(e, 3) for e in errors))
check(errors[-1] < 0.25 * errors[0],
      label + ": the L2 pressure error falls by more than 3/4")
hertz = run["hertz"] or {}
print(label + ": contact edge between %s and %s" % (rounded(hertz.get("edge_inside"), 4),
                                                    rounded(hertz.get("edge_outside"), 4)))
check_files(run, label, 4)

finish()
