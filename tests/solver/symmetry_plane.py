# Symmetry planes: per-id Dirichlet components ("0: 0; 3: all") make a
# roller on a symmetry plane beside a clamped side. The half (2D) and
# quarter (3D) models must give the full model's solution: J and the
# contact force are exactly half (a quarter) of the full model's, and the
# contact vertices on the plane, where the roller meets the contact
# boundary, are contact vertices (u.n <= g with the roller's u_x = 0).
# (One component list for all Dirichlet ids would make a roller leave a
# translation free; taken as a Dirichlet vertex, the corner would be
# unconstrained in u.n.)
# A part and the full model have the same functional only with the same
# reference length (Scaling): the parts are given the full model's 2.
# Also refused, one line each: a roller meeting the contact boundary where
# the obstacle normal is not a free axis, and malformed per-id lists.
# ctest: mpirun cost=9
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_refused, finish, relative_difference

R = Runner(sys.argv)


def plane_rows(run, axis):
    """contact.csv rows on the plane coordinate[axis] = 0."""
    with open(os.path.join(run.directory, "contact.csv")) as f:
        return [r for r in csv.DictReader(f) if float(r["xyz"[axis]]) == 0.]


def compare(part, full, parts, label):
    check(part.ok() and full.ok() and part["converged"] and full["converged"],
          label + ": both run and converge")
    print("%s: active %d (part) %d (full), energy increases %d %d"
          % (label, part["active"], full["active"], part["energy_increases"],
             full["energy_increases"]))
    d_J = relative_difference(parts * part["functional"], full["functional"])
    # the resultant's component normal to the planes (the last): the part's
    # other components need not vanish (with a curved obstacle normal)
    d_F = relative_difference(parts * part["contact_force"][-1], full["contact_force"][-1])
    check(d_J < 1e-8, label + ": %d J(part) = J(full) to 1e-8" % parts)
    check(d_F < 1e-8, label + ": %d F_last(part) = F_last(full) to 1e-8" % parts)


# 2D: the square [-1, 1] x [0, 1] and its half [0, 1]^2 with a roller
# (u_x = 0) on x = 0; gap even in x, so contact is partial
gap2 = ["Data/Gap=0.008*x*x", "Geometry/Levels=5"]
half = ["Scaling/Reference length=2",
        "Boundary conditions/Dirichlet boundary ids=0, 3",
        "Boundary conditions/Dirichlet components=0: 0",
        "Boundary conditions/Neumann boundary ids=1"]
full = ["Geometry/Box lower corner=-1, 0", "Geometry/Box subdivisions=2, 1"]
halves = {}
for solver in ["monotone multigrid", "active set"]:
    tag = solver.split()[0]
    p = R.run("prm/square.prm", gap2 + half + ["Solver/Type=" + solver], name="half_" + tag)
    f = R.run("prm/square.prm", gap2 + full + ["Solver/Type=" + solver], name="full_" + tag)
    compare(p, f, 2, "2D half square, " + solver)
    halves[solver] = p
    rows = plane_rows(p, 0)
    check(len(rows) == 1 and rows[0]["in_contact"] == "1",
          "2D, " + solver + ": the corner on the plane is an active contact vertex")
    check(f["active"] == 2 * p["active"] - 1,
          "2D, " + solver + ": active(full) = 2 active(half) - 1 (the plane's vertex once)")

# the half on 2 processes: the roller contact vertex may be a ghost (the
# half square with its own reference length, 1)
p2 = R.run("prm/square.prm", gap2 + half[1:], name="half_np2", processes=2)
p1 = R.run("prm/square.prm", gap2 + half[1:], name="half_np1")
check(p2.ok() and relative_difference(p2["functional"], p1["functional"]) < 1e-10,
      "2D half square on 2 processes: J as on 1 to 1e-10")

# 3D: the cube [-1, 1]^2 x [0, 1] and its quarter [0, 1]^3 with rollers
# u_x = 0 on x = 0 (id 0) and u_y = 0 on y = 0 (id 2)
gap3 = ["Data/Gap=0.008*(x*x+y*y)", "Geometry/Levels=3"]
quarter = ["Scaling/Reference length=2",
           "Boundary conditions/Dirichlet boundary ids=0, 2, 5",
           "Boundary conditions/Dirichlet components=0: 0; 2: 1",
           "Boundary conditions/Neumann boundary ids=1, 3"]
full3 = ["Geometry/Box lower corner=-1, -1, 0", "Geometry/Box subdivisions=2, 2, 1"]
q = R.run("prm/cube3d.prm", gap3 + quarter, name="quarter_cube")
f = R.run("prm/cube3d.prm", gap3 + full3, name="full_cube")
compare(q, f, 4, "3D quarter cube")
p_x, p_y = ([r for r in plane_rows(q, a) if r["in_contact"] == "1"] for a in (0, 1))
print("3D quarter cube: active contact vertices on x = 0: %d, on y = 0: %d" % (len(p_x), len(p_y)))
check(any(float(r["y"]) == 0. for r in p_x), "3D quarter cube: the corner on both planes is active")
# a vertex off the planes has 4 mirror images, one on a single plane 2,
# the corner on both 1
check(f["active"] == 4 * q["active"] - 2 * len(p_x) - 2 * len(p_y) + 1,
      "3D: active(full) = 4 active(quarter) - 2 (active on the planes) + 1")

# the shipped quarter model of the 3D Hertz scene
q = R.run("prm/ball3d_quarter.prm", ["Geometry/Levels=3"], name="ball3d_quarter")
f = R.run("prm/ball3d.prm", ["Geometry/Levels=3"], name="ball3d")
compare(q, f, 4, "prm/ball3d_quarter.prm against prm/ball3d.prm, 3 levels")

# the quarter model with the ball's own normal (x, y, -sqrt(R^2 - r^2)):
# on x = 0 it is orthogonal to e_x but not an axis (vertex_rotation keeps
# e_x a column), on y = 0 orthogonal to e_y (H(n) keeps e_y)
sphere = ["Geometry/Levels=3", "Data/Obstacle normal=x; y; -sqrt(R^2 - x^2 - y^2)"]
q = R.run("prm/ball3d_quarter.prm", sphere, name="ball3d_quarter_sphere_normal")
f = R.run("prm/ball3d.prm", sphere, name="ball3d_sphere_normal")
compare(q, f, 4, "ball3d quarter against full, the sphere's normal, 3 levels")

# refused
check_refused(R.run("prm/square.prm", half + ["Data/Obstacle normal=0.3; -1"], name="tilted"),
        "roller meeting contact with a normal along its prescribed u_x",
              "has an obstacle normal with a part along a prescribed component")
for value, pattern in [("5: 0", "names boundary id 5, which is not in"),
                       ("0: 0; 0: all", "names boundary id 0 twice"),
                       ("0: 2", "has entry '2'; valid"),
                       ("0 0", "has entry '0 0'; valid"),
                       ("0:", "has entry '0:'; expected 'id: components'")]:
    check_refused(R.run("prm/square.prm", half[:2] + half[3:] +
                  ["Boundary conditions/Dirichlet components=" + value], name="bad"),
            "Dirichlet components = '%s'" % value, pattern)
finish()
