#!/usr/bin/env python3
# prm/cattaneo_mindlin.prm on 8 levels: a rigid cylinder pressed into an
# incompressible half-plane (its far field on the box's outer boundary)
# with P = 0.01, then pulled sideways with Q = 0.5 f P and 0.8 f P under
# Coulomb friction (f = 0.3), against Cattaneo and Mindlin's solution
# (Johnson, Contact Mechanics, section 7.1), computed here from each
# step's contact_000N.csv:
#  - the contact force is P and Q to 1% (the far field's data carry them);
#  - the pressure is within 2% of Hertz's for the computed force
#    (relative L2 on the contact boundary);
#  - pressed, the tangential traction is within 3% of f p (relative L2):
#    an incompressible body on a rigid obstacle (Dundurs' beta = 0) gets
#    no tangential traction from the pressure;
#  - pulled: each end of the stick zone, midway between its outermost
#    stick vertex and the next vertex, is within one vertex spacing of
#    +-c = +-a sqrt(1 - Q/(f P)), and the tangential traction is within 5%
#    of q (relative L2);
#  - the program's own comparison (summary.json "hertz" and
#    "cattaneo_mindlin", the last step) gives the figures computed here
#    (to 1e-6);
#  - J never increases, every iterate feasible (the last solve);
#  - on 6 levels, 2 MPI processes give the comparison of 1 (summary.json
#    "cattaneo_mindlin" and "hertz", to 1e-8: the force, c and the stick
#    zone's ends relative to themselves, the relative errors of the
#    pressure and the traction as they are, that is relative to the norms
#    of p and q as the forces are. The two runs take the same Tresca
#    problems and Newton steps; their relative errors differ by 5e-10
#    (pressure) and 4e-9 (traction), 1e-8 to 2e-8 of the errors
#    themselves, and tighter tolerances of the solver and the fixed point
#    (1e-10 and 1e-9) move these between 2e-10 and 1e-8 in no order: the
#    round-off floor of the comparison, not a dependence on the processes).
# ctest: mpirun timeout=400 cost=190
import csv
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import (CATTANEO_MINDLIN_LOADS as LOADS, CATTANEO_MINDLIN_P as P, Runner,
                        cattaneo_mindlin_2d, check, check_monotone_feasible, finish, rounded)

R = Runner(sys.argv)


run = R.run("prm/cattaneo_mindlin.prm", ["Geometry/Levels=8"], "cattaneo_mindlin")
check_monotone_feasible(run, "8 levels")
with open(os.path.join(run.directory, "load_steps.csv")) as f:
    steps = list(csv.DictReader(f))
check(len(steps) == len(LOADS), "every step written")
figures = []
for k, (Q, step) in enumerate(zip(LOADS, steps)):
    with open(os.path.join(run.directory, "contact_%04d.csv" % k)) as f:
        rows = sorted(csv.DictReader(f), key=lambda r: float(r["x"]))
    normal, tangential = float(step["normal_force"]), float(step["tangential_force"])
    r = cattaneo_mindlin_2d(rows, normal, tangential)
    figures.append(r)
    print("Q = %g: P = %s, Q = %s, Q/(f P) = %s; Hertz a = %s, pressure error %s%%" % (
        Q, rounded(normal, 4), rounded(tangential if Q else 0, 4),
        rounded(r["ratio"] if Q else 0, 3), rounded(r["a"], 4),
        rounded(100 * r["pressure_error"], 2)))
    print("  c = %s, stick zone from %s to %s (%s and %s vertex spacings from -c and c), "
          "traction error %s of |f p|%s" % (
              rounded(r["c"], 4), rounded(r["from"], 4), rounded(r["to"], 4),
              rounded(r["from_error"], 2), rounded(r["to_error"], 2), rounded(r["of_fp"], 2),
              ", %s of |q|" % rounded(r["of_q"], 2) if "of_q" in r else ""))
    # (pressed, Q is 0 up to round-off, which the screen does not show)
    check(abs(normal - P) <= 0.01 * P and abs(tangential - Q) <= 0.01 * max(Q, 1e-6 * P),
          "Q = %g: the contact force is P and Q to 1%%" % Q)
    check(r["pressure_error"] <= 0.02, "Q = %g: the pressure within 2%% of Hertz's" % Q)
    if Q == 0:
        check(r["of_fp"] <= 0.03, "pressed: the tangential traction within 3% of f p")
    else:
        check(r["from_error"] <= 1 and r["to_error"] <= 1,
              "Q = %g: both ends of the stick zone within one vertex spacing of +-c" % Q)
        check(r["of_q"] <= 0.05, "Q = %g: the tangential traction within 5%% of q" % Q)

last, hertz, cm = figures[-1], run["hertz"], run["cattaneo_mindlin"]
check(hertz is not None and cm is not None
      and abs(hertz["pressure_error_boundary"] - last["pressure_error"]) <= 1e-6 * last["pressure_error"]
      and all(abs(cm[k] - last[v]) <= 1e-6 * abs(last[v])
              for k, v in (("c", "c"), ("ratio", "ratio"), ("stick_from", "from"), ("stick_to", "to"),
                           ("stick_from_error", "from_error"), ("stick_to_error", "to_error"),
                           ("traction_error", "of_q"), ("traction_error_of_slip_limit", "of_fp"))),
      "summary.json's Hertz and Cattaneo-Mindlin comparison gives the figures computed here")
runs = [R.run("prm/cattaneo_mindlin.prm", ["Geometry/Levels=6"], "cattaneo_mindlin_%d" % n,
              processes=n) for n in (1, 2)]
check(all(r.ok() for r in runs) and all(
    abs(runs[0][key][k] - runs[1][key][k]) <= 1e-8 * abs(runs[0][key][k])
    for key, keys in (("cattaneo_mindlin", ("c", "stick_from", "stick_to")), ("hertz", ("force",)))
    for k in keys) and all(
    abs(runs[0][key][k] - runs[1][key][k]) <= 1e-8
    for key, keys in (("cattaneo_mindlin", ("traction_error", "traction_error_of_slip_limit")),
                      ("hertz", ("pressure_error_boundary",)))
    for k in keys), "6 levels: 2 processes give the comparison of 1 (to 1e-8)")
finish()
