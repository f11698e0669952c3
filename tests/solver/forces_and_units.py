#!/usr/bin/env python3
# The answers in an engineer's terms: the force on every boundary id, the
# contact zone, and the names of the units.
#  - Boundary forces (summary.json boundary_forces, boundary_force_sum): the
#    integral of sigma n over each id, n the body's outward normal, the force
#    exerted on the body there, in the contact force's convention (the
#    contact id's entry is contact_force). Their sum is the integral of
#    div sigma over the body (divergence theorem, exact for the RT0 stress),
#    so without body force Cauchy-Schwarz bounds it by
#    |body|^(1/2) |div sigma|_L2 = |body|^(1/2) (S/L) (functional_eq /
#    C_eq)^(1/2): checked on the square (the contact force against the top's
#    reaction), the half disc (curved faces) and the cube, and on the square
#    on 2 processes against 1. Traction-free Neumann ids carry no force.
#  - The contact zone (summary.json contact_zone): recomputed from
#    contact.csv (the boundary shares of the vertices in contact, their
#    pressures -sigma_nn) to 1e-8 (the file's 10 digits); on the square the
#    whole bottom (width 1, mean pressure times width = the contact force),
#    on the cube the whole face (area 1), on the half disc between the Hertz
#    comparison's contact edges, with its peak.
#  - Scaling/Unit names: the steel roller in mm, N, MPa: the screen's force
#    lines in N/mm, the zone in mm and MPa, summary.json "units"; the names
#    change no number; scripts/plot.py draws the run. Bad names are refused
#    in one line.
# ctest: mpirun sanitize
import csv
import json
import math
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_refused, finish, relative_difference, rounded

R = Runner(sys.argv)


def norm(v):
    return math.sqrt(sum(c * c for c in v))


def all_forces(run):
    """{id: force} of every boundary id, and the kind of each."""
    forces, kinds = {}, {}
    for kind, part in (run["boundary_forces"] or {}).items():
        for i, f in part.items():
            forces[int(i)] = f
            kinds[int(i)] = kind
    return forces, kinds


def check_equilibrium(run, label, volume, C_eq=100., length=1., stress=1.):
    """The boundary forces of @p run: the contact ids' add up to
    contact_force, their sum is boundary_force_sum and within the
    Cauchy-Schwarz bound of the equilibrium residual."""
    check(run.ok() and run["converged"] is True, label + ": runs and converges")
    forces, kinds = all_forces(run)
    print("%s: %s" % (label, ", ".join(
        "%s %d: %s" % (kinds[i], i, " ".join(rounded(c, 6) if abs(c) > 1e-9 * run.force
                                             else "0" for c in forces[i]))
        for i in sorted(forces))))
    dim = len(run["contact_force"])
    contact = [sum(forces[i][d] for i in forces if kinds[i] == "contact") for d in range(dim)]
    check(relative_difference(contact, run["contact_force"]) < 1e-12,
          label + ": the contact ids' forces add up to contact_force")
    total = [sum(f[d] for f in forces.values()) for d in range(dim)]
    # (a sum of forces that cancel: its round-off is that of the forces,
    # which summary.json has to 12 digits)
    check(norm([a - b for a, b in zip(total, run["boundary_force_sum"])]) < 1e-10 * run.force,
          label + ": boundary_force_sum is the sum of the boundary forces")
    bound = math.sqrt(volume * run["functional_eq"] / C_eq) * stress / length
    print("%s: |sum| / |contact force| = %s, |sum| / bound = %s"
          % (label, rounded(norm(run["boundary_force_sum"]) / run.force, 2),
             rounded(norm(run["boundary_force_sum"]) / bound, 2)))
    check(norm(run["boundary_force_sum"]) <= bound * (1. + 1e-6) + 1e-12 * run.force,
          label + ": |sum| <= |body|^(1/2) |div sigma|")
    return forces, kinds


