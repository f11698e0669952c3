#!/usr/bin/env python3
"""The largest complementarity weight C_compl for which the functional is
positive definite, level by level: how far the limit moves between the level
the definiteness check is run on and finer levels.

For each scene and value of Geometry/Levels it runs the definiteness check
on the finest level (Solver/Definiteness check max dofs raised above its
DoFs) with C_compl = auto and prints the limit the program computes there
(DefinitenessCheck::limit_factor, a generalized eigenproblem on the contact
Schur complement; doc/method.md section 6), its move from the previous
level, and the ratio of the limit on the level that the default check
(at most 20,000 DoFs) runs on to the finest level's: the margin auto's
fraction 1/2 must cover. The solve itself is cut to one projected
Gauss-Seidel sweep (a step of the active set method would factorize the
whole matrix: a minute on the cube's level 5).

With --bisect, it also bisects C_compl between a weight the program accepts
and one it refuses (the check's smallest relative eigenvalue of the contact
Schur complement decides), as an independent check of the computed limit:
the bracket [accepted, refused] must hold it.

    bench/definiteness_limit.py [--exe build/fosls-contact]
        [--scene square.prm:3-9] [--scene hertz.prm:2-6] [--scene cube3d.prm:2-5]
        [--scene punch.prm:1-4] [--bisect] [--tolerance 2e-3]

After the first level of a scene, the bisection starts from the last
level's bracket: its refused weight is refused on the finer level too (the
spaces are nested), and its accepted weight lowered by 20% (halved until
accepted).
"""
import argparse
import re
import tempfile

from common import BIN, command, launch

LIMIT = re.compile(r"C_compl = auto: [0-9.eE+-]+ \([^)]*largest definite value "
                   r"([0-9.eE+-]+) on level (\d+)\)")
PATTERN = re.compile(r"Definiteness check on level (\d+)[^:]*: smallest relative eigenvalue of the "
                     r"contact Schur complement = (-?[0-9.eE+-]+)")


def arguments():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--exe", default=BIN)
    p.add_argument("--scene", action="append", metavar="FILE:FIRST-LAST",
                   help="a file of prm/ and its Geometry/Levels range "
                   "(default square.prm:3-9, hertz.prm:2-6, cube3d.prm:2-5, punch.prm:1-4)")
    p.add_argument("--bisect", action="store_true",
                   help="also bisect the limit between accepted and refused weights")
    p.add_argument("--low", type=float, default=0.2,
                   help="a weight accepted on the first level (default 0.2)")
    p.add_argument("--high", type=float, default=1.0,
                   help="a weight refused on the first level (default 1)")
    p.add_argument("--tolerance", type=float, default=2e-3,
                   help="width of the bracket (absolute)")
    a = p.parse_args()
    a.scene = a.scene or ["square.prm:3-9", "hertz.prm:2-6", "cube3d.prm:2-5",
                          "punch.prm:1-4"]
    return a


def finest_level_check(exe, scene, levels, out, settings=()):
    """The command of a run of prm/@p scene on @p levels levels with the
    definiteness check on its finest level and the solve cut to one
    projected Gauss-Seidel sweep, its output in @p out; @p settings: more
    "key=value" settings (also for bench/definiteness_cost.py)."""
    return command(scene, [f"Geometry/Levels={levels}",
                           "Solver/Definiteness check max dofs=100000000",
                           "Solver/Type=projected gauss seidel",
                           "Solver/Max iterations=1",
                           "Output/Write vtu=false",
                           f"Output/Directory={out}"] + list(settings), exe)


def smallest_eigenvalue(exe, scene, levels, weight):
    """The check's eigenvalue and level for C_compl = weight."""
    with tempfile.TemporaryDirectory() as out:
        run = launch(finest_level_check(exe, scene, levels, f"{out}/o",
                                        [f"Functional weights/C_compl={weight!r}"]),
                     capture_output=True, text=True)
    m = PATTERN.search(run.stdout + run.stderr)
    if not m:
        raise SystemExit(f"no definiteness check in the output of {scene} at {levels} levels, "
                         f"C_compl = {weight}:\n{run.stdout[-2000:]}{run.stderr[-2000:]}")
    return int(m.group(1)), float(m.group(2))


def limit(exe, scene, levels, low, high, tolerance):
    """[accepted, refused] bracket of the definiteness limit."""
    level, value = smallest_eigenvalue(exe, scene, levels, low)
    while value <= 0:  # refused: the limit is below low
        if low < 1e-3:
            raise SystemExit(f"{scene}, {levels} levels: even C_compl = {low} is refused")
        high, low = low, 0.5 * low
        level, value = smallest_eigenvalue(exe, scene, levels, low)
    if smallest_eigenvalue(exe, scene, levels, high)[1] > 0:
        raise SystemExit(f"{scene}, {levels} levels: C_compl = {high} is accepted")
    while high - low > tolerance:
        middle = 0.5 * (low + high)
        if smallest_eigenvalue(exe, scene, levels, middle)[1] > 0:
            low = middle
        else:
            high = middle
    return level, low, high


def computed_limit(exe, scene, levels, settings=()):
    """The limit that C_compl = auto computes on the finest level, and that level."""
    with tempfile.TemporaryDirectory() as out:
        run = launch(finest_level_check(exe, scene, levels, f"{out}/o",
                                        ["Functional weights/C_compl=auto"] + list(settings)),
                     capture_output=True, text=True)
    m = LIMIT.search(run.stdout)
    if not m:
        raise SystemExit(f"no computed limit in the output of {scene} at {levels} levels:\n"
                         f"{run.stdout[-2000:]}{run.stderr[-2000:]}")
    return float(m.group(1)), int(m.group(2))


def default_check_level(exe, scene, levels):
    """The level the default definiteness check (at most 20,000 DoFs) runs on."""
    with tempfile.TemporaryDirectory() as out:
        run = launch(finest_level_check(exe, scene, levels, f"{out}/o",
                                        ["Solver/Definiteness check max dofs=20000",
                                         "Functional weights/C_compl=auto"]),
                     capture_output=True, text=True)
    m = LIMIT.search(run.stdout)
    return int(m.group(2)) if m else None


def main():
    a = arguments()
    bracket = " C_compl accepted | refused |" if a.bisect else ""
    print("| scene | Geometry/Levels | computed limit |" + bracket +
          " move from the level before | default check's level | its limit / this limit |")
    print("|---|---|---|" + ("---|---|" if a.bisect else "") + "---|---|---|")
    for spec in a.scene:
        scene, _, span = spec.partition(":")
        first, _, last = span.partition("-")
        previous = None
        limits = {}
        low, high = a.low, a.high
        for levels in range(int(first), int(last) + 1):
            value, level = computed_limit(a.exe, scene, levels)
            limits[level] = value
            row = f"| {scene} | {levels} | {value:.4f} |"
            if a.bisect:
                # the limit only goes down under refinement (nested spaces):
                # the last level's refused weight is refused here too, and
                # the bracket starts below its accepted one
                _, low, high = limit(a.exe, scene, levels,
                                     a.low if previous is None else 0.8 * low,
                                     high, a.tolerance)
                row += f" {low:.4f} | {high:.4f} |"
            move = "" if previous is None else f"{(value - previous) / previous:+.1%}"
            checked = default_check_level(a.exe, scene, levels)
            ratio = (f"{limits[checked] / value:.3f}" if checked in limits else "")
            row += f" {move} | {checked} | {ratio} |"
            print(row, flush=True)
            previous = value


if __name__ == "__main__":
    main()
