#!/usr/bin/env python3
# Quasi-static load steps (Data/Load steps): each step takes new values of
# constants of Data/Constants, sets the levels' data up again on the same
# mesh and starts from the previous step's solution.
#  - Without friction the answer does not depend on the path: the last step
#    of a path is the one-step run with the last step's constants (J and the
#    contact force to 1e-6, both converged to Solver/Tolerance), on the half
#    disc (the contact zone grows along the path) and on the square whose
#    obstacle normal turns with a constant (the rotations of the contact
#    DoFs are set up again).
#  - The square pressed on its whole bottom is linear in the push: the
#    forces of the steps are in the ratio of the pushes (to 1e-8), the
#    reaction of the pushed top balances the contact force (to 1e-5: their
#    sum is the integral of div sigma, the equilibrium residual of the
#    least-squares solution, 1.3e-6 of the force on 4 levels).
#  - The table: load_steps.csv and summary.json "load_steps" with a row per
#    step (the constants, iterations, forces, the contact zone, the
#    reactions), contact_NNNN.csv per step with contact.csv the last one's,
#    solution.pvd with a time step per load step; the same rows on 2
#    processes as on 1. The tangential force is 0 without friction.
#  - A run without Load steps writes none of it.
#  - SIGTERM once the screen says "Load step 2 of 3": exit code 4, one line
#    naming the step under way; the finished steps published as one set
#    (load_steps.csv and contact_000k.csv of exactly those).
# ctest: mpirun sanitize cost=11
import csv
import json
import os
import signal
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, command_line, finish, relative_difference, rounded

R = Runner(sys.argv)
MG = "Solver/Type=monotone multigrid"


def rows_of(directory):
    """The rows of load_steps.csv in @p directory (dicts of floats), [] if missing."""
    try:
        with open(os.path.join(directory, "load_steps.csv")) as f:
            return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    except OSError:
        return []


def show(run, label):
    for row in run["load_steps"] or []:
        print("%s step %d: %s, %d iterations, normal force %s, "
              "%d vertices in contact, width %s, peak pressure %s" % (
                  label, row["step"],
                  ", ".join("%s = %s" % (k, rounded(v)) for k, v in row["constants"].items()),
                  row["iterations"], rounded(row["normal_force"]), row["vertices_in_contact"],
                  rounded(row["contact_width"]), rounded(row["peak_pressure"])))


def check_path_independent(path, direct, label):
    check(path.ok() and path["converged"] is True and direct.ok()
          and direct["converged"] is True, label + ": both runs converge")
    check(relative_difference(path["functional"], direct["functional"]) <= 1e-6
          and relative_difference(path["contact_force"], direct["contact_force"]) <= 1e-6,
          label + ": the path's last step is the one-step run (J and the force to 1e-6)")


# --- the half disc pressed in two steps
disc = ["Geometry/Levels=3", MG]
path = R.run("prm/hertz.prm", disc + ["Data/Load steps=push=0.005; push=0.01"], "disc_path")
direct = R.run("prm/hertz.prm", disc, "disc_direct")
show(path, "half disc")
check_path_independent(path, direct, "half disc")
steps = path["load_steps"] or []
rows = rows_of(path.directory)
check(len(steps) == 2 and len(rows) == 2
      and [r["constants"]["push"] for r in steps] == [0.005, 0.01]
      and [r["push"] for r in rows] == [0.005, 0.01],
      "half disc: two rows in summary.json and load_steps.csv, with the push of each")
check(steps and steps[1]["normal_force"] > 1.5 * steps[0]["normal_force"] > 0
      and steps[1]["contact_width"] >= steps[0]["contact_width"] > 0
      and steps[1]["vertices_in_contact"] >= steps[0]["vertices_in_contact"],
      "half disc: the force and the contact zone grow with the push")
check(steps and all(abs(r["tangential_force"]) <= 1e-8 * r["normal_force"] for r in steps),
      "half disc: no tangential force without friction")
last = steps[-1] if steps else {}
check(relative_difference(last.get("contact_force"), path["contact_force"]) == 0
      and relative_difference(last.get("reactions", {}).get("1"),
                              path["boundary_forces"]["dirichlet"]["1"]) == 0,
      "half disc: the last row's forces are summary.json's")
check(relative_difference([-c for c in last.get("reactions", {}).get("1", [0, 0])],
                          last.get("contact_force")) <= 1e-3,
      "half disc: the reaction of the clamped top balances the contact force (to 1e-3)")
tables = [os.path.exists(os.path.join(path.directory, "contact_%04d.csv" % s)) for s in (0, 1)]
with open(os.path.join(path.directory, "contact.csv")) as f, \
        open(os.path.join(path.directory, "contact_0001.csv")) as g:
    same = f.read() == g.read()
