#!/usr/bin/env python3
# Friction (Friction/Law = Tresca or Coulomb) on the square pressed on its
# whole bottom, 4 levels (tests/scenes/square.prm), solved by the active set
# method (the semismooth Newton method of frictional contact):
#  - A slip bound of 0 (Tresca) and a coefficient of 0 (Coulomb) give the
#    frictionless solution: J and the contact force to 1e-8.
#  - Full slip: pressed, then its top moved sideways past the stick limit,
#    every contact vertex slips and the tangential force is Tresca's bound
#    times the contact width (to 1e-8), Coulomb's f times the normal force
#    (to 1e-6, the fixed point's Friction/Fixed point tolerance); the
#    tangential traction opposes the slip at every slipping vertex.
#  - Pressed only (a compressible body, lambda = mu, expands sideways): the
#    middle of the contact sticks and its ends slip; the stick zone shrinks
#    as f decreases.
#  - contact.csv gains the friction columns (slip, tangential traction,
#    status) with friction only; the same steps on 2 processes as on 1.
#  - Projected Gauss-Seidel, the other solver that takes friction, reaches
#    the active set method's J and force on 2 levels (to 1e-6).
# ctest: mpirun
import csv
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, relative_difference, rounded

R = Runner(sys.argv)
SQUARE = "tests/scenes/square.prm"
PRESS = ["Data/Constants=push=0.01, shift=0", "Data/Dirichlet values=shift; -push",
         "Solver/Type=active set", "Solver/Tolerance=1e-12"]
PATH = ["Data/Load steps=push=0.01; shift=0.002; shift=0.02"]


def table(directory, name="contact.csv"):
    with open(os.path.join(directory, name)) as f:
        return list(csv.DictReader(f))


def show(run, label):
    for row in run["load_steps"] or []:
        print("%s step %d: shift %s, normal force %s, tangential force %s, "
              "%d stick and %d slip vertices" % (
                  label, row["step"], rounded(row["constants"]["shift"]),
                  rounded(row["normal_force"]), rounded(row["tangential_force"]),
                  row["stick_vertices"], row["slip_vertices"]))


# --- no friction from a zero bound or coefficient
plain = R.run(SQUARE, PRESS, "frictionless")
for law, value in (("Tresca", "Friction/Bound=0"), ("Coulomb", "Friction/Coefficient=0")):
    zero = R.run(SQUARE, PRESS + ["Friction/Law=" + law, value], law + "_zero")
    check(plain.ok() and zero.ok()
          and relative_difference(zero["functional"], plain["functional"]) <= 1e-8
          and relative_difference(zero["contact_force"], plain["contact_force"]) <= 1e-8,
          "%s with 0: the frictionless J and contact force (to 1e-8)" % law)
check("slip_x" not in table(plain.directory)[0] and "friction" not in plain.summary,
      "frictionless: no friction columns in contact.csv, no friction in summary.json")

# --- Tresca: full slip at the bound times the width
s = 0.001
tresca = R.run(SQUARE, PRESS + PATH + ["Friction/Law=Tresca", "Friction/Bound=%g" % s],
               "tresca_path")
show(tresca, "Tresca")
steps = tresca["load_steps"] or []
last = steps[-1] if steps else {}
check(tresca.ok() and len(steps) == 3 and all(r["converged"] for r in steps),
      "Tresca: the three steps converge")
check(abs(last.get("tangential_force", 0) - s * last.get("contact_width", 0)) <= 1e-8 * s,
      "Tresca: sliding, the tangential force is the bound times the contact width (to 1e-8)")
rows = table(tresca.directory)
slipping = [r for r in rows if r["status"] == "2"]
check(len(slipping) == last.get("vertices_in_contact") == last.get("slip_vertices")
      and last.get("stick_vertices") == 0,
      "Tresca: sliding, every contact vertex slips")
check(all(float(r["slip_x"]) * float(r["traction_t_x"]) < 0 for r in slipping),
      "Tresca: the tangential traction opposes the slip")
