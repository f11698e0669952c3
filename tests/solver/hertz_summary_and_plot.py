# The Hertz comparison and the plot script.
# prm/steel_cylinder.prm (a steel roller, R = 50 mm, in mm/N/MPa; 3 levels
# here) declares a Hertz comparison: summary.json's "hertz" must hold
# Hertz's half-width a = sqrt(4 F R / (pi E*)) and peak p0 = 2 F / (pi a)
# for the computed force, with E* = E / (1 - nu^2), and the computed
# contact edge, peak, relative l2 pressure error at the contact vertices
# and relative L2 error on the contact boundary, all recomputed here from
# contact.csv to 1e-8 (and the vertices' shares of the boundary sum to its
# area on the ball's flat bottom); Hertz's a must lie between the last vertex in
# contact and the next one, the peak within 5% of p0 (measured: 4.5% on 3
# levels, 0.4% on the shipped 4). The same for prm/ball3d.prm (a sphere, 3
# levels) with a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2).
# scripts/plot.py draws both runs: two PNG files each, exit code 0; on a
# missing run directory one line on stderr and exit code 1.
import csv
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_hertz, finish

R = Runner(sys.argv)
plot = os.path.join(R.source, "scripts", "plot.py")

cylinder = R.run("prm/steel_cylinder.prm", ["Geometry/Levels=3"], name="steel_cylinder")
check(cylinder.ok() and "hertz" in cylinder.summary, "steel cylinder: runs, summary has hertz")
peak, p0 = check_hertz(cylinder, "cylinder", "cylinder", 210000., 0.3, 50., [0., 0.], [0., -1.])[:2]
check(abs(peak - p0) <= 0.05 * p0, "cylinder: peak pressure within 5% of p0")

sphere = R.run("prm/ball3d.prm", ["Geometry/Levels=3"], name="ball3d")
check(sphere.ok() and "hertz" in sphere.summary, "ball3d: runs, summary has hertz")
check_hertz(sphere, "sphere", "sphere", 2.5, 0.25, 2., [0., 0., 0.], [0., 0., -1.])
# the vertices' shares of the contact boundary, the block's flat bottom
# [-1, 1]^2, sum to its area
with open(os.path.join(sphere.directory, "contact.csv")) as f:
    shares = [float(row["boundary_share"]) for row in csv.DictReader(f)]
check(abs(sum(shares) - 4.) <= 1e-12, "ball3d: the boundary shares sum to the area 4 (1e-12)")

for run in (cylinder, sphere):
    out = run.directory + "_plots"
    p = subprocess.run([sys.executable, plot, run.directory, "-o", out],
                       capture_output=True, text=True)
    files = [os.path.join(out, n) for n in ("contact_pressure.png", "convergence.png")]
    pngs = all(os.path.isfile(f) and os.path.getsize(f) > 1000 and
               open(f, "rb").read(8) == b"\x89PNG\r\n\x1a\n" for f in files)
    check(p.returncode == 0 and pngs, run.name + ": plot.py writes two PNG files")
p = subprocess.run([sys.executable, plot, "no_such_run"], capture_output=True, text=True)
check(p.returncode == 1 and len(p.stderr.strip().splitlines()) == 1 and
      "no_such_run" in p.stderr, "plot.py on a missing directory: one line, exit code 1")
finish()
