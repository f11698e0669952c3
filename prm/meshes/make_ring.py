#!/usr/bin/env python3
"""Write the coarse mesh of prm/shrink_fit.prm: a ring (annulus) around the
origin, inner radius 20, outer radius 40 (mm), of 16 x 2 quadrilaterals
with their vertices on the two circles, in Gmsh's format 2.2. Boundary id
(physical tag) 1 is the inner circle, 2 the outer one; the scene's
Geometry/Manifolds keeps both circular under refinement.

    make_ring.py [OUTPUT]     (default: ring.msh beside this script)

tests/solver/shrink_fit checks that it writes prm/meshes/ring.msh.
"""
import math
import os
import sys

INNER, OUTER, SECTORS, LAYERS = 20.0, 40.0, 16, 2


def node(sector, layer):
    """The number of the vertex at @p sector (angle) and @p layer (radius)."""
    return layer * SECTORS + sector % SECTORS + 1


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else \
        os.path.join(os.path.dirname(os.path.abspath(__file__)), "ring.msh")
    nodes = []
    for layer in range(LAYERS + 1):
        r = INNER + (OUTER - INNER) * layer / LAYERS
        for sector in range(SECTORS):
            t = 2 * math.pi * sector / SECTORS
            nodes.append((r * math.cos(t), r * math.sin(t)))
    # (type, physical tag, vertices): lines (1) of the two circles, then the
    # quadrilaterals (3), counterclockwise
    elements = []
    for sector in range(SECTORS):
        elements.append((1, 1, [node(sector, 0), node(sector + 1, 0)]))
        elements.append((1, 2, [node(sector, LAYERS), node(sector + 1, LAYERS)]))
    for layer in range(LAYERS):
        for sector in range(SECTORS):
            elements.append((3, 0, [node(sector, layer), node(sector, layer + 1),
                                    node(sector + 1, layer + 1), node(sector + 1, layer)]))
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for k, (x, y) in enumerate(nodes):
            f.write("%d %.17g %.17g 0\n" % (k + 1, x, y))
        f.write("$EndNodes\n$Elements\n%d\n" % len(elements))
        for k, (kind, tag, vertices) in enumerate(elements):
            f.write("%d %d 2 %d %d %s\n" % (k + 1, kind, tag, tag, " ".join(map(str, vertices))))
        f.write("$EndElements\n")


if __name__ == "__main__":
    main()
