# The built-in half ball (Geometry/Shape = half ball) and its quarter from a
# mesh file, as shipped in prm/:
#  - prm/half_ball.prm (a sphere on a plane, 3 levels): converges, every
#    iterate monotone and feasible, at least 8 contact vertices in contact
#    (measured 101), and summary.json's Hertz comparison as recomputed from
#    contact.csv, Hertz's a between the last vertex in contact and the next;
#  - prm/quarter_ball_file.prm (its quarter from prm/meshes/quarter_ball.msh
#    with the sphere as manifold, Force factor 4): the same Hertz checks
#    with the factor, and four times its force and functional are the half
#    ball's to 1e-6: the finest meshes are the same (tests/unit/mesh_input),
#    so the two discrete problems are one up to the symmetry, and the runs
#    differ by their stopping points (tolerance 1e-8 on the error reduction;
#    measured 4e-10 for the force and 1.3e-9 for J).
# ctest: cost=14
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_hertz, check_shipped, finish, relative_difference

R = Runner(sys.argv)

half = R.run("prm/half_ball.prm", name="half_ball")
check_shipped(half, "half ball")
check_hertz(half, "half ball", "sphere", 2.5, 0.25, 0.5, [0., 0., 0.5], [0., 0., -1.])

quarter = R.run("prm/quarter_ball_file.prm", name="quarter_ball_file")
check_shipped(quarter, "quarter ball from a file")
check_hertz(quarter, "quarter ball from a file", "sphere", 2.5, 0.25, 0.5, [0., 0., 0.5],
            [0., 0., -1.], factor=4.)
dF = relative_difference(4. * quarter["contact_force"][2], half["contact_force"][2])
dJ = relative_difference(4. * quarter["functional"], half["functional"])
check(dF <= 1e-6 and dJ <= 1e-6,
      "4 times the quarter's force and J are the half ball's to 1e-6")

finish()
