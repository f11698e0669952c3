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
#    as f decreases; a fixed point cut short ends as not converged.
#  - contact.csv gains the friction columns (slip, tangential traction,
#    status) with friction only; the same steps on 2 processes as on 1.
#  - prm/sliding_block.prm (on 3 levels) ends sliding at Q = f P (to 2%).
#  - The error indicators (the cellwise parts of J) hold the friction terms:
#    their sum is J on the paths, on 1 and 2 processes (to 1e-6).
#  - Projected Gauss-Seidel, the other solver that takes friction, reaches
#    the active set method's J and force on 2 levels (to 1e-6).
# ctest: mpirun cost=42
import csv
import math
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
    friction = zero["friction"] or {}
    check(friction.get("stick_vertices") == 0 and friction.get("slip_vertices", 0) > 0,
          "%s with 0: no vertex sticks (the stick zone of the pressed square is gone)" % law)
check("slip_x" not in table(plain.directory)[0] and "friction" not in plain.summary,
      "frictionless: no friction columns in contact.csv, no friction in summary.json")

def path(law, setting):
    """The load path PATH with friction @p law (@p setting its datum): the
    run, its steps and its last step; checks that the steps converge."""
    run = R.run(SQUARE, PRESS + PATH + ["Friction/Law=" + law, setting], law + "_path")
    show(run, law)
    steps = run["load_steps"] or []
    check(run.ok() and len(steps) == 3 and all(r["converged"] for r in steps),
          law + ": the three steps converge")
    return run, steps, steps[-1] if steps else {}


# --- Tresca: full slip at the bound times the width
s = 0.001
tresca, steps, last = path("Tresca", "Friction/Bound=%g" % s)
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
coulomb, steps, last = path("Coulomb", "Friction/Coefficient=%g" % f)
difference = relative_difference(last.get("tangential_force", 0), f * last.get("normal_force", 0))
check(difference <= 1e-6 and last.get("stick_vertices") == 0,
      "Coulomb: sliding, the tangential force is f times the normal force (to 1e-6)")
print("Coulomb: sliding, |Q - f P| / (f P) below %s; %d Tresca problems in the last step" % (
    "1e%d" % math.ceil(math.log10(max(difference, 1e-300))),
    (coulomb["friction"] or {}).get("fixed_point_iterations", 0)))

# --- pressed only: a stick zone in the middle that shrinks with f
sticks = []
for f in (1, 0.3, 0.1):
    run = R.run(SQUARE, PRESS + ["Friction/Law=Coulomb", "Friction/Coefficient=%g" % f],
                "press_f%g" % f)
    friction = run["friction"] or {}
    sticks.append(friction.get("stick_vertices", -1))
    rows = table(run.directory)
    middle = [r for r in rows if r["status"] == "1"]
    print("pressed, f = %g: %d stick and %d slip vertices, stuck from x = %s to %s, "
          "%d Tresca problems" % (
              f, friction.get("stick_vertices", -1), friction.get("slip_vertices", -1),
              min((r["x"] for r in middle), default="-"),
              max((r["x"] for r in middle), default="-"),
              friction.get("fixed_point_iterations", 0)))
    check(run.ok() and middle and all(0 < float(r["x"]) < 1 for r in middle)
          and rows[0]["status"] == "2" and rows[-1]["status"] in ("0", "2"),
          "pressed, f = %g: the middle sticks, the ends slip" % f)
check(sticks[0] > sticks[1] > sticks[2] > 0, "pressed: the stick zone shrinks as f decreases")
short = R.run(SQUARE, PRESS + ["Friction/Law=Coulomb", "Friction/Coefficient=0.3",
                               "Friction/Fixed point iterations=2"], "press_short")
check(short.ok() and short["converged"] is False and short.returncode == 2
      and "the Coulomb fixed point still changes the slip bounds" in short.stderr,
      "pressed, f = 0.3, 2 Tresca problems: not converged (exit code 2), naming the fixed point")

