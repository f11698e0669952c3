#!/usr/bin/env python3
# prm/shrink_fit.prm: a steel ring fitted with interference onto a rigid
# shaft, with Coulomb friction, then turned at its outer surface until it
# slips; solved by the monotone multigrid, against the closed forms of the
# thick cylinder (plane strain):
#  - the fit's contact pressure is uniform (to 1e-3 of its mean) and tends
#    to Lame's p = 175 MPa: within 2% on 5 levels, its error falling by at
#    least 3 from 4 to 5 levels (the mesh size squared: 4);
#  - while every contact vertex sticks, the torque is the ring's torsional
#    stiffness 4 pi mu a^2 b^2 / (b^2 - a^2) times theta (to 0.2%);
#  - past the torque capacity every vertex slips and the torque is
#    f a times the integral of the pressure (Coulomb's law), to 1e-3: the
#    columns of contact.csv are means of the two faces at a vertex, whose
#    tangents differ by 2 pi / N on N faces, so the mean of two tractions
#    of size f p is shorter by 1 - cos(pi / N) (3e-4 on 4 levels); the
#    change from stick to slip between the steps theta = 1.5e-4 and 2e-4
#    around Lame's slip angle 1.625e-4;
#  - J never increases, every iterate feasible (the last solve);
#  - prm/meshes/make_ring.py writes prm/meshes/ring.msh.
# ctest: timeout=300 cost=43
import csv
import filecmp
import math
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, finish, rounded

R = Runner(sys.argv)
A, B, DELTA, E, NU, F = 20., 40., 0.01, 210000., 0.3, 0.2
MU = E / (2 * (1 + NU))
LAMBDA = E * NU / ((1 + NU) * (1 - 2 * NU))
# u_r = c1 r + c2 / r with u_r(a) = delta, u_r(b) = 0; p = -sigma_rr(a)
C1 = DELTA * A / (A * A - B * B)
C2 = -DELTA * A * B * B / (A * A - B * B)
LAME = -(2 * (LAMBDA + MU) * C1 - 2 * MU * C2 / (A * A))
STIFFNESS = 4 * math.pi * MU * A * A * B * B / (B * B - A * A)
SLIP_ANGLE = F * LAME * 2 * math.pi * A * A / STIFFNESS
print("Lame: p = %s MPa, torsional stiffness %s N mm/rad, slip angle %s" % (
    rounded(LAME, 5), rounded(STIFFNESS, 5), rounded(SLIP_ANGLE, 4)))

generated = os.path.join(os.getcwd(), "ring.msh")
subprocess.run([sys.executable, os.path.join(R.source, "prm", "meshes", "make_ring.py"),
                generated], check=True)
check(filecmp.cmp(generated, os.path.join(R.source, "prm", "meshes", "ring.msh"), shallow=False),
      "prm/meshes/make_ring.py writes prm/meshes/ring.msh")


def steps_of(run, thetas):
    """Per step: theta, the mean pressure (weighted by the vertices'
    boundary shares), its spread, the torque on the ring, the integral of
    the pressure, and the numbers of stick and slip vertices."""
    result = []
    for k, theta in enumerate(thetas):
        with open(os.path.join(run.directory, "contact_%04d.csv" % k)) as f:
            rows = list(csv.DictReader(f))
        share = [float(r["boundary_share"]) for r in rows]
        p = [-float(r["sigma_nn"]) for r in rows]
        torque = sum(s * (float(r["x"]) * float(r["traction_t_y"])
                          - float(r["y"]) * float(r["traction_t_x"])) for s, r in zip(share, rows))
        force = sum(s * q for s, q in zip(share, p))
        result.append({"theta": theta, "p": force / sum(share), "spread": max(p) - min(p),
                       "torque": abs(torque), "force": force,
                       "stick": sum(r["status"] == "1" for r in rows),
                       "slip": sum(r["status"] == "2" for r in rows), "vertices": len(rows)})
    return result


ALL = [0, 5e-5, 1e-4, 1.5e-4, 2e-4, 3e-4]
FEW = [0, 1e-4, 3e-4]
errors = {}
for levels, thetas in ((4, ALL), (5, FEW)):
    settings = ["Geometry/Levels=%d" % levels,
                "Data/Load steps=" + "; ".join("theta=%g" % t for t in thetas)]
    run = R.run("prm/shrink_fit.prm", settings, "shrink_fit_%d" % levels)
    steps = steps_of(run, thetas) if run.ok() else []
    check(run.ok() and len(steps) == len(thetas), "%d levels: the run ends, every step written"
          % levels)
    check_monotone_feasible(run, "%d levels" % levels)
    if not steps:
        continue
    errors[levels] = abs(steps[0]["p"] - LAME) / LAME
    print("%d levels: %d contact vertices, pressure %s MPa (%s%% from Lame's)" % (
        levels, steps[0]["vertices"], rounded(steps[0]["p"], 5), rounded(100 * errors[levels], 2)))
    for s in steps:
        # (unturned, the torque is round-off: its digits are not printed)
        torque = "%s N mm/mm" % rounded(s["torque"], 5) if s["theta"] > 0 else \
            "below 1e-9 of the capacity" if abs(s["torque"]) <= 1e-9 * F * A * s["force"] \
            else "%g N mm/mm, above 1e-9 of the capacity" % s["torque"]
        print("  theta = %g: torque %s, %d stick and %d slip vertices" % (
            s["theta"], torque, s["stick"], s["slip"]))
    check(all(s["spread"] <= 1e-3 * s["p"] for s in steps),
          "%d levels: the pressure is uniform (to 1e-3)" % levels)
    sticking = [s for s in steps if s["theta"] < SLIP_ANGLE]
    slipping = [s for s in steps if s["theta"] > SLIP_ANGLE]
    check(all(s["stick"] == s["vertices"] for s in sticking)
          and all(abs(s["torque"] - STIFFNESS * s["theta"]) <= 2e-3 * STIFFNESS * s["theta"]
                  for s in sticking if s["theta"] > 0),
          "%d levels: below the slip angle every vertex sticks and the torque is the "
          "stiffness times theta (to 0.2%%)" % levels)
    check(slipping and all(s["slip"] == s["vertices"] for s in slipping)
          and all(abs(s["torque"] - F * A * s["force"]) <= 1e-3 * F * A * s["force"]
                  for s in slipping),
          "%d levels: above it every vertex slips and the torque is f a times the integral "
          "of the pressure (to 1e-3)" % levels)
check(errors.get(5, 1) <= 0.02 and errors.get(4, 0) >= 3 * errors.get(5, 1),
      "the pressure: within 2% of Lame's on 5 levels, the error falling by 3 or more from 4 levels")
finish()
