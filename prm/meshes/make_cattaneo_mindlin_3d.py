#!/usr/bin/env python3
"""Write the coarse mesh of prm/cattaneo_mindlin_3d.prm: the box
[-0.5, 0.5] x [-0.5, 0.5] x [0, 0.5] of hexahedra graded toward the contact
point at the origin, in Gmsh's format 2.2. From the center out, in each
direction, K cells of 1/N, then cells that double in size up to 1/2:
1/16, 1/16, 1/8, 1/4 (N = 16, K = 2, 8 x 8 x 4 cells), or with --finest 64
(prm/cattaneo_mindlin_3d_fine.prm) 1/64, 1/64, 1/32, 1/16, 1/8, 1/4
(12 x 12 x 6 cells). Uniform refinement keeps the grading. The edge of the
contact zone (radius 0.08) lies in cells 1/16 wide on both meshes: the
finer one refines the contact point only. With --core 4 and --finest 32
the cells are 1/32 wide out to 1/8, the whole contact, for the finer
mesh's number of cells (doc/method.md section 7.7 compares the two). The
far cells are up to 4 (or 16) times as long as they are wide. Boundary ids
(physical tags): 1 the contact face z = 0, 2 the top z = 0.5, 3 the sides.

    make_cattaneo_mindlin_3d.py [--finest N] [--core K] [OUTPUT]
        N: 1/N is the width of the cells at the contact point, a power of
           2 from 4 (default 16); K: the number of those cells from the
           center out, a power of 2 from 2 to N/2 (default 2); OUTPUT:
           default cattaneo_mindlin_3d.msh (N = 16) or
           cattaneo_mindlin_3d_fine.msh (N = 64) beside this script

tests/solver/cattaneo_mindlin_3d checks that it writes the shipped files.
"""
import argparse
import math
import os

CONTACT, TOP, SIDES = 1, 2, 3


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--finest", type=int, default=16)
    parser.add_argument("--core", type=int, default=2)
    parser.add_argument("output", nargs="?")
    args = parser.parse_args()
    levels = round(math.log2(args.finest)) if args.finest > 0 else 0
    if args.finest < 4 or 2 ** levels != args.finest:
        parser.error("--finest must be a power of 2 of at least 4, not %d" % args.finest)
    core = round(math.log2(args.core)) if args.core > 0 else -1
    if core < 1 or 2 ** core != args.core or args.core > args.finest // 2:
        parser.error("--core must be a power of 2 from 2 to N/2, not %d" % args.core)
    # node coordinates from the center out: K cells of 1/N, then doubling
    # cells to 1/2: 0, 1/N, ..., K/N, 2K/N, 4K/N, ..., 1/2
    half = [i / args.finest for i in range(args.core + 1)] + \
        [2.0 ** -k for k in range(levels - core - 1, 0, -1)]
    xs = [-x for x in reversed(half[1:])] + half
    zs = half
    name = "cattaneo_mindlin_3d_%d_%d.msh" % (args.finest, args.core) if args.core != 2 else \
        "cattaneo_mindlin_3d.msh" if args.finest == 16 else \
        "cattaneo_mindlin_3d_fine.msh" if args.finest == 64 else \
        "cattaneo_mindlin_3d_%d.msh" % args.finest
    path = args.output or os.path.join(os.path.dirname(os.path.abspath(__file__)), name)
    n = len(xs)

    def node(i, j, k):
        return (k * n + j) * n + i + 1

    nodes = [(x, y, z) for z in zs for y in xs for x in xs]
    elements = []  # (type, physical tag, vertices)
    m = n - 1
    # boundary quadrilaterals (3), then the hexahedra (5: the bottom face
    # counterclockwise seen from above, then the top face)
    for j in range(m):
        for i in range(m):
            elements.append((3, CONTACT, [node(i, j, 0), node(i, j + 1, 0),
                                          node(i + 1, j + 1, 0), node(i + 1, j, 0)]))
            top = len(zs) - 1
            elements.append((3, TOP, [node(i, j, top), node(i + 1, j, top),
                                      node(i + 1, j + 1, top), node(i, j + 1, top)]))
    for k in range(len(zs) - 1):
        for t in range(m):
            elements.append((3, SIDES, [node(0, t, k), node(0, t + 1, k),
                                        node(0, t + 1, k + 1), node(0, t, k + 1)]))
            elements.append((3, SIDES, [node(m, t, k), node(m, t, k + 1),
                                        node(m, t + 1, k + 1), node(m, t + 1, k)]))
            elements.append((3, SIDES, [node(t, 0, k), node(t, 0, k + 1),
                                        node(t + 1, 0, k + 1), node(t + 1, 0, k)]))
            elements.append((3, SIDES, [node(t, m, k), node(t + 1, m, k),
                                        node(t + 1, m, k + 1), node(t, m, k + 1)]))
    for k in range(len(zs) - 1):
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
