#!/usr/bin/env python3
# A deep hierarchy in 2D: the square (prm/square.prm, default solver) on
# 6, 7, 8 and 9 levels (6402 to 395266 DoFs, a hierarchy of 9 levels).
# Measured on 2 cores with another job sharing the machine: the whole test
# 26 s, the 9-level run about 15 s (solve 8 s, peak memory 1.5 GB).
# Checks per level: converged within 10 iterations (measured 3, 4, 4, 3;
# levels 8 and 9 end at the round-off floor), no NaN/Inf, energy_increases
# == 0, every iterate feasible, KKT residual < 1e-10, all 2^(J-1) + 1
# bottom vertices in contact. The force of 9 levels is checked against
# the extrapolation of levels 6, 7, 8: F_9 ~ F_8 + q (F_8 - F_7) with
# q = (F_8 - F_7) / (F_7 - F_6) (measured q = 0.36, F_9 within 6e-7 of
# the prediction; asserted 1e-5), and the level differences must shrink.
# ctest: timeout=900 cost=15
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_flat_contact_run, finish, \
    rounded

R = Runner(sys.argv)
forces = {}
for levels in [6, 7, 8, 9]:
    print("=== %d levels" % levels)
    run = R.run("prm/square.prm", ["Geometry/Levels=%d" % levels],
                "level_%d" % levels)
    check_flat_contact_run(run, 10, 2 ** (levels - 1) + 1)
    print("contact force |F| = %s" % rounded(run.force, 7))
    forces[levels] = run.force or 0.
d = [forces[l + 1] - forces[l] for l in [6, 7, 8]]
q = d[1] / d[0]
prediction = forces[8] + q * d[1]
print("level differences of F: %s" % " ".join(rounded(x, 2) for x in d))
print("q = %s, extrapolated F_9 = %s" % (rounded(q, 2), rounded(prediction, 7)))
check(0 < d[2] < d[1] < d[0], "the level differences of F shrink")
check(abs(forces[9] - prediction) <= 1e-5 * prediction,
      "F_9 within 1e-5 of the extrapolation of levels 6-8")
finish()
