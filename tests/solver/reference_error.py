#!/usr/bin/env python3
# Adaptivity/Reference refinements: after the adaptive loop the last mesh
# is refined everywhere and solved again (the reference, the last row of
# the step table), and every step's error is measured against it in
# H1 x H(div), with the efficiency index sqrt(J) / error. Checked:
# - the step table: the steps, then one reference row with more DoFs;
#   every step before it has its errors and index, the reference none;
# - on the manufactured solution, where the exact error is known, each
#   step's error against the reference differs from its exact error by at
#   most the reference's own exact error (the triangle inequality, for the
#   H1 and the H(div) part each): the step solutions carried over to the
#   reference mesh are the same functions, and the norms are right (a
#   wrong carry-over or a missing divergence breaks it);
# - on the Hertz half disc (curved contact boundary, RT faces of both
#   orientations, the monotone multigrid on the adaptive levels) the
#   errors against the reference fall from step to step and the carried
#   start of the reference keeps the last step's J within 10%;
# - the parameter without an adaptive loop is refused in one line.
import math
import os
import sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_refused, finish, rounded

R = Runner(sys.argv)


def step_rows(run, label, n_meshes):
    steps = run["adaptive_steps"] or []
    check(run.ok() and run["converged"] is True and len(steps) == n_meshes + 1,
          label + ": exit code 0, %d meshes and the reference" % n_meshes)
    check(len(steps) == n_meshes + 1 and steps[-1]["reference"] and
          not any(s["reference"] for s in steps[:-1]),
          label + ": the last row is the reference, no other")
    check(len(steps) >= 2 and steps[-1]["dofs"] > 3 * steps[-2]["dofs"],
          label + ": the reference has more than 3 times the last step's DoFs")
    check(all(s["efficiency_index"] is not None and s["efficiency_index"] > 0
              for s in steps[:-1]) and steps[-1]["efficiency_index"] is None,
          label + ": every step has its efficiency index, the reference none")
    for s in steps:
        print("%s, step %d%s: %d DoFs, sqrt(J) %s, against the reference: H1 %s, Hdiv %s, "
              "index %s" % (label, s["step"], " (reference)" if s["reference"] else "",
                            s["dofs"], rounded(math.sqrt(s["functional"]), 4),
                            rounded(s["reference_error_u_h1"], 4),
                            rounded(s["reference_error_sigma_hdiv"], 4),
                            rounded(s["efficiency_index"], 3)))
    return steps


# the manufactured solution: the exact errors are known
label = "manufactured solution, 3 levels, 2 steps, reference refined twice"
run = R.run("prm/elasticity_mms.prm",
            ["Solver/Type=active set", "Geometry/Levels=3", "Adaptivity/Steps=2",
             "Adaptivity/Reference refinements=2"], "mms")
steps = step_rows(run, label, 3)
if len(steps) == 4:
    reference = steps[-1]
    for part, exact, against in [("H1", "error_u_h1", "reference_error_u_h1"),
                                 ("Hdiv", "error_sigma_hdiv", "reference_error_sigma_hdiv")]:
        bound = reference[exact]
        worst = max(abs(s[against] - s[exact]) for s in steps[:-1])
        print("%s, %s: reference's exact error %s, largest |against reference - exact| %s" % (
            label, part, rounded(bound, 4), rounded(worst, 4)))
        check(worst <= bound * (1 + 1e-6),
              label + ", " + part + ": each step's error against the reference is its exact "
              "error to within the reference's exact error")
        check(steps[0][exact] >= 3 * bound,
              label + ", " + part + ": the reference is at least 3 times more accurate "
              "than the first mesh")

# the Hertz half disc with the monotone multigrid
label = "hertz_adaptive, 2 steps, reference refined once"
run = R.run("prm/hertz_adaptive.prm",
            ["Adaptivity/Steps=2", "Adaptivity/Max DoFs=0",
             "Adaptivity/Reference refinements=1"], "hertz")
steps = step_rows(run, label, 3)
if len(steps) == 4:
    errors = [math.hypot(s["reference_error_u_h1"], s["reference_error_sigma_hdiv"])
              for s in steps[:-1]]
    check(all(b < a for a, b in zip(errors, errors[1:])),
          label + ": the error against the reference falls from step to step")
    check(abs(steps[-1]["functional_start"] - steps[-2]["functional"]) <=
          0.1 * steps[-2]["functional"],
          label + ": the reference's carried start has the last step's J to within 10%")

# no adaptive loop, no reference
run = R.run("prm/square.prm", ["Geometry/Levels=3", "Adaptivity/Reference refinements=1"],
            "refused")
check_refused(run, "Reference refinements without Adaptivity/Steps",
              "'Adaptivity/Reference refinements' > 0 needs 'Adaptivity/Steps' > 0")

finish()
