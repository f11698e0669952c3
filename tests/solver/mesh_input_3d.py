# Meshes from files (Geometry/Shape = file) in 3D, and their paths:
#  - the quarter ball of prm/quarter_ball_file.prm (2 levels) as Gmsh
#    format 2.2 (prm/meshes/quarter_ball.msh), 4.1 and .inp
#    (tests/meshes/convert_msh.py): the same force and J, to 1e-10 and 1e-6;
#  - paths: a mesh file named in a scene file is relative to that file
#    (also when the scene file is included from another directory), one
#    given with --set relative to the current directory; used_parameters.prm
#    names it absolutely and runs again from anywhere to the same force;
#  - on 2 MPI processes the quarter ball's force and J are those of 1
#    process to 1e-8.
# ctest: mpirun sanitize
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_same, describe, finish

R = Runner(sys.argv)
meshes = os.path.join(R.source, "tests", "meshes")
quarter = "prm/quarter_ball_file.prm"
two = ["Geometry/Levels=2"]
runs = [R.run(quarter, two, name="quarter_v2")]
for f in ["quarter_ball_v41.msh", "quarter_ball.inp"]:
    runs.append(R.run(quarter, two + ["Geometry/Mesh file=" + os.path.join(meshes, f)],
                      name="quarter_" + f[-3:]))
describe(runs[0], "3D quarter ball", ("dofs", "converged", "active"))
check_same(runs, "3D quarter ball: Gmsh 2.2, 4.1 and Abaqus", 1e-10, 1e-6)

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
check_same(paths, "3D quarter ball: --set relative to the current directory, in an included "
           "scene, from used_parameters.prm", 1e-10)

parallel = R.run(quarter, two, name="quarter_2_processes", processes=2)
check_same([runs[0], parallel], "3D quarter ball on 2 processes", 1e-8)
finish()
