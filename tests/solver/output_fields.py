# The VTU fields, read back (tests/solver/vtu.py decodes deal.II's
# compressed VTU):
# - the square of prm/square.prm in SI units (a 0.1 m steel square, E =
#   210e9 Pa, nu = 0.3, pushed 1 mm, 5 levels): the pvtu names its active
#   fields (Scalars von_mises, Vectors u, Tensors stress) and solution.pvd
#   lists it and the contact surface as two parts of one step (ParaView
#   opens both as one multiblock data set); the points are in the scene's units (the box [0, 0.1]^2);
#   stress is the symmetric part of sigma, von_mises and pressure are those
#   of stress with the plane-strain stress_zz = nu (s_xx + s_yy), all to
#   float precision; the error indicators eta_T (cell data) square-sum to
#   summary.json's error_indicators.sum, which is J (to 1e-7: J of the QP
#   carries the round-off of the assembled matrix, measured 1.4e-8 on the
#   square); the contact surface (contact_surface_0000.pvtu) has, at every
#   vertex, contact.csv's values of that vertex under its names (contact
#   pressure -sigma_nn, normal displacement u_n, initial gap, remaining gap
#   g - u_n, in_contact; to float precision), the remaining gap is never
#   negative, and the face's own pressure (face_pressure: RT0's normal
#   traction, constant on a face) integrated over the contact faces is the
#   contact force (the vertex means of contact.csv smear the zone's edge:
#   their integral is printed, 40% off on the 2-level cylinder);
#   summary.json's memory_by_phase has the resident memory after each phase
#   (and its file-backed part), its memory_mb the memory of the program's structures,
#   and memory_mb_by_level the same level by level.
# - prm/steel_cylinder.prm (2 levels), a curved boundary: the VTU draws the
#   cells with a quadratic mapping, subdivided once, so the midpoints of
#   the boundary edges lie on the circle of radius 50 mm as well.
# - prm/ball3d.prm (2 levels), 3D: the same fields without stress_zz, and
#   the contact surface's force.
# ctest: sanitize
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, relative_difference, rounded
import vtu

R = Runner(sys.argv)


def run_with_vtu(prm, settings, name):
    run = R.run(prm, settings + ["Output/Write vtu=true"], name=name)
    check(run.ok(), name + ": runs")
    return run


def check_fields(run, dim, nu, label):
    header, pieces = vtu.read_record(os.path.join(run.directory, "solution_0000.pvtu"))
    check('Scalars="von_mises" Vectors="u" Tensors="stress"' in header and
          all('Vectors="u"' in p.header for p in pieces),
          label + ": the pvtu and its pieces name the active fields")
    with open(os.path.join(run.directory, "solution.pvd")) as f:
        pvd = f.read()
    check('part="0" name="body" file="solution_0000.pvtu"' in pvd and
          'part="1" name="contact surface" file="contact_surface_0000.pvtu"' in pvd,
          label + ": solution.pvd lists the body and the contact surface as parts of one step")
    names = ["u", "sigma", "stress", "von_mises", "pressure", "div_sigma_plus_f",
             "error_indicator", "contact_status"] + (["stress_zz"] if dim == 2 else [])
    check(all(n in p.arrays for n in names for p in pieces), label + ": fields " + ", ".join(names))
    worst = 0.
    for p in pieces:
        for q in range(len(p.points)):
            sigma, s = p["sigma"][q], p["stress"][q]
            scale = max(1e-30, max(abs(v) for v in sigma))
            sym = max(abs(s[3 * i + j] - 0.5 * (sigma[3 * i + j] + sigma[3 * j + i]))
                      for i in range(dim) for j in range(dim)) / scale
            zz = p["stress_zz"][q][0] if dim == 2 else s[8]
            d = [s[0], s[4], zz]
            mean = sum(d) / 3.
            dev2 = sum((x - mean) ** 2 for x in d) + 2 * (s[1] ** 2 + s[2] ** 2 + s[5] ** 2)
            vm = math.sqrt(1.5 * dev2)
            e_vm = abs(vm - p["von_mises"][q][0]) / scale
            e_p = abs(-sum(d) / 3. - p["pressure"][q][0]) / scale
            e_zz = abs(zz - nu * (s[0] + s[4])) / scale if dim == 2 else 0.
            worst = max(worst, sym, e_vm, e_p, e_zz)
    check(worst < 1e-5, label + ": stress = sym(sigma), von_mises, pressure%s agree "
          "to float precision" % (", stress_zz = nu (s_xx + s_yy)" if dim == 2 else ""))
    return pieces


