#!/usr/bin/env python3
# Known problem (DISABLED in tests/CMakeLists.txt until the library is
# fixed; the .output is what a fixed library must print): with a contact
# zone that ends inside the contact boundary (curved obstacle, Hertz) the
# default solver stagnates from some level on.
#  - The half disc (prm/hertz.prm): 3 iterations on 2 levels, 6 on 3
#    levels (rate 0.69 per cycle), but on 4 levels (24962 DoFs) not
#    converged after 30 iterations (rate 0.98 per cycle, 67 s), J = 1.94e-6
#    vs the active set solver's 6.41e-7, force 0.01137 vs 0.01453, 97
#    active constraints vs 95: at the two contact vertices x = +-0.0734
#    (gap open) the iterate keeps the normal stress of the adjacent faces
#    at its bound 0 where the KKT point has sigma_nn = -0.0157. DoFs at
#    their bound are truncated from the coarse/Newton corrections, and the
#    projected vertex-patch smoother does not release them. The linear
#    problem on the same meshes (no contact, curved side traction-loaded)
#    converges in 4-5 iterations on levels 2-5, so the untruncated
#    hierarchy is fine.
#  - The square (prm/square.prm) on a cylinder of radius 1 below it,
#    Data/Gap = 1 - sqrt(1 - (x - 0.5)^2): 3 iterations on 3 and 4
#    levels, but on 5 levels "NOT converged after 200 iterations" (2198
#    cycles, rate 0.994 per cycle), force 1.3e-4 off. Here the active set
#    is right; the vertex x = 0.4375 is 5.2e-6 from its bound at the KKT
#    point and the iterates approach it from the bound side (1.6e-6 away
#    after 30 iterations), so the projected steps stay tiny. Radius 2: the
#    same (rate 0.97); radius 0.5 converges in 7 iterations.
# Reproduction: fosls-contact prm/square.prm --set Geometry/Levels=5
#   --set "Data/Gap=1 - sqrt(1 - (x-0.5)^2)"
#               fosls-contact prm/hertz.prm --set Geometry/Levels=4
# Checks: both converge within 30 iterations to the active set solver's
# force (1e-8 relative). Labelled "long": when the problem is present the
# half disc alone takes about 4 minutes.
import sys
import os
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, relative_difference

R = Runner(sys.argv)
for label, prm, scene in [
        ("cylinder R = 1, 5 levels", "prm/square.prm",
         ["Geometry/Levels=5", "Data/Gap=1 - sqrt(1 - (x-0.5)^2)"]),
        ("half disc, 4 levels", "prm/hertz.prm", ["Geometry/Levels=4"])]:
    reference = R.run(prm, scene + ["Solver/Type=active set"], "reference")
    run = R.run(prm, scene + ["Solver/Max iterations=30"], "multigrid")
    check(run.ok() and run["converged"] is True and run["iterations"] <= 30,
          label + ": converged within 30 iterations")
    check(relative_difference(run["contact_force"],
                              reference["contact_force"]) <= 1e-8,
          label + ": |F - F_ref| / |F_ref| <= 1e-8")
finish()