check(tresca["friction"] and tresca["friction"]["law"] == "Tresca"
      and tresca["friction"]["tangential_force"] == last.get("tangential_force"),
      "Tresca: summary.json's friction is the last step's")

# --- Coulomb: full slip at f times the normal force
f = 0.3
coulomb = R.run(SQUARE, PRESS + PATH + ["Friction/Law=Coulomb", "Friction/Coefficient=%g" % f],
                "coulomb_path")
show(coulomb, "Coulomb")
steps = coulomb["load_steps"] or []
last = steps[-1] if steps else {}
check(coulomb.ok() and len(steps) == 3 and all(r["converged"] for r in steps),
      "Coulomb: the three steps converge")
check(relative_difference(last.get("tangential_force", 0), f * last.get("normal_force", 0)) <= 1e-6
      and last.get("stick_vertices") == 0,
      "Coulomb: sliding, the tangential force is f times the normal force (to 1e-6)")
print("Coulomb: %d Tresca problems in the last step" %
      (coulomb["friction"] or {}).get("fixed_point_iterations", 0))

# --- pressed only: a stick zone in the middle that shrinks with f
sticks = []
for f in (1, 0.3, 0.1):
    run = R.run(SQUARE, PRESS + ["Friction/Law=Coulomb", "Friction/Coefficient=%g" % f],
                "press_f%g" % f)
    friction = run["friction"] or {}
    sticks.append(friction.get("stick_vertices", -1))
    rows = table(run.directory)
    middle = [r for r in rows if r["status"] == "1"]
    print("pressed, f = %g: %d stick and %d slip vertices, stuck from x = %s to %s" % (
        f, friction.get("stick_vertices", -1), friction.get("slip_vertices", -1),
        min((r["x"] for r in middle), default="-"), max((r["x"] for r in middle), default="-")))
    check(run.ok() and middle and all(0 < float(r["x"]) < 1 for r in middle)
          and rows[0]["status"] == "2" and rows[-1]["status"] in ("0", "2"),
          "pressed, f = %g: the middle sticks, the ends slip" % f)
check(sticks[0] > sticks[1] > sticks[2] > 0, "pressed: the stick zone shrinks as f decreases")

# --- 2 processes: the same steps
two = R.run(SQUARE, PRESS + PATH + ["Friction/Law=Coulomb", "Friction/Coefficient=0.3"],
            "coulomb_path_2", processes=2)


def same_steps(a, b):
    """The same stick and slip vertices, and forces to 1e-8 of the normal force."""
    a, b = a["load_steps"] or [], b["load_steps"] or []
    return len(a) == len(b) > 0 and all(
        (r["stick_vertices"], r["slip_vertices"]) == (s["stick_vertices"], s["slip_vertices"])
        and abs(r["normal_force"] - s["normal_force"]) <= 1e-8 * r["normal_force"]
        and abs(r["tangential_force"] - s["tangential_force"]) <= 1e-8 * r["normal_force"]
        for r, s in zip(a, b))


check(two.ok() and same_steps(two, coulomb), "Coulomb: the same steps on 2 processes as on 1")

# --- projected Gauss-Seidel against the active set method
small = ["Geometry/Levels=2", "Friction/Law=Tresca", "Friction/Bound=0.005"]
reference = R.run(SQUARE, PRESS + small, "small_active_set")
pgs = R.run(SQUARE, PRESS + small + ["Solver/Type=projected gauss seidel",
                                     "Solver/Max iterations=100000"], "small_pgs")
print("2 levels: projected Gauss-Seidel %d iterations" % (pgs["iterations"] or 0))
check(pgs.ok() and pgs["converged"] is True
      and relative_difference(pgs["functional"], reference["functional"]) <= 1e-6
      and relative_difference(pgs["contact_force"], reference["contact_force"]) <= 1e-6,
      "2 levels: projected Gauss-Seidel reaches the active set method's J and force (to 1e-6)")
finish()
