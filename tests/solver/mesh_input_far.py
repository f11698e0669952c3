# Meshes from files far from the origin, and unstructured hexahedra:
#  - the quarter ball of prm/quarter_ball_file.prm (2 levels) moved by
#    (1000, 1000, 1000) (mesh, manifold, gap and contact point) gives the
#    same force and J to 1e-6 (measured 1.3e-10); moved by 3e4 (1.5e6 of its
#    smallest cells) it is refused in one line: deal.II's reader computes
#    cell volumes from the absolute coordinates and turns a cell inside out,
#    which the cell check finds and names; moved by 1e7 (its size 0.5
#    cannot be resolved there in double precision) deal.II's reader finds
#    cells without volume, named in one line;
#  - Gmsh's unstructured hexahedra of the quarter ball
#    (tests/meshes/quarter_ball_unstructured.geo; faces meeting in all
#    orientations): converges, monotone and feasible.
# ctest: cost=9
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check_monotone_feasible, check_refused, check_same, describe, finish

R = Runner(sys.argv)
meshes = os.path.join(R.source, "tests", "meshes")
quarter = "prm/quarter_ball_file.prm"
two = ["Geometry/Levels=2"]


def moved(shift):
    name = "moved_%g.msh" % shift
    with open(os.path.join(R.source, "prm", "meshes", "quarter_ball.msh")) as f:
        lines = f.read().split("\n")
    start, end = lines.index("$Nodes") + 2, lines.index("$EndNodes")
    for i in range(start, end):
        words = lines[i].split()
        lines[i] = " ".join([words[0]] + [repr(float(w) + shift) for w in words[1:]])
    with open(name, "w") as f:
        f.write("\n".join(lines))
    s = repr(shift)
    return two + ["Geometry/Mesh file=" + name,
                  "Geometry/Manifolds=1: sphere %s, %s, %s radius 0.5" % (s, s, repr(shift + 1)),
                  "Data/Gap=z - (%s + 1 - R)" % s,
                  "Hertz comparison/Contact point=%s, %s, %s" % (s, s, repr(shift + 0.5))]


at_origin = R.run(quarter, two, name="quarter")
far = R.run(quarter, moved(1000.), name="moved_1000")
check_same([at_origin, far], "3D quarter ball moved by 1000", 1e-6)
inside_out = R.run(quarter, moved(3e4), name="moved_3e4")
check_refused(inside_out, "3D quarter ball moved by 3e4",
              "far from the origin against the size of its cells")
too_far = R.run(quarter, moved(1e7), name="moved_1e7")
check_refused(too_far, "3D quarter ball moved by 1e7", "double precision cannot resolve")

unstructured = R.run(quarter, two + ["Geometry/Mesh file=" + os.path.join(
    meshes, "quarter_ball_unstructured.msh")], name="quarter_unstructured")
describe(unstructured, "3D unstructured quarter ball", ("dofs", "converged", "active"))
check_monotone_feasible(unstructured, "3D unstructured quarter ball")
finish()