check(all(tables) and same, "half disc: contact_0000.csv, contact_0001.csv; contact.csv the last")
check(path["adaptive_steps"] is None and not rows_of(direct.directory) and direct["load_steps"] is None
      and not os.path.exists(os.path.join(direct.directory, "contact_0000.csv")),
      "half disc: a run without load steps writes no step table")
check("Load step 1 of 2: push = 0.005" in path.screen
      and "Load step 2 of 2: push = 0.01" in path.screen
      and "Initial guess: the previous load step's solution" in path.screen,
      "half disc: the screen names each step and its start")

plot = subprocess.run([sys.executable, os.path.join(R.source, "scripts", "plot.py"),
                       path.directory], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
check(plot.returncode == 0 and os.path.exists(os.path.join(path.directory, "load_path.png")),
      "half disc: plot.py draws the force against the push (load_path.png)")

# (on 2 processes: the same rows, rounded)
two = R.run("prm/hertz.prm", disc + ["Data/Load steps=push=0.005; push=0.01"], "disc_path_2",
            processes=2)


def table(run):
    return [(r["iterations"], r["vertices_in_contact"], rounded(r["normal_force"], 6),
             rounded(r["contact_width"], 6)) for r in run["load_steps"] or []]


print("half disc on 2 processes: %s" % table(two))
check(two.ok() and table(two) == table(path) and table(two),
      "half disc: the same steps on 2 processes as on 1")

# --- the square pressed on its whole bottom: linear in the push
square = ["Data/Constants=push=0.01", "Data/Dirichlet values=0; -push", MG]
linear = R.run("tests/scenes/square.prm",
               square + ["Data/Load steps=push=0.005; push=0.01; push=0.02"], "square_path")
show(linear, "square")
steps = linear["load_steps"] or []
forces = [r["contact_force"][1] for r in steps]
check(len(forces) == 3 and all(abs(forces[s] / forces[0] - (1, 2, 4)[s]) <= 1e-8 for s in (1, 2)),
      "square: the contact forces in the ratio of the pushes, 1 : 2 : 4 (to 1e-8)")
check(len(steps) == 3 and all(
    relative_difference([-c for c in r["reactions"]["3"]], r["contact_force"]) <= 1e-5
    for r in steps), "square: the top's reaction balances the contact force (to 1e-5)")
check(len(steps) == 3 and len({r["vertices_in_contact"] for r in steps}) == 1,
      "square: the whole bottom in contact at every step")

# --- an obstacle normal turned by a constant: the rotations follow the step
turned = square + ["Data/Constants=push=0.01, a=0.05", "Data/Obstacle normal=sin(a); -cos(a)"]
path = R.run("tests/scenes/square.prm", turned + ["Data/Load steps=a=0; a=0.05"], "turned_path")
direct = R.run("tests/scenes/square.prm", turned, "turned_direct")
show(path, "turned normal")
check_path_independent(path, direct, "turned normal")

# --- VTU: a time step of solution.pvd per load step
vtu = R.run("tests/scenes/square.prm",
            square + ["Data/Load steps=push=0.005; push=0.01", "Output/Write vtu=true",
                      "Geometry/Levels=3"], "square_vtu")
with open(os.path.join(vtu.directory, "solution.pvd")) as f:
    pvd = f.read()
check(vtu.ok() and 'timestep="0"' in pvd and 'timestep="1"' in pvd and 'timestep="2"' not in pvd
      and all(os.path.exists(os.path.join(vtu.directory, "solution_%04d.pvtu" % s))
              for s in (0, 1)),
      "VTU: solution.pvd holds both load steps, each its own solution_NNNN.pvtu")
# --- interrupted along the path
command = command_line(R.exe, os.path.join(R.source, "prm", "hertz.prm"),
                       ["Output/Directory=interrupted", "Output/Write vtu=false", MG,
                        "Data/Load steps=push=0.005; push=0.0075; push=0.01"])
process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                           start_new_session=True)
for line in process.stdout:
    if line.startswith("Load step 2 of 3"):
        process.send_signal(signal.SIGTERM)
        break
process.stdout.read()
err = process.stderr.read().strip().splitlines()
code = process.wait(timeout=300)
rows = rows_of("interrupted")
finished = len(rows)
print("interrupted: exit code %d, %d finished step(s)" % (code, finished))
check(code == 4 and len(err) == 1 and "SIGTERM in load step %d" % (finished + 1) in err[0],
      "interrupted: exit code 4, one line naming the step under way")
check(finished >= 1 and all(r["converged"] == 1 for r in rows)
      and all(os.path.exists(os.path.join("interrupted", "contact_%04d.csv" % k))
              for k in range(finished))
      and not os.path.exists(os.path.join("interrupted", "contact_%04d.csv" % finished)),
      "interrupted: the finished steps published, each with its contact table")
finish()
