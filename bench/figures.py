#!/usr/bin/env python3
"""Pictures of solutions for doc/results.md, drawn from the program's own VTU
output with matplotlib (no ParaView needed):

  doc/figures/solution_square.png        the square (prm/square.prm, 6 levels):
                                         the deformed mesh (displacement x 20)
                                         coloured by the von Mises stress
  doc/figures/solution_hertz.png         the half disc (prm/hertz.prm): von
                                         Mises stress and mesh near the contact
                                         zone, and the contact pressure against
                                         Hertz's
  doc/figures/solution_steel_cylinder.png the steel roller (prm/steel_cylinder.prm,
                                         mm and MPa): the same
  doc/figures/solution_ball3d.png        the 3D Hertz block (prm/ball3d.prm, 4
                                         levels): the contact pressure on the
                                         bottom face, with Hertz's contact circle

  doc/figures/adaptive_hertz.png         the half disc refined adaptively
                                         (prm/hertz_adaptive.prm, up to 30,000
                                         DoFs): the mesh coloured by the error
                                         indicator, the contact zone magnified
  doc/figures/adaptive_l_shape.png       the L-shape refined adaptively
                                         (prm/l_shape_singular.prm): the same,
                                         the re-entrant corner magnified

    bench/figures.py            # runs the six scenes (about two minutes)

The runs go to bench/results/figures_<scene>/.
"""
import math
import os
import re
import sys

import common
from common import RESULTS as RES, ROOT

sys.path.insert(0, os.path.join(ROOT, "tests", "solver"))
import vtu  # noqa: E402  (the reader the tests use)

FIG = os.path.join(ROOT, "doc", "figures")


def run(name, prm, settings):
    out = os.path.join(RES, "figures_" + name)
    summary = common.run(prm, ["Output/Verbose=false"] + settings, out)
    _, pieces = vtu.read_record(os.path.join(out, "solution_0000.pvtu"))
    return out, summary, pieces


def triangles(pieces, field, scale=0., component=0):
    """Points (displaced by scale * u), triangles (two per quadrilateral
    cell of the 2D output) and the field's values at the points."""
    xs, ys, values, tris = [], [], [], []
    for p in pieces:
        base = len(xs)
        for q, point in enumerate(p.points):
            u = p["u"][q]
            xs.append(point[0] + scale * u[0])
            ys.append(point[1] + scale * u[1])
            values.append(p[field][q][component])
        for c in p.cells:
            # deal.II's quadrilateral patches: vertices 0 1 3 2 in order
            a, b, d, e = (base + i for i in c)
            tris += [(a, b, d), (a, d, e)]
    return xs, ys, values, tris


def cell_edges(pieces, scale=0.):
    """The edges of the output cells, for drawing the mesh."""
    segments = []
    for p in pieces:
        for c in p.cells:
            corners = [p.points[i] for i in c]
            shifted = [(x[0] + scale * p["u"][i][0], x[1] + scale * p["u"][i][1])
                       for x, i in zip(corners, c)]
            for k in range(len(shifted)):
                segments.append([shifted[k], shifted[(k + 1) % len(shifted)]])
    return segments


def contact_rows(out):
    import csv
    with open(os.path.join(out, "contact.csv")) as f:
        return list(csv.DictReader(f))


def hertz_curve(hertz, xs):
    a, p0 = hertz["a"], hertz["p0"]
    return [p0 * math.sqrt(1 - (x / a) ** 2) if abs(x) < a else 0. for x in xs]


def square(plt, collections):
    out, s, pieces = run("square", "square.prm", [])
    xs, ys, vm, tris = triangles(pieces, "von_mises", scale=20.)
    fig, ax = plt.subplots(figsize=(5.6, 4.6))
    t = ax.tripcolor(xs, ys, tris, vm, shading="gouraud", cmap="viridis")
    ax.add_collection(collections.LineCollection(cell_edges(pieces, 20.), colors="k",
                                                 linewidths=0.15, alpha=0.4))
    fig.colorbar(t, ax=ax, label="von Mises stress")
    ax.set_aspect("equal")
    ax.set_title("square, 6 levels: deformed mesh (u x 20), von Mises stress", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(FIG, "solution_square.png"), dpi=110)
    plt.close(fig)


