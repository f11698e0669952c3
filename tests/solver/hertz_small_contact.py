#!/usr/bin/env python3
# prm/hertz_small_contact.prm: the adaptive Hertz half disc with a contact
# zone two cells wide on the starting mesh (push 0.0025, a/R = 0.05, where
# Hertz's formula holds to within 0.4%, so that the pressure error measures
# the mesh). Checked:
# - every step converges, the DoFs grow and stay within Adaptivity/Max
#   DoFs, and sqrt(J) falls from step to step;
# - the relative L2 error of the pressure against Hertz's formula, above
#   5% on the starting mesh (measured 0.063), is at most 1% on the last
#   mesh (measured 0.0038 at 114,482 DoFs): the indicators refine toward
#   the edge of the contact zone, where the pressure has its square-root
#   edge (uniform refinement is at 1.5% with 1.6 million DoFs);
# - on the last mesh the last contact vertex in contact and the next one
#   are closer than a/50 (measured a/136; 0.012 = a/2 on the starting
#   mesh), and Hertz's half-width a is within a/50 of the point halfway
#   between them (measured a/157, the half disc's contact zone 0.6%
#   narrower than the half-space's; a/5.5 on the starting mesh).
# ctest: cost=47
import os
import sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, rounded

R = Runner(sys.argv)
run = R.run("prm/hertz_small_contact.prm", [], "small_contact")
steps = (run["adaptive_steps"] or []) if run.ok() else []
check(run.ok() and run["converged"] is True and len(steps) >= 2,
      "exit code 0, converged, more than one mesh")
for s in steps:
    print("step %d: %d DoFs, sqrt(J) %s, pressure L2 error %s, %d iterations, %d cycles"
          % (s["step"], s["dofs"], rounded(s["functional"] ** 0.5, 4),
             rounded(s["hertz_pressure_error_boundary"], 3), s["iterations"], s["cycles"]))
if steps:
    check(all(s["converged"] for s in steps), "every step converges")
    check(all(b["dofs"] > a["dofs"] for a, b in zip(steps, steps[1:])) and
          steps[-1]["dofs"] <= 150000, "the DoFs grow and stay within Max DoFs = 150000")
    check(all(b["functional"] < a["functional"] for a, b in zip(steps, steps[1:])),
          "sqrt(J) falls from step to step")
    first, last = steps[0]["hertz_pressure_error_boundary"], \
        steps[-1]["hertz_pressure_error_boundary"]
    check(first > 0.05, "the starting mesh's pressure error is above 5%")
    check(last <= 0.01, "the last mesh's pressure error is at most 1%")
    hertz = run["hertz"]
    inside, outside, a = hertz["edge_inside"], hertz["edge_outside"], hertz["a"]
    print("last mesh: Hertz's a = %s, contact edge between %s and %s"
          % (rounded(a, 4), rounded(inside, 4), rounded(outside, 4)))
    check(outside - inside < a / 50,
          "the last vertex in contact and the next one closer than a/50")
    check(abs((inside + outside) / 2 - a) < a / 50, "Hertz's a within a/50 of halfway between")
finish()
