#!/usr/bin/env python3
# Functional weights/C_compl = auto, the default, and the data checked only
# where the scene uses them.
#  - The square, 4 levels: auto takes the cap 0.1 and computes the limit of
#    definiteness on the finest level, which must lie in the bracket
#    [0.2974, 0.2986] that bench/definiteness_limit.py --bisect finds by
#    bisecting accepted and refused weights; the run is the same as with
#    C_compl = 0.1 given (J and force to 1e-12). C_compl = 0.3 is refused,
#    and the message names the largest accepted value, in the same bracket.
#  - The user's punch (prm/punch.prm, a Gmsh mesh of 256 unstructured quads,
#    mm/N/MPa), 3 levels, checked on level 2: auto takes half the limit of
#    level 2 (bracket [0.0618, 0.0638]), below the cap, and the run
#    converges; its force agrees to 1e-3 with C_compl = 0.03 given (a
#    weight below the limit, which a user's scene may set). C_compl = 0.1
#    is refused, naming the largest accepted value X (the limit less the
#    50% margin of a check on a coarser level): 0.99 X is accepted, 1.01 X
#    refused.
#  - used_parameters.prm of the auto run holds the weight taken, and runs
#    the same functional again (J to 1e-12).
#  - Data are parsed where the scene uses them: a 3D scene without Neumann
#    boundary and with every component of its Dirichlet boundaries
#    prescribed runs with a 2-component traction; with a Neumann boundary,
#    or a Dirichlet boundary that leaves a component free (a roller, where
#    the traction acts on the free component), the same traction is refused
#    naming 'Data/Traction'.
# ctest: cost=12
import os
import re
import sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_refused, finish, relative_difference, rounded

R = Runner(sys.argv)
ACCEPTED = re.compile(r"the largest accepted value on this mesh is ([0-9.eE+-]+)")


def weights(run):
    return run["functional_weights"] or {}


def accepted_value(run):
    m = ACCEPTED.search(run.stderr)
    return float(m.group(1)) if m else None


print("=== square, 4 levels")
auto = R.run("prm/square.prm", ["Geometry/Levels=4"], "square_auto")
given = R.run("prm/square.prm", ["Geometry/Levels=4", "Functional weights/C_compl=0.1"],
              "square_given")
w = weights(auto)
print("auto: C_compl = %s, limit = %s" % (rounded(w.get("C_compl"), 4),
                                          rounded(w.get("C_compl_limit"), 4)))
check(auto.ok() and w.get("C_compl_auto") is True and w.get("C_compl") == 0.1,
      "auto takes the cap 0.1")
check(0.2974 <= (w.get("C_compl_limit") or 0) <= 0.2986,
      "the computed limit lies in the bisected bracket [0.2974, 0.2986]")
check(given.ok() and weights(given).get("C_compl_auto") is False
      and relative_difference(auto["functional"], given["functional"]) < 1e-12
      and relative_difference(auto["contact_force"], given["contact_force"]) < 1e-12,
      "the same run as with C_compl = 0.1 given")
refused = R.run("prm/square.prm", ["Geometry/Levels=4", "Functional weights/C_compl=0.3"],
                "square_refused")
check_refused(refused, "C_compl = 0.3", "C_compl")
value = accepted_value(refused)
print("C_compl = 0.3: largest accepted value named: %s" % rounded(value, 4))
check(value is not None and 0.2974 <= value <= 0.2986,
      "the message names the largest accepted value, in the bracket")

print("=== the user's punch, 3 levels (checked on level 2)")
punch = R.run("prm/punch.prm", [], "punch_auto")
w = weights(punch)
print("auto: C_compl = %s, limit = %s, iterations %s, force %s N/mm"
      % (rounded(w.get("C_compl"), 4), rounded(w.get("C_compl_limit"), 4),
         punch["iterations"], rounded(punch.force, 5)))
check(punch.ok() and punch["converged"] is True, "the punch runs with the defaults")
limit = w.get("C_compl_limit") or 0
check(0.0618 <= limit <= 0.0638, "the computed limit lies in the bisected bracket "
      "[0.0618, 0.0638]")
check(w.get("C_compl") is not None and w["C_compl"] < 0.1
      and abs(w["C_compl"] - 0.5 * limit) <= 1e-12 * limit,
      "auto takes half the limit, below the cap")
user = R.run("prm/punch.prm", ["Functional weights/C_compl=0.03"], "punch_user")
check(user.ok() and relative_difference(punch.force, user.force) < 1e-3,
      "the force of the user's C_compl = 0.03 to 1e-3")
refused = R.run("prm/punch.prm", ["Functional weights/C_compl=0.1"], "punch_refused")
check_refused(refused, "C_compl = 0.1", "C_compl")
value = accepted_value(refused)
print("C_compl = 0.1: largest accepted value named: %s" % rounded(value, 4))
if check(value is not None and abs(value - limit / 1.5) <= 2e-3 * value,
         "the value named is the limit less the 50% margin"):
    below = R.run("prm/punch.prm", ["Functional weights/C_compl=%r" % (0.99 * value)],
                  "punch_below")
    check(below.ok(), "0.99 times the value named is accepted")
    above = R.run("prm/punch.prm", ["Functional weights/C_compl=%r" % (1.01 * value)],
                  "punch_above")
    check_refused(above, "1.01 times the value named", "C_compl")

print("=== used_parameters.prm of the auto run")
used = os.path.join(punch.directory, "used_parameters.prm")
with open(used) as f:
    lines = [l for l in f if re.match(r"\s*set C_compl\s*=", l)]
check(len(lines) == 1 and "# auto" in lines[0]
      and relative_difference(float(lines[0].split("=")[1].split("#")[0]),
                              w.get("C_compl")) < 1e-11,
      "it holds the weight taken")
again = R.run(os.path.abspath(used), [], "punch_again")
check(again.ok() and weights(again).get("C_compl_auto") is False
      and relative_difference(again["functional"], punch["functional"]) < 1e-12,
      "it runs the same functional again")

print("=== data checked where used (cube, 2 levels)")
# (the sides' Dirichlet values vanish at the contact face z = 0)
cube = ["Geometry/Levels=2", "Data/Traction=0; 0", "Data/Dirichlet values=0; 0; -0.01 * z"]
clamped = R.run("prm/cube3d.prm", cube + ["Boundary conditions/Dirichlet boundary ids=0, 1, 2, 3, 5",
                                          "Boundary conditions/Neumann boundary ids="],
                "cube_no_neumann")
check(clamped.ok(), "no Neumann boundary: a 2-component traction is not used, the run goes on")
neumann = R.run("prm/cube3d.prm", cube, "cube_neumann")
check_refused(neumann, "with a Neumann boundary", "Data/Traction")
roller = R.run("prm/cube3d.prm", cube + ["Boundary conditions/Dirichlet boundary ids=0, 1, 2, 3, 5",
                                         "Boundary conditions/Neumann boundary ids=",
                                         "Boundary conditions/Dirichlet components=0: 0; 1: 0; "
                                         "2: 1; 3: 1; 5: all"],
               "cube_roller")
check_refused(roller, "with a roller boundary", "Data/Traction")
finish()