def check_zone(run, label):
    """contact_zone against contact.csv."""
    zone = run["contact_zone"] or {}
    with open(os.path.join(run.directory, "contact.csv")) as f:
        rows = list(csv.DictReader(f))
    active = [r for r in rows if r["in_contact"] == "1"]
    measure = sum(float(r["boundary_share"]) for r in active)
    mean = sum(float(r["boundary_share"]) * -float(r["sigma_nn"]) for r in active) / measure
    peak = max(-float(r["sigma_nn"]) for r in rows)
    key = "width" if len(run["contact_force"]) == 2 else "area"
    print("%s: %s %s, mean pressure %s, peak pressure %s, %d of %d vertices in contact"
          % (label, key, rounded(zone.get(key), 6), rounded(zone.get("mean_pressure"), 6),
             rounded(zone.get("peak_pressure"), 6), zone.get("vertices_in_contact", -1),
             zone.get("contact_vertices", -1)))
    # (contact.csv has 10 digits)
    check(relative_difference(zone.get(key), measure) < 1e-8
          and relative_difference(zone.get("mean_pressure"), mean) < 1e-8
          and relative_difference(zone.get("peak_pressure"), peak) < 1e-8
          and zone.get("vertices_in_contact") == len(active)
          and zone.get("contact_vertices") == len(rows),
          label + ": contact_zone as recomputed from contact.csv")
    return zone


# the square pushed onto the plane: the contact force against the reaction
# of the clamped top
square = ["Geometry/Levels=5", "Solver/Type=active set"]
s1 = R.run("prm/square.prm", square, name="square")
forces, kinds = check_equilibrium(s1, "square", 1.)
check(kinds == {0: "neumann", 1: "neumann", 2: "contact", 3: "dirichlet"},
      "square: ids 0, 1 Neumann, 2 contact, 3 Dirichlet")
check(norm(forces[0]) < 1e-10 * s1.force and norm(forces[1]) < 1e-10 * s1.force,
      "square: the traction-free sides carry no force")
check(relative_difference(forces[3], [-c for c in forces[2]]) < 1e-6,
      "square: the top's reaction is minus the contact force (1e-6)")
zone = check_zone(s1, "square")
check(abs(zone.get("width", 0) - 1.) < 1e-12 and
      relative_difference(zone.get("mean_pressure", 0) * zone.get("width", 0),
                          s1["contact_force"][1]) < 1e-10,
      "square: width 1, mean pressure times width = the contact force")
screen = s1.screen.splitlines()
check(any(l.startswith("Contact force =") and "exerted on the body by the obstacle" in l
          for l in screen)
      and any("per unit length out of plane (plane strain), in the scene's units" in l
              for l in screen)
      and any(l.startswith("Contact zone: width 1 (17 of 17 contact vertices in contact)")
              for l in screen),
      "square: the screen states the convention, per unit length, the scene's units")
check(s1["units"] == {"length": "", "force": "", "stress": "", "reported_force": "",
                      "contact_measure": "", "functional": ""},
      "square: summary.json units empty (the scene's units, unnamed)")

s2 = R.run("prm/square.prm", square, name="square_np2", processes=2)
check(s2.ok() and all(relative_difference(all_forces(s2)[0][i], forces[i]) < 1e-10
                      or norm(forces[i]) < 1e-10 * s1.force for i in forces)
      and relative_difference(s2["contact_zone"]["mean_pressure"],
                              zone.get("mean_pressure")) < 1e-10
      and relative_difference(s2["contact_zone"]["width"], zone.get("width")) < 1e-12,
      "square on 2 processes: the forces and the zone as on 1 (1e-10)")

# the half disc (curved faces, partial contact) and its Hertz comparison
h = R.run("prm/hertz.prm", ["Solver/Type=active set"], name="hertz")
# (the polygon of the mesh's boundary within 1% of the half disc's area)
check_equilibrium(h, "half disc", 1.01 * math.pi * 0.25 / 2)
zone = check_zone(h, "half disc")
hertz = h["hertz"] or {}
check(2 * hertz.get("edge_inside", 0) <= zone.get("width", -1) <= 2 * hertz.get("edge_outside", 0)
      and zone.get("peak_pressure") == hertz.get("peak"),
      "half disc: width between the contact edges of the Hertz comparison, its peak")
