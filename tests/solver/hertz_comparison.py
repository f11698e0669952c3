# The Hertz comparison and the plot script.
# prm/steel_cylinder.prm (a steel roller, R = 50 mm, in mm/N/MPa; 3 levels
# here) declares a Hertz comparison: summary.json's "hertz" must hold
# Hertz's half-width a = sqrt(4 F R / (pi E*)) and peak p0 = 2 F / (pi a)
# for the computed force, with E* = E / (1 - nu^2), and the computed
# contact edge, peak and relative l2 pressure error, all recomputed here
# from contact.csv to 1e-8; Hertz's a must lie between the last vertex in
# contact and the next one, the peak within 5% of p0 (measured: 4.5% on 3
# levels, 0.4% on the shipped 4). The same for prm/ball3d.prm (a sphere, 3
# levels) with a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2).
# scripts/plot.py draws both runs: two PNG files each, exit code 0; on a
# missing run directory one line on stderr and exit code 1.
import csv
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, relative_difference, rounded

R = Runner(sys.argv)
plot = os.path.join(R.source, "scripts", "plot.py")


def recompute(run, shape, E, nu, radius, centre, normal):
    h = run["hertz"]
    dim = len(centre)
    E_star = E / (1. - nu * nu)
    F = abs(sum(f * n for f, n in zip(run["contact_force"], normal)))
    if shape == "cylinder":
        a = math.sqrt(4. * F * radius / (math.pi * E_star))
        p0 = 2. * F / (math.pi * a)
    else:
        a = (3. * F * radius / (4. * E_star)) ** (1. / 3.)
        p0 = 3. * F / (2. * math.pi * a * a)
    with open(os.path.join(run.directory, "contact.csv")) as f:
        rows = list(csv.DictReader(f))

    def r_of(row):
        p = [float(row["xyz"[d]]) - centre[d] for d in range(dim)]
        pn = sum(p[d] * normal[d] for d in range(dim))
        return math.sqrt(sum((p[d] - pn * normal[d]) ** 2 for d in range(dim)))

    def hertz(r):
        return p0 * math.sqrt(1. - r * r / (a * a)) if r < a else 0.

    inside = max(r_of(x) for x in rows if x["active"] == "1")
    outside = min(r_of(x) for x in rows if x["active"] == "0" and r_of(x) > inside)
    peak = max(-float(x["sigma_nn"]) for x in rows)
    error = math.sqrt(sum((-float(x["sigma_nn"]) - hertz(r_of(x))) ** 2 for x in rows) /
                      sum(hertz(r_of(x)) ** 2 for x in rows))
    expected = {"force": F, "contact_modulus": E_star, "a": a, "p0": p0,
                "edge_inside": inside, "edge_outside": outside, "peak": peak,
                "pressure_error": error}
    wrong = [k for k, v in expected.items() if not relative_difference(h[k], v) <= 1e-8]
    check(not wrong, shape + ": summary.json's hertz entries as recomputed from "
          "contact.csv to 1e-8" + (" (not: %s)" % ", ".join(wrong) if wrong else ""))
    print("%s: F %s, a %s between %s and %s, p0 %s, peak %s, pressure error %s"
          % (shape, rounded(F, 5), rounded(a, 4), rounded(inside, 4), rounded(outside, 4),
             rounded(p0, 4), rounded(peak, 4), rounded(error, 3)))
    check(inside < a < outside, shape + ": Hertz's a between the last vertex in contact "
          "and the next")
    return peak, p0


cylinder = R.run("prm/steel_cylinder.prm", ["Geometry/Levels=3"], name="steel_cylinder")
check(cylinder.ok() and "hertz" in cylinder.summary, "steel cylinder: runs, summary has hertz")
peak, p0 = recompute(cylinder, "cylinder", 210000., 0.3, 50., [0., 0.], [0., -1.])
check(abs(peak - p0) <= 0.05 * p0, "cylinder: peak pressure within 5% of p0")

sphere = R.run("prm/ball3d.prm", ["Geometry/Levels=3"], name="ball3d")
check(sphere.ok() and "hertz" in sphere.summary, "ball3d: runs, summary has hertz")
recompute(sphere, "sphere", 2.5, 0.25, 2., [0., 0., 0.], [0., 0., -1.])

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
