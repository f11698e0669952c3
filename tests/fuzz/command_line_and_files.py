# ctest: long sanitize cost=242
"""Fuzz the command line, the scene files and the parameter values of
fosls-contact.

usage: command_line_and_files.py FOSLS_CONTACT SOURCE_DIR [--cases N]
           [--mesh-cases M] [--cause-cases K] [--mpi-cases P] [--seed S] [--jobs J]

Generates N cases (default 600) with a fixed seed (default 1) from the
scenes in tests/scenes (Geometry/Levels = 2, at most 20 iterations, one
thread): random valid values (which reach the solver: weights, solver
choices, data expressions, ...), random and malformed values of every
parameter (huge numbers,
NaN/inf, empty, control characters, bounds +-1), random expressions and
constants, malformed --set arguments and options, scene files mutated
(truncated, lines dropped, doubled or swapped, garbage bytes, unbalanced
subsections, includes of themselves, of each other, of missing files, of
devices), files of garbage bytes, empty files and JSON scenes (as
--print-parameters writes them) mutated. Each case runs in its own
directory with a timeout of 60 s. A case fails on a crash (a signal), a
hang (the timeout), an exit code other than 0, 1 or 2, an exit code 1
whose stderr is not exactly one line `fosls-contact: error in ...` without
raw control bytes, output files (or a staging directory, a lock file)
left after an error, or a run with exit code 0 or 2 without its
summary.json, or with something on stderr beyond the one line of exit 2.

Then M mesh cases (default 150; --mesh-cases M, drawn with a random
generator of their own so that the cases above stay the same): a small
structured mesh of quadrilaterals or hexahedra (Geometry/Shape = file,
the whole boundary clamped) written as Gmsh 2.2, Gmsh 4.1, VTK, AVS UCD
or Abaqus, with one corruption drawn: a node index past the nodes or
negative, a cell listed twice (same order, rotated, reversed), a cell
listed twisted (a quadrilateral crossed, a hexahedron's upper face turned
by a quarter, a half or three quarters), a cell refined alone (hanging nodes), a cell moved by half its size (overlap), a
shared node split in two at one point (a crack), z != 0 in 2D, a
coordinate that is no finite number or missing, a Gmsh header of another
version than its body, a truncation at a random byte; or none, or a UTF-8
byte order mark and CRLF line ends. Beyond the failures above, a mesh
case fails if a corruption that must be refused (all but the truncation)
runs (exit code other than 1), or if a valid mesh (none, BOM and CRLF) is
refused (exit code 1).

Then K cause cases (default 60; --cause-cases K, with a random generator
of their own): hostile inputs of the classes that must be refused naming
their cause, on the square or the cube (or a small mesh file): a data
expression (Dirichlet values, traction, gap, body force) that is NaN in
part of the body, or of a size the dimensionless problem overflows on
(1e120 to 1e300); a push so small that it underflows (1e-300 to 1e-160);
a box so thin that its cells' aspect ratio is 2e4 to 1e9;
a Gmsh physical tag that is negative or above 255; an Abaqus surface whose
name holds no id, a signed one or two numbers; a mesh with a part apart
from the rest that only a Neumann boundary or the obstacle holds. A cause
case fails if it is not refused (exit code 1) in one line that names the
cause (the parameter, the physical tag, the *SURFACE, the parts).

Then P MPI cases (default 20; --mpi-cases P, a generator of their own):
two processes started by one mpirun with `-np 1 A : -np 1 B`, where B is
A or differs in one drawn way: another --set value (Levels, solver, output
directory, adaptivity, dimension), an option on one process only (--help,
--version, --print-parameters), or another scene file (a line changed). A
case fails beyond the failures above if processes with different inputs
are not refused with exit code 1 (or hang), or if the same inputs are
refused.

Prints the number of cases and of failures of each kind (all 0 when the
program is right); every failing case is printed with the command that
reproduces it (its files stay in case_NNNN/) and the script exits with 1.
"""
import concurrent.futures
import json
import os
import random
import re
import subprocess
import sys

SCENES = ["square.prm", "hertz.prm", "cube3d.prm", "elasticity_mms.prm",
          "square_tilted_obstacle.prm"]
TIMEOUT = 60
# valid values that would make a case slow (big meshes, many iterations)
SAFE_MAX = {"Levels": 3, "Box subdivisions": 4, "Coarse refinements": 3, "Length subdivisions": 4,
            "Threads": 4, "Max iterations": 50, "Pre smoothing": 5, "Post smoothing": 5,
            "Krylov steps": 50, "Definiteness check max dofs": 20000,
            "Steps": 4}
NUMBERS = ["0", "-0", "1", "-1", "0.5", "1e-300", "1e300", "1e308", "1e309", "-1e309",
           "nan", "NaN", "inf", "-inf", "infinity", "abc", "", " ", "1e", "0x10", "1.5.2",
           "99999999999999999999", "2147483648", "-2147483649", "1,2", "{1}", "1 2",
           "\x01", "1\x7f", "\u00e9", "%s%n", "1;2"]