# --- the definiteness limit of C_compl with the friction term (C_compl = auto)
limits = []
for law in ("none", "Coulomb"):
    run = R.run(SQUARE, PRESS + ["Functional weights/C_compl=auto", "Friction/Law=" + law,
                                 "Friction/Coefficient=0.3"], "limit_" + law)
    limits.append((run["functional_weights"] or {}).get("C_compl_limit"))
print("the largest definite C_compl: %s without friction, %s with" % tuple(
    rounded(v, 4) for v in limits))
check(all(limits) and limits[1] < limits[0],
      "the friction term lowers the definiteness limit of C_compl")

# --- a known limit: an incompressible body on a curved contact boundary.
# Its pressure sigma = p I costs nothing in the functional, and with the
# tangential tractions free its traction p n, which has a tangential part
# on the curve, is held by the complementarity term alone: on 3 levels of
# the half disc the Schur complement is indefinite without it (refused,
# naming lambda); on 4 levels graded with exponent 3 the largest definite
# C_compl collapses, auto takes it, and the run warns.
disc = ["Material/lambda=inf", "Solver/Type=active set", "Friction/Bound=0.001",
        "Functional weights/C_compl=auto"]
refused = R.run("prm/hertz.prm", disc + ["Geometry/Levels=3", "Friction/Law=Tresca"],
                "incompressible_3")
lines = refused.stderr.strip().splitlines()
check(refused.returncode == 1 and len(lines) == 1
      and "Material/lambda = inf) is free on a curved contact boundary" in lines[0],
      "half disc, lambda = inf, 3 levels: refused, naming lambda")
collapse = [R.run("prm/hertz.prm", disc + ["Geometry/Levels=4", "Geometry/Grading=3",
                                           "Friction/Law=" + law],
                  "incompressible_4_" + law) for law in ("none", "Tresca")]
limits = [(r["functional_weights"] or {}).get("C_compl_limit") or 0 for r in collapse]
print("half disc, lambda = inf, 4 graded levels: the largest definite C_compl %s without friction, "
      "below %s with" % (rounded(limits[0], 3),
                         "1e%d" % math.ceil(math.log10(max(limits[1], 1e-300)))))
check(limits[0] > 0.1 and 0 < limits[1] < 1e-3 * limits[0]
      and "Warning: with friction C_compl = auto takes" in collapse[1].screen
      and "Warning: with friction" not in collapse[0].screen,
      "half disc, lambda = inf, 4 graded levels: the limit collapses with friction, and the run warns")

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

# --- the shipped scene, on 3 levels: it ends sliding
block = R.run("prm/sliding_block.prm", ["Geometry/Levels=3"], "sliding_block")
steps = block["load_steps"] or []
ratio = steps[-1]["tangential_force"] / (0.5 * steps[-1]["normal_force"]) if steps else 0
print("prm/sliding_block.prm, 3 levels: stick vertices %s, last Q / (f P) = %s" % (
    [r["stick_vertices"] for r in steps], rounded(ratio, 3)))
# (not to 1e-6 as on the square: the faces at the lifted trailing edge, in
# contact at one vertex only, stay below their slip bound on this coarse
# mesh; complementarity is a weighted term of J, not a constraint)
check(block.ok() and len(steps) == 5 and steps[0]["stick_vertices"] > 0
      and steps[-1]["stick_vertices"] == 0 and abs(ratio - 1) <= 2e-2,
      "prm/sliding_block.prm: pressed, it sticks in part; moved 2 mm, every vertex slips "
      "and Q = f P to 2%")

# --- the error indicators hold the friction terms: their sum is J (without
# them it falls short of J by the friction term)
for run, label in ((tresca, "Tresca path"), (coulomb, "Coulomb path"),
                   (two, "Coulomb path on 2 processes"), (block, "prm/sliding_block.prm")):
    total = (run["error_indicators"] or {}).get("sum", 0)
    check(run.ok() and relative_difference(total, run["functional"]) <= 1e-6,
          "%s: the cellwise parts of J (error indicators) sum to J, friction terms included "
          "(to 1e-6)" % label)

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
