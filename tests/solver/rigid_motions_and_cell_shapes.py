# The checks of a scene before the solve:
#  - rigid motions (FoslsProblem::check_rigid_motions): refused where the
#    boundary conditions leave one free, accepted where the fixed DoFs hold
#    every one, also when they hold every DoF of a mode (a one-cell square
#    with Dirichlet sides: the least-energy problem's mass matrix is then
#    singular, which LAPACK's generalized solver refused);
#  - cell shapes on every level (CellShapeCheck): the half disc
#    with Grading 3.7 had positive coarse cell areas but an inverted
#    corner, and the run ended with J = -3.7e-5 (a sum of squares) without
#    a word.
# ctest: timeout=120
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_refused, finish

R = Runner(sys.argv)


run = R.run("prm/square.prm", ["Geometry/Levels=1",
                               "Boundary conditions/Dirichlet boundary ids=0, 1, 2, 3",
                               "Boundary conditions/Neumann boundary ids=",
                               "Boundary conditions/Contact boundary ids="], name="one_cell")
check(run.ok() and run["converged"], "one cell, Dirichlet on every side: runs and converges")
run = R.run("prm/square.prm", ["Geometry/Levels=3"], name="square")
check(run.ok() and run["converged"], "square as given: runs and converges")
check_refused(R.run("prm/square.prm", ["Geometry/Levels=3", "Boundary conditions/Dirichlet components=1"],
              name="roller"),
        "square with a roller on top", "rigid motion free (translation in x,")
check_refused(R.run("prm/cube3d.prm", ["Geometry/Levels=2", "Boundary conditions/Dirichlet components=2"],
              name="cube_z"),
        "cube held in z only", "translation in x + translation in y + rotation about z")
for grading, levels in [("3.7", "1"), ("4", "3")]:
    check_refused(R.run("prm/hertz.prm", ["Geometry/Grading=" + grading, "Geometry/Levels=" + levels],
                  name="grading_" + grading),
            "half disc, Grading %s, %s levels" % (grading, levels),
            "'Geometry/Grading' = %s" % grading)
run = R.run("prm/hertz.prm", ["Geometry/Grading=3.5", "Geometry/Levels=3"], name="grading_3.5")
check(run.ok() and run["functional"] > 0, "half disc, Grading 3.5, 3 levels: runs, J > 0")
finish()