TOKENS = ["x", "y", "z", "1", "0", "2.5", "-", "+", "*", "/", "^", "(", ")", "sin", "cos",
          "exp", "log", "sqrt", "pi", "1e308", "nan", "inf", ";", ",", "if", "a", "_", "$",
          "&&", "==", "?", ":", "<", ">", " ", "abs", "min", "max", "rand"]
EXPRESSIONS = ["", ";", ";;", "1;2", "0; 0", "0; 0; 0", "1/(x-x)", "sqrt(-1)", "log(0)",
               "exp(1000)", "x^1e10", "1e308*1e308", "sin(", "(((((", "a" * 150,
               "if(x<0.5,1,0)", "0; -0.01", "x; y", "nan; 0", "0; inf", "x y", "1e309",
               "0;" * 40, "\x00", "0; -0.01\n0"]
CONSTANTS = ["a=1", "a=b", "=1", "a=", "a=1,a=2", "x=1", "pi=3", "1a=2", "a" * 120 + "=1",
             "a=nan", "a=1e309", "a=1=2", ",", "a=1,,b=2", "_=1", "z=1", "a b=1", "\x01=1"]
DIRECTORIES = ["", " ", ".", "..", "/", "/proc/fuzz", "a/b/c", "x\x01y", "out/", "out//x",
               "scene.prm", "scene.prm/x", "d" * 300, "~", "-", "*", "out/../out2"]
SET_ARGUMENTS = ["", "=", "Solver", "Solver/", "/=1", "Solver/=1", "/Tolerance=1",
                 "Solver/Tolerance", "a/b/c/d=1", "Solver//Tolerance=1", "Solver/Tolerance==1",
                 "Solvr/Tolerance=1", "Solver/Tolerence=1", "\u00e9/\u00e9=\u00e9",
                 "Solver/Type=\x1b[31m", "Output/Directory=a\nb", "x" * 5000 + "=1",
                 "Geometry/Levels= 2 ", "Geometry/Levels=2\r"]
OPTIONS = [["--foo"], ["-"], ["--"], ["--set"], ["--help", "--set", "x"], ["--version"],
           ["--print-parameters"], ["--print-parameters", "--set", "Solver/Tolerance=1"],
           ["a.prm", "b.prm"], ["--set=Solver/Tolerance=1"], ["-h"], ["--print-parameters", "-"]]
LINES = ["subsection", "subsection Nope", "end", "end end", "END", "set", "set =", "set = 1",
         "set Levels", "set Levels = = 2", "include", "include ", "include /dev/null",
         "include /dev/zero", "include /proc/self/environ", "include .", "include missing.prm",
         "include scene.prm", "include other.prm", "\\", "# comment", "\t\tset\tLevels\t=\t2",
         "subsection Geometry\\", "set Levels = 2 # \\", "\x00\x01\x02", "\xff\xfe"]


def catalogue(exe):
    """Every parameter: (section path, name, pattern description)."""
    out = subprocess.run([exe, "--print-parameters"], stdout=subprocess.PIPE,
                         check=True).stdout
    entries = []

    def walk(node, path):
        for key, value in node.items():
            if isinstance(value, dict) and "value" in value:
                entries.append((path, key, value.get("pattern_description", "")))
            elif isinstance(value, dict):
                walk(value, path + [key])
    walk(json.loads(out), [])
    return entries


def value_for(rng, name, pattern):
    """A random value for a parameter with @p pattern."""
    if name.startswith("Directory"):
        return rng.choice(DIRECTORIES)
    if name == "Constants":
        return rng.choice(CONSTANTS)
    if pattern.startswith("[Selection"):
        choices = pattern[11:-2].split("|")
        return rng.choice(choices + [c.upper() for c in choices] + ["", " x", choices[0] + " "])
    if pattern == "[Bool]":
        return rng.choice(["true", "false", "yes", "1", "", "TRUE", "false "])
    if pattern.startswith("[Integer"):
        bounds = re.findall(r"-?\d+", pattern)
        low = int(bounds[0]) if bounds else 0
        high = min(int(bounds[1]) if len(bounds) > 1 else 10, SAFE_MAX.get(name, 10 ** 9))
        values = [str(low - 1), str(low), str(min(low + 1, high)), str(high), str(high + 1)]
        if name in SAFE_MAX:
            values.remove(str(high + 1))
        return rng.choice(values + [v for v in NUMBERS if not re.fullmatch(r"\d+", v)])
    if pattern.startswith("[List"):
        if name in SAFE_MAX:
            return rng.choice(["1, 1", "2, 1", "0, 1", "1", "1, 1, 1", "", "a, b", "1,,1"])
        return ", ".join(rng.choice(NUMBERS[:12]) for _ in range(rng.randint(0, 4)))
    if name in ("lambda",) or pattern.startswith("[Double"):
        return rng.choice(NUMBERS)
    # [Anything]: expressions and lists
    if rng.random() < 0.5:
        return rng.choice(EXPRESSIONS)
    return "".join(rng.choice(TOKENS) for _ in range(rng.randint(1, 8)))