def hertz_like(plt, collections, name, prm, settings, zoom, unit_length, unit_stress, title):
    out, s, pieces = run(name, prm, settings)
    hertz = s["hertz"]
    xs, ys, vm, tris = triangles(pieces, "von_mises")
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.2))
    t = ax.tripcolor(xs, ys, tris, vm, shading="gouraud", cmap="viridis")
    ax.add_collection(collections.LineCollection(cell_edges(pieces), colors="k",
                                                 linewidths=0.2, alpha=0.5))
    cx, cy = hertz["contact_point"]
    ax.set_xlim(cx - zoom, cx + zoom)
    ax.set_ylim(cy, cy + zoom)
    ax.set_aspect("equal")
    fig.colorbar(t, ax=ax, label="von Mises stress" + unit_stress)
    ax.set_title(title + "\nvon Mises stress and mesh at the contact", fontsize=9)
    rows = contact_rows(out)
    rows.sort(key=lambda r: float(r["x"]))
    x = [float(r["x"]) - cx for r in rows]
    p = [-float(r["sigma_nn"]) for r in rows]
    act = [float(r["in_contact"]) > 0.5 for r in rows]
    bx.plot(x, p, "-", color="tab:blue", lw=1, label="computed -sigma_nn")
    bx.plot([a for a, b in zip(x, act) if b], [a for a, b in zip(p, act) if b], "o",
            mfc="none", color="tab:blue", ms=4, label="vertices in contact")
    span = 2.5 * hertz["a"]
    grid = [-span + 2 * span * k / 600 for k in range(601)]
    bx.plot(grid, hertz_curve(hertz, grid), "--", color="tab:red",
            label="Hertz: a = %.3g, p0 = %.4g" % (hertz["a"], hertz["p0"]))
    bx.set_xlim(-span, span)
    bx.set_xlabel("x - x_contact" + unit_length)
    bx.set_ylabel("contact pressure" + unit_stress)
    bx.set_title("contact pressure: peak %.4g (Hertz %.4g), l2 error %.3f"
                 % (hertz["peak"], hertz["p0"], hertz["pressure_error"]), fontsize=9)
    bx.legend(fontsize=8)
    bx.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(FIG, "solution_%s.png" % name), dpi=110)
    plt.close(fig)


def ball(plt):
    out, s, _ = run("ball3d", "ball3d.prm", [])
    hertz = s["hertz"]
    _, pieces = vtu.read_record(os.path.join(out, "contact_surface_0000.pvtu"))
    xs, ys, ps, tris = [], [], [], []
    for p in pieces:
        base = len(xs)
        for q, point in enumerate(p.points):
            xs.append(point[0])
            ys.append(point[1])
            ps.append(p["contact_pressure"][q][0])
        for c in p.cells:
            a, b, d, e = (base + i for i in c)
            tris += [(a, b, d), (a, d, e)]
    fig, ax = plt.subplots(figsize=(5.6, 4.8))
    t = ax.tripcolor(xs, ys, tris, ps, shading="gouraud", cmap="magma")
    circle = [(hertz["a"] * math.cos(2 * math.pi * k / 200),
               hertz["a"] * math.sin(2 * math.pi * k / 200)) for k in range(201)]
    ax.plot([c[0] for c in circle], [c[1] for c in circle], "--", color="tab:cyan",
            lw=1, label="Hertz's contact circle, a = %.3g" % hertz["a"])
    fig.colorbar(t, ax=ax, label="contact pressure")
    ax.set_xlim(-0.6, 0.6)
    ax.set_ylim(-0.6, 0.6)
    ax.set_aspect("equal")
    ax.legend(fontsize=8, loc="upper right")
    ax.set_title("3D Hertz block, 4 levels: contact pressure on the bottom face\n"
                 "peak %.4g (Hertz %.4g), l2 error %.3f"
                 % (hertz["peak"], hertz["p0"], hertz["pressure_error"]), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(FIG, "solution_ball3d.png"), dpi=110)
    plt.close(fig)


def last_step(out):
    """The pieces of the last step of an adaptive run (solution.pvd lists
    them as time steps)."""
    with open(os.path.join(out, "solution.pvd")) as f:
        files = re.findall(r'name="body" file="(solution_\d{4}\.pvtu)"', f.read())
    return vtu.read_record(os.path.join(out, files[-1]))[1]