def surface_force(run, dim, normal):
    _, pieces = vtu.read_record(os.path.join(run.directory, "contact_surface_0000.pvtu"))
    names = ("contact_pressure", "normal_displacement", "gap", "remaining_gap", "in_contact",
             "face_pressure")
    check(all(n in p.arrays for p in pieces for n in names),
          "contact surface: " + ", ".join(names))
    with open(os.path.join(run.directory, "contact.csv")) as f:
        table = list(csv.DictReader(f))
    size = max(abs(float(r[k])) for r in table for k in ("x", "y", "z")[:dim])
    columns = {"contact_pressure": ("sigma_nn", -1.), "normal_displacement": ("u_n", 1.),
               "gap": ("gap", 1.), "remaining_gap": ("remaining_gap", 1.),
               "in_contact": ("in_contact", 1.)}
    largest = {name: max(abs(float(r[c])) for r in table) for name, (c, _) in columns.items()}
    worst, matched = 0., set()
    for p in pieces:
        for i, x in enumerate(p.points):
            # (the VTU's points are single precision)
            distance, row = min((math.dist(x[:dim], [float(r[k]) for k in ("x", "y", "z")[:dim]]),
                                 n) for n, r in enumerate(table))
            # (a vertex of a contact face that is also on a Dirichlet
            # boundary is no contact vertex: the face's own values there)
            if distance > 1e-6 * size:
                continue
            matched.add(row)
            for name, (column, sign) in columns.items():
                worst = max(worst, abs(p[name][i][0] - sign * float(table[row][column])) /
                            max(1e-300, largest[name]))
    check(len(matched) == len(table) and worst < 1e-6,
          "contact surface: contact.csv's values at every contact vertex (float precision)")
    force, vertex_force, lowest, scale = 0., 0., 0., 0.
    for p in pieces:
        for cell in p.cells:
            x = [p.points[i] for i in cell]
            if dim == 2:
                area = vtu.norm([x[1][k] - x[0][k] for k in range(3)])
            else:  # a quadrilateral: two triangles
                a = [x[1][k] - x[0][k] for k in range(3)]
                b = [x[2][k] - x[0][k] for k in range(3)]
                c = [x[3][k] - x[0][k] for k in range(3)]
                cross = lambda u, v: [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                                      u[0] * v[1] - u[1] * v[0]]
                area = 0.5 * (vtu.norm(cross(a, c)) + vtu.norm(cross(c, b)))
            pressure = sum(p["face_pressure"][i][0] for i in cell) / len(cell)
            force += pressure * area
            vertex_force += sum(p["contact_pressure"][i][0] for i in cell) / len(cell) * area
        lowest = min([lowest] + [v[0] for v in p["remaining_gap"]])
        scale = max([scale] + [abs(v[0]) for v in p["normal_displacement"]])
    F = abs(sum(f * n for f, n in zip(run["contact_force"], normal)))
    off = relative_difference(vertex_force, F)
    print("contact surface: the integral of contact.csv's pressure differs from the force "
          "by %s relative" % ("%.1g" % off if off >= 1e-3 else "less than 1e-3"))
    return force, F, lowest, scale


# the SI square
si = ["Material/mu=", "Material/lambda=", "Material/E=210e9", "Material/nu=0.3",
      "Geometry/Box upper corner=0.1, 0.1", "Data/Dirichlet values=0; -0.001",
      "Geometry/Levels=5"]
square = run_with_vtu("prm/square.prm", si, "square_si")
pieces = check_fields(square, 2, 0.3, "SI square")
xs = [x for p in pieces for x in p.points]
box = [min(x[0] for x in xs), max(x[0] for x in xs), min(x[1] for x in xs), max(x[1] for x in xs)]
check(max(abs(a - b) for a, b in zip(box, [0., 0.1, 0., 0.1])) < 1e-7,
      "SI square: the points fill the box [0, 0.1]^2 (the scene's units)")
eta2 = sum(p["error_indicator"][cell[0]][0] ** 2 for p in pieces for cell in p.cells)
indicators = square["error_indicators"]
check(relative_difference(eta2, indicators["sum"]) < 1e-5,
      "SI square: the eta_T of the VTU square-sum to error_indicators.sum (float precision)")
check(relative_difference(indicators["sum"], square["functional"]) < 1e-7,
      "SI square: error_indicators.sum = J to 1e-7")
print("SI square: %d cells, %d of them hold half of J" % (indicators["cells"],
                                                         indicators["cells_for_half_of_J"]))