print("half disc: width %s, Hertz's 2a %s" % (rounded(zone.get("width"), 4),
                                               rounded(2 * hertz.get("a", 0), 4)))

# the cube: the whole bottom face
c = R.run("prm/cube3d.prm", ["Solver/Type=active set"], name="cube")
check_equilibrium(c, "cube", 1.)
zone = check_zone(c, "cube")
check(abs(zone.get("area", 0) - 1.) < 1e-12, "cube: area 1")
check(any("force exerted on the body there, in the scene's units" in l
          for l in c.screen.splitlines()) and "plane strain" not in c.screen,
      "cube: forces in the scene's units, not per unit length")

# the steel roller in mm, N and MPa
steel = ["Geometry/Levels=3", "Solver/Type=active set"]
names = "length=mm, force=N, stress=MPa"
u = R.run("prm/steel_cylinder.prm", steel + ["Scaling/Unit names=" + names], name="steel_mm")
plain = R.run("prm/steel_cylinder.prm", steel, name="steel_unnamed")
check(u.ok() and u["units"] == {"length": "mm", "force": "N", "stress": "MPa",
                                "reported_force": "N/mm", "contact_measure": "mm",
                                "functional": "mm^2"},
      "steel roller: summary.json units, the force per unit length in N/mm")
check(u["contact_force"] == plain["contact_force"] and u["functional"] == plain["functional"]
      and u["contact_zone"] == plain["contact_zone"]
      and u["boundary_forces"] == plain["boundary_forces"],
      "steel roller: the names change no number")
lines = u.screen.splitlines()
force_line = [l for l in lines if l.startswith("Contact force =")]
zone_line = [l for l in lines if l.startswith("Contact zone:")]
check(len(force_line) == 1 and force_line[0].endswith(
          " N/mm (exerted on the body by the obstacle)")
      and any(l.endswith("per unit length out of plane (plane strain), in N/mm") for l in lines)
      and len(zone_line) == 1 and " mm (" in zone_line[0] and " MPa, peak pressure " in zone_line[0]
      and zone_line[0].endswith(" mm"),
      "steel roller: the screen's forces in N/mm, the zone in mm and MPa")
print("steel roller, 3 levels: contact force %s N/mm, width %s mm, mean pressure %s MPa, "
      "peak %s MPa" % (rounded(u["contact_force"][1], 4), rounded(u["contact_zone"]["width"], 3),
                       rounded(u["contact_zone"]["mean_pressure"], 4),
                       rounded(u["contact_zone"]["peak_pressure"], 4)))
p = subprocess.run([sys.executable, os.path.join(R.source, "scripts", "plot.py"), u.directory],
                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
check(p.returncode == 0 and os.path.isfile(os.path.join(u.directory, "contact_pressure.png")),
      "steel roller: plot.py draws the run with its units")

# refused, one line naming the parameter
for value, pattern in [
        ("length=mm, force=N", "does not name 'stress'"),
        ("length=mm, force=N, stress=MPa, time=s",
         "names 'time'; valid names: length, force, stress"),
        ("length=mm, length=m, force=N, stress=MPa", "names 'length' twice"),
        ("length=mm, force=, stress=MPa", "gives 'force' no unit"),
        ("length=mm, force=N m, stress=MPa", "gives 'force' the unit 'N m'"),
        ("mm, N, MPa", "has entry 'mm'; expected 'name=unit'")]:
    check_refused(R.run("prm/square.prm", square + ["Scaling/Unit names=" + value], name="bad"),
                  "Unit names = '%s'" % value, "'Scaling/Unit names' = '%s' %s" % (value, pattern))
finish()