def mesh_panel(ax, collections, pieces, xlim, ylim, title, linewidth=0.15):
    """The mesh of @p pieces coloured by log10 of the error indicator."""
    import matplotlib.colors as colors
    xs, ys, eta, tris = triangles(pieces, "error_indicator")
    t = ax.tripcolor(xs, ys, tris, [max(e, 1e-30) for e in eta], cmap="viridis",
                     norm=colors.LogNorm(vmin=max(min(eta), max(eta) * 1e-4), vmax=max(eta)))
    ax.add_collection(collections.LineCollection(cell_edges(pieces), colors="k",
                                                 linewidths=linewidth, alpha=0.6))
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=9)
    return t


def adaptive(plt, collections):
    """The adaptive meshes: the half disc (hertz_adaptive.prm up to 30,000
    DoFs) and the L-shape (l_shape_singular.prm, 10 steps)."""
    out, s, _ = run("hertz_adaptive", "hertz_adaptive.prm",
                    ["Adaptivity/Max DoFs=30000", "Output/Write vtu=true"])
    pieces = last_step(out)
    hertz, last = s["hertz"], s["adaptive_steps"][-1]
    cx, cy = hertz["contact_point"]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.4))
    mesh_panel(ax, collections, pieces, (cx - 0.5, cx + 0.5), (cy, cy + 0.5),
               "half disc after %d adaptive steps: %d cells, %d DoFs\n"
               "cells coloured by the error indicator eta_T (log scale)"
               % (last["step"], last["cells"], last["dofs"]))
    zoom = 2.5 * hertz["a"]
    t = mesh_panel(bx, collections, pieces, (cx - zoom, cx + zoom), (cy, cy + zoom),
                   "at the contact zone: Hertz's half-width a = %.4g (dashed),\n"
                   "vertices in contact (dots); pressure L2 error %.4f"
                   % (hertz["a"], hertz["pressure_error_boundary"]))
    rows = [r for r in contact_rows(out) if float(r["in_contact"]) > 0.5]
    bx.plot([float(r["x"]) for r in rows], [float(r["y"]) for r in rows], "o", color="tab:red",
            ms=2.5)
    for x in (cx - hertz["a"], cx + hertz["a"]):
        bx.axvline(x, ls="--", color="tab:red", lw=0.8)
    fig.colorbar(t, ax=bx, label="eta_T")
    fig.tight_layout()
    fig.savefig(os.path.join(FIG, "adaptive_hertz.png"), dpi=110)
    plt.close(fig)

    out, s, _ = run("l_shape", "l_shape_singular.prm", ["Output/Write vtu=true"])
    pieces = last_step(out)
    last = s["adaptive_steps"][-1]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(10, 4.6))
    mesh_panel(ax, collections, pieces, (-1, 1), (-1, 1),
               "L-shape after %d adaptive steps: %d cells, %d DoFs\n"
               "cells coloured by the error indicator eta_T (log scale)"
               % (last["step"], last["cells"], last["dofs"]), linewidth=0.4)
    t = mesh_panel(bx, collections, pieces, (-0.01, 0.01), (-0.01, 0.01),
                   "the re-entrant corner, magnified 100 times", linewidth=0.4)
    fig.colorbar(t, ax=bx, label="eta_T")
    fig.tight_layout()
    fig.savefig(os.path.join(FIG, "adaptive_l_shape.png"), dpi=110)
    plt.close(fig)


def main():
    try:
        import matplotlib
    except ImportError:
        sys.exit("bench/figures.py needs matplotlib: apt-get install python3-matplotlib, "
                 "then run it with the system's /usr/bin/python3")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib import collections
    os.makedirs(FIG, exist_ok=True)
    os.makedirs(RES, exist_ok=True)
    square(plt, collections)
    hertz_like(plt, collections, "hertz", "hertz.prm", [], 0.15, "", "",
               "half disc (R = 0.5), 3 levels, Grading 2")
    hertz_like(plt, collections, "steel_cylinder", "steel_cylinder.prm", [], 6., " [mm]",
               " [MPa]", "steel roller (R = 50 mm), 4 levels, Grading 3")
    ball(plt)
    adaptive(plt, collections)
    print("wrote doc/figures/solution_{square,hertz,steel_cylinder,ball3d}.png and "
          "adaptive_{hertz,l_shape}.png")


if __name__ == "__main__":
    main()
