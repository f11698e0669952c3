#!/usr/bin/env python3
"""Write the coarse mesh of prm/cattaneo_mindlin_3d.prm: the box
[-0.5, 0.5] x [-0.5, 0.5] x [0, 0.5] of 8 x 8 x 4 hexahedra, graded toward
the contact point at the origin (cell sizes 1/16, 1/16, 1/8, 1/4 from the
center out, in each direction), in Gmsh's format 2.2. Uniform refinement
keeps the grading: the contact zone (radius 0.08) is meshed as finely as a
uniform box with 8 times the cells in each direction. Boundary ids
(physical tags): 1 the contact face z = 0, 2 the top z = 0.5, 3 the sides.

    make_cattaneo_mindlin_3d.py [OUTPUT]   (default: cattaneo_mindlin_3d.msh
                                            beside this script)

tests/solver/cattaneo_mindlin_3d checks that it writes the shipped file.
"""
import os
import sys

HALF = [0.0, 0.0625, 0.125, 0.25, 0.5]  # node coordinates from the center out
XS = [-x for x in reversed(HALF[1:])] + HALF
ZS = HALF
CONTACT, TOP, SIDES = 1, 2, 3


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else \
        os.path.join(os.path.dirname(os.path.abspath(__file__)), "cattaneo_mindlin_3d.msh")
    n = len(XS)

    def node(i, j, k):
        return (k * n + j) * n + i + 1

    nodes = [(x, y, z) for z in ZS for y in XS for x in XS]
    elements = []  # (type, physical tag, vertices)
    m = n - 1
    # boundary quadrilaterals (3), then the hexahedra (5: the bottom face
    # counterclockwise seen from above, then the top face)
    for j in range(m):
        for i in range(m):
            elements.append((3, CONTACT, [node(i, j, 0), node(i, j + 1, 0),
                                          node(i + 1, j + 1, 0), node(i + 1, j, 0)]))
            top = len(ZS) - 1
            elements.append((3, TOP, [node(i, j, top), node(i + 1, j, top),
                                      node(i + 1, j + 1, top), node(i, j + 1, top)]))
    for k in range(len(ZS) - 1):
        for t in range(m):
            elements.append((3, SIDES, [node(0, t, k), node(0, t + 1, k),
                                        node(0, t + 1, k + 1), node(0, t, k + 1)]))
            elements.append((3, SIDES, [node(m, t, k), node(m, t, k + 1),
                                        node(m, t + 1, k + 1), node(m, t + 1, k)]))
            elements.append((3, SIDES, [node(t, 0, k), node(t, 0, k + 1),
                                        node(t + 1, 0, k + 1), node(t + 1, 0, k)]))
            elements.append((3, SIDES, [node(t, m, k), node(t + 1, m, k),
                                        node(t + 1, m, k + 1), node(t, m, k + 1)]))
    for k in range(len(ZS) - 1):
        for j in range(m):
            for i in range(m):
                elements.append((5, 0, [node(i, j, k), node(i + 1, j, k),
                                        node(i + 1, j + 1, k), node(i, j + 1, k),
                                        node(i, j, k + 1), node(i + 1, j, k + 1),
                                        node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]))
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(nodes))
        for number, (x, y, z) in enumerate(nodes):
            f.write("%d %.17g %.17g %.17g\n" % (number + 1, x, y, z))
        f.write("$EndNodes\n$Elements\n%d\n" % len(elements))
        for number, (kind, tag, vertices) in enumerate(elements):
            f.write("%d %d 2 %d %d %s\n" % (number + 1, kind, tag, tag,
                                            " ".join(map(str, vertices))))
        f.write("$EndElements\n")


if __name__ == "__main__":
    main()
