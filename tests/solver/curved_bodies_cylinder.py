# The built-in half cylinder (Geometry/Shape = half cylinder), as shipped
# in prm/half_cylinder.prm (a cylinder on a plane with roller end faces,
# plane strain, 3 levels): converges, monotone, feasible, at least 8
# vertices in contact (measured 45), the Hertz comparison of a cylinder in
# 3D (per unit length, distances from the contact line), and its force per
# unit length is that of the 2D half disc of prm/hertz.prm with the same
# cross-section mesh to 0.5% (measured 0.10%: in 3D the third stress row,
# RT0, is constant in x and y in a cell, where sigma_zz = lambda tr eps
# varies; the 2D discretization needs no such row); scripts/plot.py draws
# its contact pressure against the distance from the contact line.
# ctest: cost=17
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_hertz, check_shipped, finish, relative_difference, rounded

R = Runner(sys.argv)

cylinder = R.run("prm/half_cylinder.prm", name="half_cylinder")
check_shipped(cylinder, "half cylinder")
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
