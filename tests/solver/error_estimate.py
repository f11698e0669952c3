#!/usr/bin/env python3
# The error in the user's terms (RunSummary::add_error_estimate,
# AdaptiveSteps::efficiency_index, AdaptiveSteps::singular_stress).
# 1. The relative error estimate sqrt(J^) / |x^_h| and, with Adaptivity/
#    Reference refinements, the efficiency indices are computed in the norm
#    of the dimensionless problem: the steel half disc (prm/hertz.prm, E =
#    210 GPa, nu = 0.3, the body 0.1 m, pushed 1e-3 m) in SI and in
#    mm/N/MPa, two adaptive steps and a reference one refinement finer, give
#    the same figures to 1e-7, every step. The efficiency index (sqrt(J)
#    over the error against the reference) is of order 1, the constants of
#    the functional's norm equivalence (measured 0.381, 0.416, 0.475;
#    computed in the scene's units it would add an H1 norm in mm to an
#    H(div) norm in MPa mm): checked within [0.25, 4]; the relative estimate falls from
#    step to step.
# 2. A singular stress is said once: the punch of prm/punch.prm, whose
#    bonded edge at (5, 20) is singular, warns in adaptive step 3 (the peak
#    von Mises stress 836 -> 1208 -> 1823 MPa at the edge), on the screen
#    once and in summary.json; the half disc, whose stress is smooth, does
#    not warn in 5 steps.
# ctest: cost=27
import os
import sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, relative_difference

R = Runner(sys.argv)


def half_disc(s, E):
    return ["Geometry/Radius=%r" % (0.5 * s), "Geometry/Center=0, %r" % s,
            "Data/Constants=push=%r, R=%r, c=%r" % (0.01 * s, 0.5 * s, s),
            "Data/Gap=y - (c - R)", "Geometry/Levels=3",
            "Material/mu=", "Material/lambda=", "Material/E=%r" % E, "Material/nu=0.3",
            "Adaptivity/Steps=2", "Adaptivity/Reference refinements=1"]


print("--- 1. the same figures in SI and in mm/N/MPa")
si = R.run("prm/hertz.prm", half_disc(0.1, 210e9), "si")
mm = R.run("prm/hertz.prm", half_disc(100., 210000.), "mm")
check(si.ok() and mm.ok(), "both runs exit 0, nothing on stderr")
steps_si, steps_mm = si["adaptive_steps"] or [], mm["adaptive_steps"] or []
check(len(steps_si) == 4 and len(steps_mm) == 4, "3 steps and the reference each")
for k in range(min(len(steps_si), len(steps_mm)) - 1):
    a, b = steps_si[k], steps_mm[k]
    check(relative_difference(a["relative_error_estimate"], b["relative_error_estimate"])
          <= 1e-7, "step %d: the relative error estimate, SI = mm" % k)
    check(relative_difference(a["efficiency_index"], b["efficiency_index"]) <= 1e-7,
          "step %d: the efficiency index, SI = mm" % k)
    check(0.25 <= a["efficiency_index"] <= 4., "step %d: efficiency index in [0.25, 4]" % k)
    if k > 0:
        check(a["relative_error_estimate"] < steps_si[k - 1]["relative_error_estimate"],
              "step %d: the relative error estimate fell" % k)
check(si["relative_error_estimate"] == si["relative_error_estimate"]
      and si["relative_error_estimate"] > 0, "summary.json: relative_error_estimate")

print("--- 2. a singular stress, said once")
punch = R.run("prm/punch.prm", ["Adaptivity/Steps=4"], "punch")
check(punch.ok(), "punch: exit 0, nothing on stderr")
warnings = [l for l in punch.screen.splitlines() if l.startswith("Warning: the largest von Mises")]
check(len(warnings) == 1 and "(5, 20)" in warnings[0],
      "punch: one warning on the screen, at the punch's edge (5, 20)")
check("(5, 20)" in (punch["singular_stress"] or ""), "punch: summary.json singular_stress")
smooth = R.run("prm/hertz.prm", ["Adaptivity/Steps=5"], "half_disc")
check(smooth.ok() and "Warning" not in smooth.screen and smooth["singular_stress"] is None,
      "half disc (a smooth stress): no warning in 5 adaptive steps")
finish()
