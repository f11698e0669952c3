# Meshes from files (Geometry/Shape = file):
#  - 2D: Gmsh's unstructured quadrilaterals of the half disc of
#    prm/hertz.prm (tests/meshes/half_disc_unstructured.geo; 3 levels) as
#    Gmsh format 2.2, 4.1 and Abaqus .inp: the three runs converge to the
#    same contact force and functional, to 1e-10 for the two Gmsh files
#    (one mesh read two ways; measured: equal), to 1e-6 for the Abaqus file
#    (deal.II's Abaqus reader passes the coordinates through a text of 8
#    significant digits; measured 2e-9 for the force and 8e-8 for J);
#    with the circle as manifold every contact vertex of the finest level
#    lies on it (contact.csv, 10 digits), without it the curved side stays
#    a polygon of the coarse mesh's chords (a vertex 3.0e-3 inside the
#    circle measured) and the force changes (by 2.4% measured);
#  - 3D: the quarter ball of prm/quarter_ball_file.prm (2 levels) as Gmsh
#    format 2.2 (prm/meshes/quarter_ball.msh), 4.1 and .inp
#    (tests/meshes/convert_msh.py): the same force and J, to 1e-10 and 1e-6;
#  - paths: a mesh file named in a scene file is relative to that file
#    (also when the scene file is included from another directory), one
#    given with --set relative to the current directory; used_parameters.prm
#    names it absolutely and runs again from anywhere to the same force;
#  - on 2 MPI processes the quarter ball's force and J are those of 1
#    process to 1e-8;
#  - far from the origin: the quarter ball moved by (1000, 1000, 1000)
#    (mesh, manifold, gap and contact point) gives the same force and J to
#    1e-6 (measured 1.3e-10); moved by 3e4 (1.5e6 of its smallest cells) it
#    is refused in one line: deal.II's reader computes cell volumes from the
#    absolute coordinates and turns a cell inside out, which the cell check
#    finds and names; moved by 1e7 (its size 0.5 cannot be resolved there
#    in double precision) deal.II's reader finds cells of no volume, named
#    in one line;
#  - Gmsh's unstructured hexahedra of the quarter ball
#    (tests/meshes/quarter_ball_unstructured.geo; faces meeting in all
#    orientations): converges, monotone and feasible.
import csv
import math
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import (Runner, check, check_monotone_feasible, check_refused, describe, finish,
                        relative_difference, rounded)

R = Runner(sys.argv)
meshes = os.path.join(R.source, "tests", "meshes")


def same(runs, label, tolerance, last_tolerance=None):
    """All @p runs converged to the first one's force and J, to @p tolerance
    (the last one to @p last_tolerance if given)."""
    check(all(r.ok() and r["converged"] is True for r in runs), label + ": all converged")
    tolerances = [tolerance] * (len(runs) - 2) + [last_tolerance or tolerance]
    check(all(relative_difference(r["contact_force"], runs[0]["contact_force"]) <= t and
              relative_difference(r["functional"], runs[0]["functional"]) <= t
              for r, t in zip(runs[1:], tolerances)),
          label + ": the same contact force and J to %g" % tolerance +
          (" (the last one to %g)" % last_tolerance if last_tolerance else ""))


def radii(run, centre):
    with open(os.path.join(run.directory, "contact.csv")) as f:
        return [math.hypot(float(r["x"]) - centre[0], float(r["y"]) - centre[1])
                for r in csv.DictReader(f)]


# 2D: one unstructured mesh in three formats
disc = ["Geometry/Shape=file", "Boundary conditions/Dirichlet boundary ids=2",
        "Boundary conditions/Contact boundary ids=1"]
circle = "Geometry/Manifolds=1: sphere 0, 1 radius 0.5"
runs = [R.run("prm/hertz.prm", disc + [circle, "Geometry/Mesh file=" +
                                       os.path.join(meshes, "half_disc_unstructured" + f)],
              name="half_disc_" + f[-3:])
        for f in ["_v2.msh", "_v4.msh", ".inp"]]
describe(runs[0], "2D half disc", ("dofs", "converged", "active"))
same(runs, "2D half disc: Gmsh 2.2, 4.1 and Abaqus", 1e-10, 1e-6)
check(max(abs(r - 0.5) for r in radii(runs[0], (0., 1.))) < 1e-9,
      "2D half disc with the circle: the contact vertices lie on it")
flat = R.run("prm/hertz.prm", disc + ["Geometry/Mesh file=" + os.path.join(
    meshes, "half_disc_unstructured_v2.msh")], name="half_disc_flat")
inside = 0.5 - min(radii(flat, (0., 1.)))
df = relative_difference(flat["contact_force"], runs[0]["contact_force"])
print("2D half disc without the circle: a contact vertex %s inside it, force %s%% off"
      % (rounded(inside, 2), rounded(100 * df, 2)))
check(flat.ok() and inside > 1e-4 and df > 0.01,
      "2D half disc without the circle: the vertices stay on the chords, the force changes")

# 3D: one mesh in three formats; paths
quarter = "prm/quarter_ball_file.prm"
two = ["Geometry/Levels=2"]
runs = [R.run(quarter, two, name="quarter_v2")]
for f in ["quarter_ball_v41.msh", "quarter_ball.inp"]:
    runs.append(R.run(quarter, two + ["Geometry/Mesh file=" + os.path.join(meshes, f)],
                      name="quarter_" + f[-3:]))
describe(runs[0], "3D quarter ball", ("dofs", "converged", "active"))
same(runs, "3D quarter ball: Gmsh 2.2, 4.1 and Abaqus", 1e-10, 1e-6)

shutil.copy(os.path.join(R.source, "prm", "meshes", "quarter_ball.msh"), "copy.msh")
os.makedirs("elsewhere", exist_ok=True)
with open(os.path.join("elsewhere", "scene.prm"), "w") as f:
    f.write("include %s\n" % os.path.join(R.source, quarter))
used = os.path.join(runs[0].directory, "used_parameters.prm")
with open(used) as f:
    named = [l.split("=", 1)[1].split("#")[0].strip() for l in f
             if l.strip().startswith("set Mesh file")]
check(named == [os.path.join(R.source, "prm", "meshes", "quarter_ball.msh")],
      "used_parameters.prm names the mesh file by its absolute path")
paths = [runs[0],
         R.run(quarter, two + ["Geometry/Mesh file=copy.msh"], name="set_relative"),
         R.run(os.path.abspath(os.path.join("elsewhere", "scene.prm")), two, name="included"),
         R.run(os.path.abspath(used), [], name="used_parameters")]
same(paths, "3D quarter ball: --set relative to the current directory, in an included "
     "scene, from used_parameters.prm", 1e-10)

parallel = R.run(quarter, two, name="quarter_2_processes", processes=2)
same([runs[0], parallel], "3D quarter ball on 2 processes", 1e-8)

# far from the origin


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


far = R.run(quarter, moved(1000.), name="moved_1000")
same([runs[0], far], "3D quarter ball moved by 1000", 1e-6)
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
