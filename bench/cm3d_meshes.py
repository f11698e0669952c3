#!/usr/bin/env python3
"""What limits the 3D Cattaneo-Mindlin scenes (doc/method.md section 7.7):
the mesh at the contact's edge. Two meshes of prm/meshes/
make_cattaneo_mindlin_3d.py with the same number of cells, on 2 levels
(90,039 DoFs): the shipped fine mesh (--finest 64: 1/128 at the contact
point on 2 levels, but 1/32 at the contact's edge r = a = 0.080) and one
with cells 1/64 wide out to r = 1/8 (--finest 32 --core 4).

For each, pressed without friction: the pressure's relative L2 error
against Hertz's (the program's "Hertz" line) beside the relative L2 error
of the best approximation of Hertz's pressure by one constant per contact
face of the finest level (the face means, a midpoint rule of 12 x 12
points per face, with the computed contact radius a). Then the whole
Coulomb load path of prm/cattaneo_mindlin_3d_fine.prm on the second mesh:
each pull's stick disc against Cattaneo and Mindlin's, its wall time and
peak memory (the fine mesh's own path is in doc/friction_results.md,
bench/friction.py). Prints the tables (the runs' output under
bench/results/cm3d_meshes/); about 13 minutes on this machine's 2 cores.

    cm3d_meshes.py [--bin PATH]
"""
import argparse
import math
import os
import re
import subprocess
import sys

import friction
from common import BIN, RESULTS, ROOT

friction.RES = os.path.join(RESULTS, "cm3d_meshes")
GENERATOR = os.path.join(ROOT, "prm", "meshes", "make_cattaneo_mindlin_3d.py")
HERTZ_RADIUS = re.compile(r"Hertz \(sphere, R = \S+, E\* = \S+\): F = \S+, a = (\S+),")
PRESSED = ["Friction/Law=none", "Data/Load steps=Q=0"]


def contact_nodes(path):
    """The sorted x coordinates of the mesh file's nodes (a tensor grid,
    the same in y)."""
    with open(path) as f:
        lines = f.read().split("$Nodes\n")[1].split("$EndNodes")[0].split("\n")[1:-1]
    return sorted({float(line.split()[1]) for line in lines})


def best_approximation(nodes, a, refinements=1, points=12):
    """The relative L2 error of the best approximation of Hertz's pressure
    sqrt(1 - r^2/a^2) by a constant on each contact face of the mesh with
    the tensor grid @p nodes refined @p refinements times."""
    for _ in range(refinements):
        nodes = sorted(nodes + [(p + q) / 2 for p, q in zip(nodes, nodes[1:])])
    cells = [(p, q) for p, q in zip(nodes, nodes[1:]) if min(abs(p), abs(q)) < a or p * q < 0]
    error = norm = 0.
    for x0, x1 in cells:
        for y0, y1 in cells:
            weight = (x1 - x0) * (y1 - y0) / points ** 2
            values = [math.sqrt(max(0., 1 - ((x0 + (x1 - x0) * (i + .5) / points) ** 2
                                             + (y0 + (y1 - y0) * (j + .5) / points) ** 2) / a ** 2))
                      for i in range(points) for j in range(points)]
            mean = sum(values) / len(values)
            error += weight * sum((v - mean) ** 2 for v in values)
            norm += weight * sum(v * v for v in values)
    return math.sqrt(error / norm)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--bin", default=BIN)
    args = ap.parse_args()
    os.makedirs(friction.RES, exist_ok=True)
    core = os.path.join(friction.RES, "cattaneo_mindlin_3d_32_4.msh")
    subprocess.run([sys.executable, GENERATOR, "--finest", "32", "--core", "4", core], check=True)
    meshes = {"fine (--finest 64)": os.path.join(ROOT, "prm", "meshes",
                                                   "cattaneo_mindlin_3d_fine.msh"),
              "core (--finest 32 --core 4)": core}

    rows = ["| mesh | DoFs | contact's edge between | best approximation by face constants "
            "| pressure error | wall time [s] |", "|---|---|---|---|---|---|"]
    for k, (name, path) in enumerate(meshes.items()):
        r = friction.run(args.bin, "cattaneo_mindlin_3d.prm", PRESSED + ["Geometry/Mesh file=" + path],
                         "pressed_%d" % k)
        a = float(HERTZ_RADIUS.search(r["screen"]).group(1))
        edge = re.search(r"contact edge between (\S+) and (\S+),", r["screen"])
        rows.append("| %s | %d | %s and %s | %.3f | %.3f | %.1f |" % (
            name, r["summary"]["dofs"], edge.group(1), edge.group(2),
            best_approximation(contact_nodes(path), a),
            float(friction.HERTZ.search(r["screen"]).group(1)), r["wall"]))
    print("## Pressed without friction, 2 levels\n\n" + "\n".join(rows) + "\n")

    r = friction.run(args.bin, "cattaneo_mindlin_3d_fine.prm",
                     ["Geometry/Mesh file=" + core], "coulomb_core")
    rows = ["| Q/(f P) | c | stick zone | ends from -c, c [spacings] | end behind the pull "
            "inside -c by | traction error of q |", "|---|---|---|---|---|---|"]
    for m in friction.CATTANEO_MINDLIN.finditer(r["screen"]):
        if float(m.group(1)) <= 1e-6:
            continue  # (pressed)
        c = float(m.group(2))
        rows.append("| %s | %s | %s | %s | %s | %s |" % (
            m.group(1), m.group(2),
            "%s to %s" % (m.group(3), m.group(4)) if m.group(3) else "no vertex sticks",
            "%s, %s" % (m.group(5), m.group(6)) if m.group(3) else "",
            "%.3f" % (float(m.group(3)) + c) if m.group(3) else "", m.group(7)))
    print("## The Coulomb path of prm/cattaneo_mindlin_3d_fine.prm on the core mesh, "
          "%.0f s, peak %.0f MB\n\n" % (r["wall"], r["summary"]["peak_rss_mb"]) + "\n".join(rows))


if __name__ == "__main__":
    main()
