#!/usr/bin/env python3
# The paper's plain monotone cycle (Solver/Krylov steps = 0) converges on
# problems where it stalls without the rerouting of the flux of partly
# truncated coarse contact faces (FluxRerouting) or with Galerkin operators
# that add up over truncation changes (deal.II's SparseMatrix::mmult/Tmmult
# add to their result, tests/unit/galerkin_product):
#  - the half disc (prm/hertz.prm, 2 levels, Grading = 1, the paper's
#    two-level experiment): without the rerouting rate 0.9999 per cycle,
#    J 19% above the active set solver's after 300 cycles; measured 13
#    cycles;
#  - the square (4 levels) from a zero start: without the rerouting
#    J = 7.9e-5 vs 2.5e-7 after 300 cycles;
#  - the square (5 levels) with C_compl = 0, a near-degenerate contact
#    (corner multipliers 100x smaller than in the middle): with summed
#    Galerkin operators rate 0.995, not converged after 100 iterations,
#    J 0.1% above the optimum.
# Checks: converged within 100 cycles, force equal to the active set
# solver's to 1e-6, J never increased.
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_plain_cycle, finish

R = Runner(sys.argv)
for label, prm, scene in [
        ("half disc, 2 levels", "prm/hertz.prm", ["Geometry/Grading=1", "Geometry/Levels=2"]),
        ("square, zero start", "prm/square.prm",
         ["Geometry/Levels=4", "Solver/Initial guess=zero"]),
        ("square, C_compl = 0", "prm/square.prm",
         ["Geometry/Levels=5", "Functional weights/C_compl=0"])]:
    run = check_plain_cycle(R, label, prm, scene)
    check(run.ok() and run["energy_increases"] == 0,
          label + ": J never increased")
finish()
