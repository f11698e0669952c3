#!/usr/bin/env python3
# 3D Hertz contact with a contact zone that ends inside the
# contact boundary. prm/ball3d.prm: the elastic block [-1,1]^2 x [0,1]
# (mu = lambda = 1) pushed down by 0.05 onto a rigid ball of radius R = 2,
# 4 levels (27771 DoFs), default solver. Hertz (rigid sphere on an elastic
# half-space): E* = E/(1 - nu^2), a = (3 F R / (4 E*))^(1/3),
# p0 = 3 F / (2 pi a^2), with F the computed total force. Measured:
# 4 iterations, F = 0.0773, Hertz a = 0.352 between the largest
# active contact vertex radius 0.280 and the smallest inactive one 0.354,
# computed peak pressure 0.287 vs p0 = 0.2985 (3.8% low; the block is
# only 3 contact radii thick, and the pressure is a vertex value of a
# h = 0.125 mesh).
# Checks: converged within 10 iterations, monotone and feasible, KKT
# residual < 1e-10, the contact force vertical, Hertz's a between the
# largest active and the smallest inactive vertex radius, peak pressure
# within 10% of p0.
# ctest: sanitize
import csv
import math
import os
import sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, describe, \
    finish, rounded

R = Runner(sys.argv)
run = R.run("prm/ball3d.prm", ["Geometry/Levels=4"], "ball3d_level_4")
describe(run, "multigrid", ("dofs", "iterations", "converged", "active"))
check(run["converged"] is True and run["iterations"] <= 10,
      "converged within 10 iterations")
check(run["kkt_residual"] is not None and run["kkt_residual"] < 1e-10,
      "KKT residual < 1e-10")
check_monotone_feasible(run, "multigrid", scale=0.05)
f = run["contact_force"] or [0, 0, 0]
check(f[2] > 0 and abs(f[0]) < 1e-12 * f[2] and abs(f[1]) < 1e-12 * f[2],
      "the contact force is vertical")

radius, mu, lam = 2.0, 1.0, 1.0
E = mu * (3 * lam + 2 * mu) / (lam + mu)
nu = lam / (2 * (lam + mu))
E_star = E / (1 - nu * nu)
a = (3 * f[2] * radius / (4 * E_star)) ** (1. / 3)
p0 = 3 * f[2] / (2 * math.pi * a * a)
with open(os.path.join(run.directory, "contact.csv")) as table:
    rows = list(csv.DictReader(table))
r_of = [(math.hypot(float(z["x"]), float(z["y"])), z) for z in rows]
r_active = max(r for r, z in r_of if z["in_contact"].strip() == "1")
r_inactive = min(r for r, z in r_of if z["in_contact"].strip() != "1")
peak = max(-float(z["sigma_nn"]) for z in rows)
print("F = %s, Hertz a = %s, active vertices up to r = %s, inactive from "
      "r = %s" % (rounded(f[2], 4), rounded(a, 3), rounded(r_active, 3),
                  rounded(r_inactive, 3)))
print("Hertz p0 = %s, computed peak pressure = %s"
      % (rounded(p0, 4), rounded(peak, 4)))
check(r_active <= a <= r_inactive,
      "Hertz's a between the last active and the first inactive vertex")
check(abs(peak - p0) <= 0.1 * p0, "peak pressure within 10% of p0")
finish()