phases = square["memory_by_phase"]
check([p["phase"] for p in phases] == ["Setup: mesh, DoFs, levels", "Functional weights", "Assembly",
      "Checks: data, rigid motions, definiteness", "Initial guess", "Setup: solver", "Solve"]
      and all(0 < p["rss_mb"] <= p["peak_rss_mb"] <= square["peak_rss_mb"] for p in phases)
      and all(a["peak_rss_mb"] <= b["peak_rss_mb"] for a, b in zip(phases, phases[1:]))
      and all(0 < p["rss_file_mb"] < p["rss_mb"] for p in phases),
      "SI square: memory_by_phase has the resident memory after each phase up to the solve, "
      "its peaks growing up to peak_rss_mb, the file-backed part of it positive and smaller")
memory = square["memory_mb"]
check(set(memory) >= {"mesh and DoF handler", "level data (coupling patterns, DoF tables, roles, bounds)",
                      "prolongations of the uniform levels",
                      "assembled problem (A, parts of J, vectors)", "multigrid: patch smoothers",
                      "multigrid: Galerkin products (index arrays)"}
      and all(v > 0 for v in memory.values())
      and sum(memory.values()) <= square["peak_rss_mb"],
      "SI square: memory_mb has the structures' memory, each positive, together below "
      "peak_rss_mb")
by_level = square["memory_mb_by_level"]
problem = by_level.get("assembled problem (A, parts of J, vectors)", [1])
patches = by_level.get("multigrid: patch smoothers", [0])
check(set(by_level) == set(memory) - {"mesh and DoF handler"}
      and all(len(v) == square["levels"] for v in by_level.values())
      and all(abs(sum(v) - memory[name]) <= 1e-6 * memory[name] for name, v in by_level.items())
      and all(mb == 0 for mb in problem[:-1]) and problem[-1] > 0
      and patches[-1] == max(patches),
      "SI square: memory_mb_by_level has every structure but the mesh, a list over the levels "
      "whose sum is memory_mb's; the assembled problem on the finest level only, the patch "
      "smoothers' largest part there")
# the multigrid solve frees the finest level's coupling pattern; the cross
# check's active set method factorizes on it, so that run keeps it
level_data = "level data (coupling patterns, DoF tables, roles, bounds)"
kept = R.run("prm/square.prm", si + ["Solver/Cross check=true"], name="square_si_cross_check")
check(memory[level_data] < 0.75 * kept["memory_mb"][level_data]
      and kept["functional"] == square["functional"],
      "SI square: the multigrid solve frees the finest level's coupling pattern (level data "
      "below 3/4 of that of the run with the cross check, which keeps it), with the same J")
force, F, lowest, scale = surface_force(square, 2, [0., -1.])
check(relative_difference(force, F) < 1e-5, "SI square: the contact surface's pressure "
      "integrates to the contact force (%s N/m)" % rounded(F, 4))
check(lowest >= -1e-7 * scale, "SI square: the remaining gap is never negative")

# a curved boundary, drawn curved
cylinder = run_with_vtu("prm/steel_cylinder.prm", ["Geometry/Levels=2"], "steel_cylinder")
pieces = check_fields(cylinder, 2, 0.3, "steel cylinder")
on_circle = set()
for p in pieces:
    for x in p.points:
        r = math.hypot(x[0], x[1] - 50.)
        if abs(r - 50.) < 1e-4 and x[1] < 50. - 1e-3:
            on_circle.add((round(x[0], 3), round(x[1], 3)))
with open(os.path.join(cylinder.directory, "contact.csv")) as f:
    vertices = len(f.read().splitlines()) - 1
print("steel cylinder: %d contact vertices, %d drawn points on the circle"
      % (vertices, len(on_circle)))
# n vertices below the top corners, n + 1 edges: drawn flat, only the n
# vertices lie on the circle, drawn curved the edges' midpoints too
check(len(on_circle) == 2 * vertices + 1, "steel cylinder: the edges between the boundary "
      "vertices are drawn on the circle (2 n + 1 points)")
force, F, _, _ = surface_force(cylinder, 2, [0., -1.])
check(relative_difference(force, F) < 1e-5,
      "steel cylinder: the contact surface's pressure integrates to the force")

# 3D
ball = run_with_vtu("prm/ball3d.prm", ["Geometry/Levels=2"], "ball3d")
check_fields(ball, 3, 0.25, "ball3d")
force, F, lowest, scale = surface_force(ball, 3, [0., 0., -1.])
check(relative_difference(force, F) < 1e-5,
      "ball3d: the contact surface's pressure integrates to the force")
check(lowest >= -1e-7 * scale, "ball3d: the remaining gap is never negative")
finish()
