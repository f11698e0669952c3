#!/usr/bin/env python3
"""What the definiteness check costs on the cube (prm/cube3d.prm), level by
level, with the check on the finest level (Solver/Definiteness check max
dofs raised above its DoFs): the check's time (summary.json's
time_sections_s), the fastest of --runs runs. With --base-exe, the same for
another binary (a build of another revision), run alternately, and the
ratio base / this; a base run cut off by --timeout is shown as "> T". The
solve is cut to one projected Gauss-Seidel sweep.

    bench/definiteness_cost.py [--exe build/fosls-contact] [--base-exe PATH]
        [--levels 3-5] [--runs 2] [--timeout 120]
"""
import argparse
import json
import subprocess
import tempfile
from pathlib import Path

from common import BIN, launch
from definiteness_limit import finest_level_check


def arguments():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--exe", default=BIN)
    p.add_argument("--base-exe", help="another binary, run alternately with --exe")
    p.add_argument("--levels", default="3-5", metavar="FIRST-LAST")
    p.add_argument("--runs", type=int, default=2)
    p.add_argument("--timeout", type=float, default=120.,
                   help="seconds after which a run is cut off (default 120)")
    return p.parse_args()


def check_seconds(exe, levels, timeout):
    """(DoFs, the check's seconds) of one run, or (None, None) if cut off."""
    with tempfile.TemporaryDirectory() as out:
        command = finest_level_check(exe, "cube3d.prm", levels, f"{out}/o")
        try:
            launch(command, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return None, None
        summary = Path(out) / "o" / "summary.json"
        if not summary.exists():
            raise SystemExit(f"no summary.json from {exe} at {levels} levels")
        s = json.loads(summary.read_text())
        return s["dofs"], s["time_sections_s"]["Definiteness check"]


def main():
    a = arguments()
    first, _, last = a.levels.partition("-")
    binaries = {"this": a.exe}
    if a.base_exe:
        binaries["base"] = a.base_exe
    print("| level | DoFs | check s | " + ("base check s | base / this |" if a.base_exe else ""))
    print("|---|---|---|" + ("---|---|" if a.base_exe else ""))
    for levels in range(int(first), int(last) + 1):
        best, dofs = {}, None
        for _ in range(a.runs):
            for name, exe in binaries.items():
                if best.get(name, 0.) is None:
                    continue  # cut off before: not again
                n, seconds = check_seconds(exe, levels, a.timeout)
                dofs = n or dofs
                best[name] = None if seconds is None else min(seconds, best.get(name) or seconds)
        this, base = best["this"], best.get("base")
        row = f"| {levels} | {dofs} | " + (f"{this:.2f} |" if this is not None
                                           else f"> {a.timeout:.0f} |")
        if a.base_exe:
            row += f" {base:.2f} |" if base is not None else f" > {a.timeout:.0f} |"
            if this is not None and base is not None:
                row += f" {base / this:.2f} |"
            elif this is not None:
                row += f" > {a.timeout / this:.1f} |"
            else:
                row += " |"
        print(row, flush=True)


if __name__ == "__main__":
    main()
