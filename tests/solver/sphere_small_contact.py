#!/usr/bin/env python3
# The 3D sphere with a small contact zone, as shipped
# (prm/ball3d_small_contact.prm: the quarter model of the ball, pushed
# 0.0012, refined adaptively), with a DoF budget of 30,000 instead of
# 2,500,000 (bench/sphere_small_contact.py runs it in full). Checks:
# - every adaptive step converged without an energy increase, the last
#   step's iterates monotone and feasible;
# - the Hertz comparison of the quarter: Hertz's force is 4 times the
#   computed one (Force factor), the contact zone small against the radius
#   (a/R <= 0.05);
# - the pressure error against Hertz's formula (relative L2 on the contact
#   boundary) falls at every step from step 2 on, to at most 0.06 on the
#   last mesh; on the first mesh, which does not touch the sphere (no
#   force, so no Hertz pressure), it is null, not 0 (the previous binary
#   wrote 0, a perfect match).
# Measured: 7 refinements to 20,661 DoFs; a = 0.0496 (a/R = 0.025); the
# error from 0.77 (step 2) to 0.057.
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, finish, \
    relative_difference, rounded

R = Runner(sys.argv)
run = R.run("prm/ball3d_small_contact.prm", ["Adaptivity/Max DoFs=30000"], "budget_30000",
            stop=None)
label = "sphere, small contact zone"
check(run.ok(), label + ": the run ends normally")
steps = run["adaptive_steps"] or []
print("%s: %d steps, %s DoFs on the last mesh" % (label, len(steps), steps[-1]["dofs"]))
check(all(s["converged"] and s["energy_increases"] == 0 for s in steps),
      label + ": every step converged, no energy increase")
check_monotone_feasible(run, label)
hertz = run["hertz"]
print("%s: Hertz a = %s (a/R = %s), force factor %s" % (
    label, rounded(hertz["a"], 3), rounded(hertz["a"] / hertz["radius"], 3),
    hertz["force_factor"]))
# (both read from summary.json, each to 12 significant digits)
check(relative_difference(hertz["force"], 4 * run["contact_force"][2]) <= 1e-11,
      label + ": Hertz's force is 4 times the quarter's")
check(hertz["a"] / hertz["radius"] <= 0.05, label + ": a/R <= 0.05")
# (the 3 levels' mesh does not reach the sphere: no force, no Hertz pressure)
check(steps[0]["contact_force"][2] == 0 and steps[0]["hertz_pressure_error"] is None and
      steps[0]["hertz_pressure_error_boundary"] is None,
      label + ": step 0 has no contact force and no pressure error (null, not 0)")
errors = [s["hertz_pressure_error_boundary"] for s in steps[2:]]
print("%s: pressure error (relative L2 on the contact boundary) from step 2: %s"
      % (label, ", ".join(str(rounded(e, 3)) for e in errors)))
check(all(b < a for a, b in zip(errors, errors[1:])),
      label + ": the pressure error falls at every step from step 2 on")
check(errors[-1] <= 0.06, label + ": the pressure error on the last mesh is at most 0.06")
finish()