def valid_value_for(rng, name, pattern, dim):
    """A random value that the pattern accepts (the run may still refuse it:
    an indefinite functional, a NaN iterate, no convergence, ...)."""
    if pattern.startswith("[Selection"):
        return rng.choice(pattern[11:-2].split("|"))
    if pattern == "[Bool]":
        return rng.choice(["true", "false"])
    if pattern.startswith("[Integer"):
        bounds = re.findall(r"-?\d+", pattern)
        low = int(bounds[0]) if bounds else 0
        high = min(int(bounds[1]) if len(bounds) > 1 else 10, SAFE_MAX.get(name, 1000))
        return str(rng.randint(low, max(low, high)))
    if pattern.startswith("[Double"):
        bounds = re.findall(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?", pattern)
        low = float(bounds[0]) if bounds else -1e300
        high = float(bounds[1]) if len(bounds) > 1 and "MAX" not in pattern.split("...")[1] \
            else 1e300
        candidates = [v for v in [0, 1e-12, 1e-8, 0.1, 0.5, 1, 2, 10, 1e3, 1e10, 1e300, -1, -1e10]
                      if low <= v <= high]
        return repr(rng.choice(candidates or [low]))
    if name == "lambda":
        return rng.choice(["0", "1", "1e10", "inf", "1e300"])
    if name == "Constants":
        return rng.choice(["a=1", "a=1,b=2", "k=1e10", "k=0", ""])
    if name == "Load steps":
        return rng.choice(["", "a=2", "a=1; a=2", "a=1, b=0; b=3", "k=1e10; k=0"])
    if name.endswith("ids") or name == "Dirichlet components":
        return rng.choice(["", "0", "1", "2", "0, 1", "0, 1, 2, 3", "7", "all", "0: 0"])
    if name.startswith("Directory"):
        return rng.choice(["out", "out/sub", "o2"])
    n = {"Exact stress": dim * dim, "Gap": 1}.get(name, dim)
    pieces = ["0", "x", "y", "-0.01", "sin(pi*x)", "1e10*x", "x*y", "exp(x)", "1e-300",
              "1/(1+x*x)", "if(x<0.5,0,-0.01)"]
    return "; ".join(rng.choice(pieces) for _ in range(n))


def mutate_scene(rng, text):
    lines = text.split("\n")
    kind = rng.randrange(7)
    if kind == 0 and lines:
        return "\n".join(lines[:rng.randrange(len(lines))]) + ("\n" if rng.random() < 0.5 else "")
    if kind == 1 and text:
        return text[:rng.randrange(len(text))]
    if kind == 2 and lines:
        del lines[rng.randrange(len(lines))]
    elif kind == 3 and lines:
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
    elif kind == 4 and len(lines) > 1:
        i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
        lines[i], lines[j] = lines[j], lines[i]
    elif kind == 5:
        lines.insert(rng.randrange(len(lines) + 1), rng.choice(LINES))
    else:
        garbage = "".join(chr(rng.randrange(256)) for _ in range(rng.randint(1, 20)))
        lines.insert(rng.randrange(len(lines) + 1), garbage)
    return "\n".join(lines)


def make_case(rng, number, source, entries):
    """(arguments, {file name: bytes}, kind) of case @p number."""
    scene_name = rng.choice(SCENES)
    with open(os.path.join(source, "tests/scenes", scene_name)) as f:
        base = f.read()
    base_arguments = ["--set", "Geometry/Levels=2", "--set", "Solver/Max iterations=20",
                      "--set", "Solver/Threads=1", "--set", "Output/Directory=out",
                      "--set", "Output/Verbose=false"]
    files = {}
    kind = rng.choice(["valid", "valid", "valid", "valid", "value", "value", "expression",
                       "set", "option", "file", "file", "garbage", "json", "include"])
    arguments = ["scene.prm"] + base_arguments
    files["scene.prm"] = base.encode()
    if kind == "valid":
        dim = 3 if "cube3d" in scene_name else 2
        for _ in range(rng.randint(1, 2)):
            path, name, pattern = rng.choice(entries)
            if name in ("Dimension", "Shape"):
                continue
            arguments += ["--set", "/".join(path + [name]) + "="
                          + valid_value_for(rng, name, pattern, dim)]
    elif kind == "value":
        for _ in range(rng.randint(1, 3)):
            path, name, pattern = rng.choice(entries)
            arguments += ["--set", "/".join(path + [name]) + "=" + value_for(rng, name, pattern)]
    elif kind == "expression":
        name = rng.choice(["Body force", "Dirichlet values", "Traction", "Gap",
                           "Obstacle normal", "Exact displacement", "Exact stress",
                           "Initial displacement", "Constants"])
        value = value_for(rng, name, "[Anything]")
        arguments += ["--set", "Data/" + name + "=" + value]
        if name == "Initial displacement":
            arguments += ["--set", "Solver/Initial guess=expression"]
    elif kind == "set":
        arguments += ["--set", rng.choice(SET_ARGUMENTS)]
    elif kind == "option":
        option = rng.choice(OPTIONS)
        arguments = option + (arguments if rng.random() < 0.5 else [])
    elif kind == "file":
        text = base
        for _ in range(rng.randint(1, 3)):
            text = mutate_scene(rng, text)
        files["scene.prm"] = text.encode("latin-1", "replace")
        files["other.prm"] = b"include scene.prm\n"
    elif kind == "garbage":
        size = rng.choice([0, 1, 10, 1000, 100000])
        files["scene.prm"] = bytes(rng.randrange(256) for _ in range(size))
        if rng.random() < 0.2:
            files["scene.prm"] = b"set " + b"x" * 200000 + b"\n"
    elif kind == "json":
        text = subprocess.run([EXE, "--print-parameters", os.path.join(source, "tests/scenes",
                                                                       scene_name)]
                              + base_arguments, stdout=subprocess.PIPE).stdout.decode()
        if rng.random() < 0.5:
            text = text[:rng.randrange(len(text) + 1)]
        else:
            tree = json.loads(text)
            path, name, pattern = rng.choice(entries)
            node = tree
            for p in path:
                node = node[p]
            node[name] = rng.choice([{"value": value_for(rng, name, pattern)},
                                     value_for(rng, name, pattern), 1, None, [], {}])
            text = json.dumps(tree)
        files["scene.json"] = text.encode()
        arguments = ["scene.json"]
    else:  # include
        target = rng.choice(["scene.prm", "other.prm", "missing.prm", "sub/inner.prm", "/dev/null",
                             "sub", "../" + "x" * 300])
        files["main.prm"] = ("include %s\n" % target).encode()
        files["other.prm"] = b"include main.prm\n"
        files["sub/inner.prm"] = b"include ../main.prm\n"
        arguments = ["main.prm"] + base_arguments
    return arguments, files, kind


MESH_CORRUPTIONS = ["index past", "index negative", "cell twice", "cell twice rotated",
                    "cell twice reversed", "cell twisted", "hanging nodes", "overlap", "point twice", "off plane",
                    "coordinate", "version", "truncation", "none", "bom crlf"]
# corruptions a run may take (a truncation can leave a mesh whole); the others must be refused
MESH_VALID = ["none", "bom crlf"]
MESH_FORMATS = ["msh2", "msh41", "vtk", "ucd", "inp"]
COORDINATES = ["nan", "NaN", "inf", "-inf", "1e400", "-1e999", "abc", "1.5.2", "0x", None]


def structured_mesh(rng, dim):
    """Points and cells (node indices in the cyclic order of the file formats) of a grid
    of 2 to 3 cells a side, of cell size h."""
    n = [rng.randint(2, 3)] + [rng.randint(1, 3) for _ in range(dim - 1)]
    h = rng.choice([1.0, 0.25, 2.0 ** -10])  # (powers of 2: the children's nodes exact)
    index = {}
    points = []
    for k in range((n[2] + 1) if dim == 3 else 1):
        for j in range(n[1] + 1):
            for i in range(n[0] + 1):
                index[(i, j, k)] = len(points)
                points.append([i * h, j * h, k * h])
    ring = [(0, 0), (1, 0), (1, 1), (0, 1)]
    cells = []
    for k in range(n[2] if dim == 3 else 1):
        for j in range(n[1]):
            for i in range(n[0]):
                layers = [0, 1] if dim == 3 else [0]
                cells.append([index[(i + a, j + b, k + c)] for c in layers for a, b in ring])
    return points, cells, h


def corrupt_mesh(rng, dim, points, cells, h, corruption):
    """Apply @p corruption to the mesh (in place, on the node indices and positions)."""
    c = rng.randrange(len(cells))
    corners = 2 ** dim
    if corruption == "index past":
        cells[c][rng.randrange(corners)] = len(points) + rng.randint(0, 3)
    elif corruption == "index negative":
        cells[c][rng.randrange(corners)] = -rng.randint(2, 5)
    elif corruption.startswith("cell twice"):
        cell = list(cells[c])
        if corruption.endswith("rotated"):
            r = rng.randint(1, 3)
            cell = cell[r:4] + cell[:r] + (cell[4 + r:] + cell[4:4 + r] if dim == 3 else [])
        elif corruption.endswith("reversed"):
            cell = cell[4:] + cell[:4] if dim == 3 else cell[::-1]
        cells.insert(rng.randrange(len(cells) + 1), cell)
    elif corruption == "cell twisted":
        cell = cells[c]
        if dim == 2:
            cell[2], cell[3] = cell[3], cell[2]
        else:
            r = rng.randint(1, 3)
            cell[4:] = cell[4 + r:] + cell[4:4 + r]
    elif corruption == "hanging nodes":
        # cell c in 2^dim children, its neighbours whole
        low = points[cells[c][0]]
        known = {tuple(p): i for i, p in enumerate(points)}

        def node(a, b, e):
            x = (low[0] + a * h / 2, low[1] + b * h / 2, low[2] + e * h / 2)
            if x not in known:
                known[x] = len(points)
                points.append(list(x))
            return known[x]
        children = []
        for e in range(2 if dim == 3 else 1):
            for b in range(2):
                for a in range(2):
                    layers = [0, 1] if dim == 3 else [0]
                    children.append([node(a + da, b + db, e + dc) for dc in layers
                                     for da, db in [(0, 0), (1, 0), (1, 1), (0, 1)]])
        cells[c:c + 1] = children
    elif corruption == "overlap":
        shift = [h / 2, h / 3, h / 4 if dim == 3 else 0]
        moved = []
        for v in cells[c]:
            moved.append(len(points))
            points.append([points[v][d] + shift[d] for d in range(3)])
        cells.append(moved)
    elif corruption == "point twice":
        # a node of two cells or more, split: cell c gets a copy at the same point
        shared = [v for v in cells[c] if sum(v in other for other in cells) > 1]
        v = rng.choice(shared)
        points.append(list(points[v]))
        cells[c][cells[c].index(v)] = len(points) - 1
    elif corruption == "off plane":
        points[rng.choice(cells[c])][2] = rng.choice([0.1, -1e-3, 1e3]) * h


def write_mesh(rng, dim, points, cells, form, coordinate=None, version=None):
    """The text of the mesh in @p form; @p coordinate replaces (or, None, drops) one
    coordinate of a node; @p version is a Gmsh header's other version."""
    bad = rng.randrange(len(points)) if coordinate is not False else -1
    bad_axis = rng.randrange(3 if form in ("msh2", "msh41", "vtk", "ucd") or dim == 3 else 2)

    def xyz(i, axes=3):
        words = [repr(x) for x in points[i][:axes]]
        if i == bad:
            if coordinate is None:
                del words[bad_axis]
            else:
                words[bad_axis] = coordinate
        return words
    hexahedron = dim == 3
    if form in ("msh2", "msh41"):
        header = version or ("2.2" if form == "msh2" else "4.1")
        text = "$MeshFormat\n%s 0 8\n$EndMeshFormat\n" % header
        if form == "msh2":
            text += "$Nodes\n%d\n" % len(points)
            text += "".join("%d %s\n" % (i + 1, " ".join(xyz(i))) for i in range(len(points)))
            text += "$EndNodes\n$Elements\n%d\n" % len(cells)
            text += "".join("%d %d 2 0 1 %s\n" % (k + 1, 5 if hexahedron else 3,
                                                 " ".join(str(v + 1) for v in cell))
                            for k, cell in enumerate(cells))
            return text + "$EndElements\n"
        text += "$Entities\n0 0 %d %d\n" % ((0, 1) if hexahedron else (1, 0))
        text += ("1 0 0 0 1 1 1 0 0\n" if not hexahedron else "1 0 0 0 1 1 1 0 0\n")
        text += "$EndEntities\n"
        text += "$Nodes\n1 %d 1 %d\n%d 1 0 %d\n" % (len(points), len(points), dim, len(points))
        text += "".join("%d\n" % (i + 1) for i in range(len(points)))
        text += "".join("%s\n" % " ".join(xyz(i)) for i in range(len(points)))
        text += "$EndNodes\n$Elements\n1 %d 1 %d\n%d 1 %d %d\n" % (
            len(cells), len(cells), dim, 5 if hexahedron else 3, len(cells))
        text += "".join("%d %s\n" % (k + 1, " ".join(str(v + 1) for v in cell))
                        for k, cell in enumerate(cells))
        return text + "$EndElements\n"
    if form == "vtk":
        text = "# vtk DataFile Version 3.0\nfuzz\nASCII\nDATASET UNSTRUCTURED_GRID\n"
        text += "POINTS %d double\n" % len(points)
        text += "".join("%s\n" % " ".join(xyz(i)) for i in range(len(points)))
        text += "\nCELLS %d %d\n" % (len(cells), (1 + 2 ** dim) * len(cells))
        text += "".join("%d %s\n" % (len(cell), " ".join(str(v) for v in cell)) for cell in cells)
        text += "\nCELL_TYPES %d\n" % len(cells)
        return text + "".join("%d\n" % (12 if hexahedron else 9) for _ in cells)
    if form == "ucd":
        text = "# fuzz\n%d %d 0 0 0\n" % (len(points), len(cells))
        text += "".join("%d %s\n" % (i + 1, " ".join(xyz(i))) for i in range(len(points)))
        return text + "".join("%d 0 %s %s\n" % (k + 1, "hex" if hexahedron else "quad",
                                                 " ".join(str(v + 1) for v in cell))
                              for k, cell in enumerate(cells))
    # Abaqus
    axes = 3 if dim == 3 or any(p[2] != 0 for p in points) else 2
    text = "*HEADING\nfuzz\n*NODE\n"
    text += "".join("%d, %s\n" % (i + 1, ", ".join(xyz(i, axes))) for i in range(len(points)))
    text += "*ELEMENT, TYPE=%s, ELSET=EB1\n" % ("C3D8" if hexahedron else "CPE4")
    return text + "".join("%d, %s\n" % (k + 1, ", ".join(str(v + 1) for v in cell))
                          for k, cell in enumerate(cells))


def make_mesh_case(rng, source):
    """(arguments, {file name: bytes}, kind) of a mesh case; kind is 'mesh <corruption>'."""
    dim = rng.choice([2, 2, 3])
    corruption = rng.choice(MESH_CORRUPTIONS)
    if corruption == "off plane" and dim == 3:
        corruption = "none"
    form = rng.choice(MESH_FORMATS)
    if corruption == "version":
        form = rng.choice(["msh2", "msh41"])
    points, cells, h = structured_mesh(rng, dim)
    corrupt_mesh(rng, dim, points, cells, h, corruption)
    text = write_mesh(rng, dim, points, cells, form,
                      rng.choice(COORDINATES) if corruption == "coordinate" else False,
                      ({"msh2": "4.1", "msh41": "2.2"}[form] if corruption == "version" else None))
    data = text.encode()
    if corruption == "truncation":
        data = data[:rng.randrange(len(data))]
    elif corruption == "bom crlf":
        data = rng.choice([b"\xef\xbb\xbf", b""]) + data.replace(b"\n", b"\r\n")
    extension = {"msh2": "msh", "msh41": "msh"}.get(form, form)
    scene = "cube3d.prm" if dim == 3 else "hertz.prm"
    with open(os.path.join(source, "tests/scenes", scene)) as f:
        files = {"scene.prm": f.read().encode(), "mesh." + extension: data}
    arguments = ["scene.prm", "--set", "Geometry/Levels=2", "--set", "Solver/Max iterations=20",
                 "--set", "Solver/Threads=1", "--set", "Output/Directory=out",
                 "--set", "Output/Verbose=false", "--set", "Geometry/Shape=file",
                 "--set", "Geometry/Mesh file=mesh." + extension,
                 "--set", "Boundary conditions/Dirichlet boundary ids=0",
                 "--set", "Boundary conditions/Neumann boundary ids=",
                 "--set", "Boundary conditions/Contact boundary ids="]
    return arguments, files, "mesh " + corruption


CAUSES = ["data nan", "data huge", "data tiny", "thin cells", "gmsh tag", "abaqus surface",
          "floating part"]
DATA = {"Dirichlet values": "Data/Dirichlet values", "Traction": "Data/Traction",
        "Gap": "Data/Gap", "Body force": "Data/Body force"}


def two_blocks_msh(rng, tag, held_by):
    """A Gmsh 2.2 file of two unit squares side by side, joined (gap 0) or
    apart; the lower side of the left one has the physical tag 1 (its
    Dirichlet boundary), the right one's lower side @p held_by (or none), a
    line of the left one's upper side the physical tag @p tag, the rest 0."""
    apart = rng.choice([0.5, 2.0, 1e-3])
    x = [0.0, 1.0, 1.0 + apart, 2.0 + apart]
    points = [(x[0], 0), (x[1], 0), (x[1], 1), (x[0], 1), (x[2], 0), (x[3], 0), (x[3], 1),
              (x[2], 1)]
    lines = [(1, 1, 2), (tag, 3, 4)] + ([(held_by, 5, 6)] if held_by is not None else [])
    text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(points)
    text += "".join("%d %r %r 0\n" % (i + 1, p[0], p[1]) for i, p in enumerate(points))
    text += "$EndNodes\n$Elements\n%d\n" % (len(lines) + 2)
    text += "".join("%d 1 2 %d 1 %d %d\n" % (k + 1, t, a, b) for k, (t, a, b) in enumerate(lines))
    text += "%d 3 2 9 1 1 2 3 4\n%d 3 2 9 1 5 6 7 8\n$EndElements\n" % (len(lines) + 1,
                                                                       len(lines) + 2)
    return text


def make_cause_case(rng, source):
    """(arguments, {file name: bytes}, kind) of a cause case; kind is 'cause <what the line
    must name>'."""
    cause = rng.choice(CAUSES)
    scene = rng.choice(["square.prm", "cube3d.prm"])
    dim = 3 if scene == "cube3d.prm" else 2
    with open(os.path.join(source, "tests/scenes", scene)) as f:
        files = {"scene.prm": f.read().encode()}
    arguments = ["scene.prm", "--set", "Geometry/Levels=2", "--set", "Solver/Max iterations=20",
                 "--set", "Solver/Threads=1", "--set", "Output/Directory=out",
                 "--set", "Output/Verbose=false"]
    if cause == "thin cells":
        thickness = rng.choice(["5e-5", "2e-5", "1e-6", "1e-9"])
        arguments += ["--set", "Geometry/Box upper corner=" + ", ".join(["1"] * (dim - 1)
                                                                         + [thickness])]
        return arguments, files, "cause aspect ratio"
    if cause.startswith("data"):
        name = rng.choice(list(DATA)) if cause != "data tiny" else "Dirichlet values"
        n = 1 if name == "Gap" else dim
        if cause == "data nan":
            bad = rng.choice(["if(x > 0.5, sqrt(-1), 0)", "if(x > 0.5, 1/(x-x), 0)",
                              "log(x - 0.75)"])
        elif cause == "data huge":
            bad = rng.choice(["1e120", "-1e200", "1e300", "1e150*(1+x)"])
        else:
            bad = rng.choice(["-1e-300", "-1e-200", "-1e-170", "-1e-160*(1+x)"])
        values = ["0"] * n
        values[rng.randrange(n) if cause != "data tiny" else n - 1] = bad
        arguments += ["--set", "Data/%s=%s" % (name, "; ".join(values))]
        if cause == "data tiny":
            arguments += ["--set", "Data/Traction=" + "; ".join(["0"] * dim),
                          "--set", "Data/Gap=0"]
        return arguments, files, "cause " + DATA[name]
    # (the mesh files are 2D: the square's scene)
    with open(os.path.join(source, "tests/scenes/square.prm")) as f:
        files = {"scene.prm": f.read().encode()}
    arguments += ["--set", "Geometry/Shape=file"]
    if cause == "abaqus surface":
        name = rng.choice(["SS-1", "TOP", "S1X2", "SS+3", "SURF-12"])
        text = ("*HEADING\nfuzz\n*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n"
                "*ELEMENT, TYPE=CPE4, ELSET=EB1\n1, 1, 2, 3, 4\n"
                "*SURFACE, NAME=%s, TYPE=ELEMENT\n1, S1\n" % name)
        files["mesh.inp"] = text.encode()
        arguments += ["--set", "Geometry/Mesh file=mesh.inp",
                      "--set", "Boundary conditions/Dirichlet boundary ids=0",
                      "--set", "Boundary conditions/Neumann boundary ids=",
                      "--set", "Boundary conditions/Contact boundary ids="]
        return arguments, files, "cause *SURFACE NAME="
    if cause == "gmsh tag":
        tag = rng.choice([-1, -7, 256, 1000, 70000])
        held_by = 1
        named = "physical tag %d" % tag
    else:
        tag = 0
        held_by = rng.choice([None, 2])
        named = "parts that are not connected through faces"
    files["mesh.msh"] = two_blocks_msh(rng, tag, held_by).encode()
    arguments += ["--set", "Geometry/Mesh file=mesh.msh",
                  "--set", "Boundary conditions/Dirichlet boundary ids=1",
                  "--set", "Boundary conditions/Neumann boundary ids=0",
                  "--set", "Boundary conditions/Contact boundary ids="
                  + ("2" if held_by == 2 else "")]
    return arguments, files, "cause " + named


MPI_DIFFERENCES = ["same", "set", "option", "scene"]
MPI_SETTINGS = ["Geometry/Levels=1", "Solver/Type=active set", "Output/Directory=other",
                "Adaptivity/Steps=1", "Geometry/Dimension=3", "Solver/Cycle=V"]


def make_mpi_case(rng, source):
    """(arguments, files, kind) of an MPI case: the arguments of mpirun, with
    the executable as '{EXE}'; kind is 'mpi <difference>'."""
    difference = rng.choice(MPI_DIFFERENCES)
    with open(os.path.join(source, "tests/scenes", "square.prm")) as f:
        scene = f.read()
    files = {"scene.prm": scene.encode()}
    common = ["--set", "Geometry/Levels=2", "--set", "Solver/Max iterations=20",
              "--set", "Solver/Threads=1", "--set", "Output/Verbose=false"]
    a = ["scene.prm"] + common + ["--set", "Output/Directory=out"]
    b = list(a)
    if difference == "set":
        b += ["--set", rng.choice(MPI_SETTINGS)]
    elif difference == "option":
        b += [rng.choice(["--help", "--version", "--print-parameters"])]
    elif difference == "scene":
        lines = scene.splitlines()
        changed = [n for n, l in enumerate(lines) if l.strip().startswith("set ")]
        n = rng.choice(changed)
        lines[n] = lines[n] + " # changed" if rng.random() < 0.5 else "  set Levels = 1"
        files["scene_b.prm"] = ("\n".join(lines) + "\n").encode()
        b[0] = "scene_b.prm"
    if rng.random() < 0.5:
        a, b = b, a
    arguments = ["-np", "1", "{EXE}"] + a + [":", "-np", "1", "{EXE}"] + b
    return arguments, files, "mpi " + difference


def listing(directory):
    found = []
    for root, dirs, names in os.walk(directory):
        for n in dirs + names:
            found.append(os.path.relpath(os.path.join(root, n), directory))
    return sorted(found)


def run_case(number, arguments, files, kind):
    directory = "case_%04d" % number
    os.makedirs(directory)
    for name, content in files.items():
        os.makedirs(os.path.join(directory, os.path.dirname(name)), exist_ok=True)
        with open(os.path.join(directory, name), "wb") as f:
            f.write(content)
    before = listing(directory)
    # (a command line cannot hold a NUL byte)
    command = [EXE] + [a.replace("\x00", "\x01") for a in arguments]
    environment = None
    if kind.startswith("mpi "):
        command = [os.environ.get("MPIRUN", "mpirun"), "--oversubscribe"] + [
            EXE if a == "{EXE}" else a for a in arguments]
        environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                           OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    try:
        p = subprocess.run(command, cwd=directory, stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, timeout=TIMEOUT, stdin=subprocess.DEVNULL,
                           env=environment, start_new_session=True)
        rc, out, err = p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired:
        return number, "hang", command, "no end within %d s" % TIMEOUT
    if kind.startswith("mpi "):
        # (mpirun adds its own report of a process's exit code non-zero,
        # between lines of dashes, after the program's line)
        if b"\n-----" in err:
            err = err[:err.index(b"\n-----") + 1]
        if kind != "mpi same" and rc != 1:
            return number, "different inputs run", command, "exit code %d" % rc
        if kind == "mpi same" and rc not in (0, 2):
            return number, "same inputs refused", command, repr(err[:300])
    after = listing(directory)
    if kind.startswith("cause ") and rc >= 0:
        one = err.decode(errors="replace").strip()
        if rc != 1 or "\n" in one or kind[6:] not in one:
            return number, "cause not named", command, "exit code %d: %r" % (rc, err[:300])
    if kind.startswith("mesh ") and rc >= 0:
        valid = kind[5:] in MESH_VALID
        if valid and rc == 1:
            return number, "good mesh refused", command, repr(err[:300])
        if not valid and kind != "mesh truncation" and rc != 1:
            return number, "bad mesh accepted", command, "exit code %d" % rc
    lines = err.split(b"\n")[:-1] if err.endswith(b"\n") else err.split(b"\n")
    raw = [c for c in err[:-1] if c < 0x20 or c == 0x7f]
    leftovers = [n for n in after if re.search(r"\.staging-|\.lock$", n)]
    if rc < 0:
        return number, "crash", command, "signal %d" % -rc
    if rc not in (0, 1, 2):
        return number, "exit code", command, "exit code %d" % rc
    if rc == 1:
        if len(lines) != 1 or not lines[0].startswith(b"fosls-contact: error in ") or raw:
            return number, "error line", command, repr(err[:300])
        if after != before:
            return number, "files after an error", command, repr(sorted(set(after) - set(before)))
        return number, None, command, ""
    printing = any(a in ("--help", "-h", "--version", "--print-parameters") for a in arguments)
    if leftovers:
        return number, "files after an error", command, repr(leftovers)
    if rc == 2 and (len(lines) != 1 or b"not converged" not in lines[0]):
        return number, "error line", command, repr(err[:300])
    if rc == 0 and err:
        return number, "error line", command, repr(err[:300])
    if printing:
        if "--print-parameters" in arguments and not any(a in ("--help", "-h", "--version")
                                                         for a in arguments):
            try:
                json.loads(out)
            except ValueError:
                return number, "output", command, "--print-parameters printed no JSON"
        return number, None, command, ""
    if not any(n.endswith("summary.json") for n in after):
        return number, "output", command, "exit code %d without summary.json" % rc
    return number, None, command, ""


def main():
    global EXE
    arguments = sys.argv[1:]
    options = {"--cases": "600", "--mesh-cases": "150", "--cause-cases": "60",
               "--mpi-cases": "20", "--seed": "1", "--jobs": "2"}
    while len(arguments) > 2:
        value = arguments.pop()
        options[arguments.pop()] = value
    EXE, source = os.path.abspath(arguments[0]), arguments[1]
    rng = random.Random(int(options["--seed"]))
    entries = catalogue(EXE)
    cases = [make_case(rng, n, source, entries) for n in range(int(options["--cases"]))]
    mesh_rng = random.Random(int(options["--seed"]) + 1000)
    cases += [make_mesh_case(mesh_rng, source) for n in range(int(options["--mesh-cases"]))]
    cause_rng = random.Random(int(options["--seed"]) + 2000)
    cases += [make_cause_case(cause_rng, source) for n in range(int(options["--cause-cases"]))]
    mpi_rng = random.Random(int(options["--seed"]) + 3000)
    cases += [make_mpi_case(mpi_rng, source) for n in range(int(options["--mpi-cases"]))]
    failures = {k: [] for k in ["crash", "hang", "exit code", "error line",
                                "files after an error", "output", "bad mesh accepted",
                                "good mesh refused", "cause not named",
                                "different inputs run", "same inputs refused"]}
    with concurrent.futures.ThreadPoolExecutor(int(options["--jobs"])) as pool:
        for number, failure, command, detail in pool.map(lambda c: run_case(c[0], *c[1]),
                                                         enumerate(cases)):
            if failure:
                failures[failure].append((number, command, detail))
    print("cases: %d (seed %s), of them mesh cases: %s, cause cases: %s, MPI cases: %s"
          % (len(cases), options["--seed"], options["--mesh-cases"], options["--cause-cases"],
             options["--mpi-cases"]))
    for kind, found in failures.items():
        print("%s: %d" % (kind, len(found)))
    for kind, found in failures.items():
        for number, command, detail in found:
            print("FAILED case_%04d (%s): %s\n  cd case_%04d && %s" % (
                number, kind, detail, number,
                " ".join(repr(a) if re.search(r"[^\w./=-]", a) else a for a in command)))
    sys.exit(1 if any(failures.values()) else 0)


EXE = None
if __name__ == "__main__":
    main()
