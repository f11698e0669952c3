# The built-in 3D curved bodies (Geometry/Shape = half ball, half cylinder)
# and the mesh-file quarter ball, as shipped in prm/:
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
#    measured 4e-10 for the force and 1.3e-9 for J);
#  - prm/half_cylinder.prm (a cylinder on a plane with roller end faces,
#    plane strain, 3 levels): converges, monotone, feasible, at least 8
#    vertices in contact (measured 45), the Hertz comparison of a cylinder in
#    3D (per unit length, distances from the contact line), and its force
#    per unit length is that of the 2D half disc of prm/hertz.prm with the
#    same cross-section mesh to 0.5% (measured 0.10%: in 3D the third stress
#    row, RT0, is constant in x and y in a cell, where sigma_zz = lambda tr
#    eps varies; the 2D discretization needs no such row); scripts/plot.py
#    draws its contact pressure against the distance from the contact line.
import csv
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import (Runner, check, check_hertz, check_monotone_feasible, describe, finish,
                        relative_difference, rounded)

R = Runner(sys.argv)


def in_contact(run):
    with open(os.path.join(run.directory, "contact.csv")) as f:
        return sum(1 for row in csv.DictReader(f) if row["active"] == "1")


def shipped(run, label):
    describe(run, label, ("dofs", "converged", "active"))
    check(run["converged"] is True, label + ": converged")
    check_monotone_feasible(run, label)
    n = in_contact(run)
    print("%s: %d contact vertices in contact" % (label, n))
    check(n >= 8, label + ": at least 8 contact vertices in contact")


half = R.run("prm/half_ball.prm", name="half_ball")
shipped(half, "half ball")
check_hertz(half, "half ball", "sphere", 2.5, 0.25, 0.5, [0., 0., 0.5], [0., 0., -1.])

quarter = R.run("prm/quarter_ball_file.prm", name="quarter_ball_file")
shipped(quarter, "quarter ball from a file")
check_hertz(quarter, "quarter ball from a file", "sphere", 2.5, 0.25, 0.5, [0., 0., 0.5],
            [0., 0., -1.], factor=4.)
dF = relative_difference(4. * quarter["contact_force"][2], half["contact_force"][2])
dJ = relative_difference(4. * quarter["functional"], half["functional"])
check(dF <= 1e-6 and dJ <= 1e-6,
      "4 times the quarter's force and J are the half ball's to 1e-6")

cylinder = R.run("prm/half_cylinder.prm", name="half_cylinder")
shipped(cylinder, "half cylinder")
check_hertz(cylinder, "half cylinder", "cylinder", 2.5, 0.25, 0.5, [0., 0.5, 0.], [0., -1., 0.],
            axis=[0., 0., 1.], length=1.)
disc = R.run("prm/hertz.prm", name="half_disc")
check(disc.ok() and disc["converged"] is True, "half disc (2D): converged")
dF = relative_difference(cylinder["contact_force"][1], disc["contact_force"][1])
print("half cylinder: force per unit length %s, half disc %s"
      % (rounded(cylinder["contact_force"][1], 5), rounded(disc["contact_force"][1], 5)))
check(dF <= 5e-3, "half cylinder: the force per unit length of the 2D half disc to 0.5%")
out = cylinder.directory + "_plots"
p = subprocess.run([sys.executable, os.path.join(R.source, "scripts", "plot.py"),
                    cylinder.directory, "-o", out], capture_output=True, text=True)
check(p.returncode == 0 and os.path.getsize(os.path.join(out, "contact_pressure.png")) > 1000,
      "half cylinder: plot.py draws the contact pressure")
finish()
