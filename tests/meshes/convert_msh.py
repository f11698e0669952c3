#!/usr/bin/env python3
"""Convert an ASCII Gmsh mesh of format 2.2 (quadrilaterals with boundary
lines, or hexahedra with boundary quadrilaterals, the physical tags of the
boundary elements being the boundary ids) into the same mesh as Gmsh
format 4.1 and as an Abaqus input file, for the tests of the mesh readers:

    convert_msh.py MESH.msh OUT.msh OUT.inp

The 4.1 file has one entity per physical tag (its physical tag is the
boundary id) and the nodes in one block; the Abaqus file numbers the
elements from 1 in one *ELEMENT block (deal.II's reader indexes them by
position) and gives every boundary id as a *SURFACE named SS<id> of
element faces (S1 to S4 of a CPE4, S1 to S6 of a C3D8).
"""

import sys

# the faces of a cell in Abaqus' numbering (node positions, from 0)
FACES = {3: [(0, 1), (1, 2), (2, 3), (3, 0)],
         5: [(0, 1, 2, 3), (4, 7, 6, 5), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6),
             (0, 4, 7, 3)]}


def read(path):
    """Nodes {tag: (x, y, z)}, elements [(type, physical tag, nodes)]."""
    lines = open(path).read().split("\n")
    assert lines[1].split()[:2] == ["2.2", "0"], "not an ASCII Gmsh 2.2 file"
    nodes, elements = {}, []
    i = lines.index("$Nodes") + 2
    while lines[i] != "$EndNodes":
        tag, x, y, z = lines[i].split()
        nodes[int(tag)] = (x, y, z)
        i += 1
    i = lines.index("$Elements") + 2
    while lines[i] != "$EndElements":
        words = [int(w) for w in lines[i].split()]
        n_tags = words[2]
        elements.append((words[1], words[3], words[3 + n_tags:]))
        i += 1
    return nodes, elements


def write_msh41(path, nodes, elements, dim):
    cell_type, face_type = (3, 1) if dim == 2 else (5, 3)
    boundary_tags = sorted({t for (kind, t, _) in elements if kind == face_type})
    volume_tags = sorted({t for (kind, t, _) in elements if kind == cell_type})
    lo = [min(float(p[d]) for p in nodes.values()) for d in range(3)]
    hi = [max(float(p[d]) for p in nodes.values()) for d in range(3)]
    box = " ".join(str(v) for v in lo + hi)
    counts = [0, 0, 0, 0]
    counts[dim - 1] = len(boundary_tags)
    counts[dim] = len(volume_tags)
    out = ["$MeshFormat", "4.1 0 8", "$EndMeshFormat", "$Entities",
           " ".join(str(c) for c in counts)]
    # one entity per physical tag, without bounding entities (not read)
    out += [f"{t} {box} 1 {t} 0" for t in boundary_tags + volume_tags]
    out.append("$EndEntities")
    tags = sorted(nodes)
    out += ["$Nodes", f"1 {len(tags)} {tags[0]} {tags[-1]}",
            f"{dim} {volume_tags[0]} 0 {len(tags)}"]
    out += [str(t) for t in tags]
    out += [" ".join(nodes[t]) for t in tags]
    out.append("$EndNodes")
    blocks = [(dim - 1, t, face_type) for t in boundary_tags] + \
             [(dim, t, cell_type) for t in volume_tags]
    members = {(t, kind): [e for e in elements if e[0] == kind and e[1] == t]
               for (_, t, kind) in blocks}
    n = sum(len(m) for m in members.values())
    out += ["$Elements", f"{len(blocks)} {n} 1 {n}"]
    number = 0
    for d, t, kind in blocks:
        out.append(f"{d} {t} {kind} {len(members[(t, kind)])}")
        for _, _, vertices in members[(t, kind)]:
            number += 1
            out.append(" ".join(str(v) for v in [number] + vertices))
    out.append("$EndElements")
    open(path, "w").write("\n".join(out) + "\n")


def write_abaqus(path, nodes, elements, dim):
    cell_type, face_type = (3, 1) if dim == 2 else (5, 3)
    cells = [e for e in elements if e[0] == cell_type]
    where = {}
    for number, (_, _, vertices) in enumerate(cells, start=1):
        for k, face in enumerate(FACES[cell_type], start=1):
            where[frozenset(vertices[i] for i in face)] = (number, k)
    out = ["*HEADING", "converted from a Gmsh mesh by tests/meshes/convert_msh.py", "*NODE"]
    out += [f"{t}, " + ", ".join(nodes[t][:dim]) for t in sorted(nodes)]
    out.append(f"*ELEMENT, TYPE={'CPE4' if dim == 2 else 'C3D8'}, ELSET=EB1")
    out += [f"{number}, " + ", ".join(str(v) for v in vertices)
            for number, (_, _, vertices) in enumerate(cells, start=1)]
    for t in sorted({e[1] for e in elements if e[0] == face_type}):
        out.append(f"*SURFACE, NAME=SS{t}")
        for kind, tag, vertices in elements:
            if kind == face_type and tag == t:
                number, k = where[frozenset(vertices)]
                out.append(f"{number}, S{k}")
    open(path, "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    source, msh41, inp = sys.argv[1:4]
    nodes, elements = read(source)
    dim = 3 if any(e[0] == 5 for e in elements) else 2
    write_msh41(msh41, nodes, elements, dim)
    write_abaqus(inp, nodes, elements, dim)
