#!/usr/bin/env python3
"""Where does the augmented functional stop being positive definite?

Runs the square scene (prm/square.prm) for several complementarity weights
C_compl and levels and prints the smallest relative eigenvalue of the contact
Schur complement that the program's definiteness check computes (negative:
the run is refused). Usage: bench/definiteness.py [path/to/fosls-contact]
"""
import re
import sys
import tempfile

from common import BIN, command, launch

exe = sys.argv[1] if len(sys.argv) > 1 else BIN
weights = ["0.05", "0.1", "0.2", "0.3", "0.5", "1", "10"]
levels = [2, 3, 4, 5, 6]
pattern = re.compile(r"Schur complement(?: =|\s+)\s*(-?[0-9.eE+-]+)")

print("| C_compl | " + " | ".join(f"level {l}" for l in levels) + " |")
print("|---|" + "---|" * len(levels))
for c in weights:
    row = []
    for l in levels:
        with tempfile.TemporaryDirectory() as out:
            run = launch(command("square.prm", [f"Functional weights/C_compl={c}",
                                                f"Geometry/Levels={l}",
                                                "Solver/Type=active set",
                                                "Output/Write vtu=false",
                                                f"Output/Directory={out}/o"], exe),
                         capture_output=True, text=True)
        text = run.stdout + run.stderr
        m = pattern.search(text)
        value = float(m.group(1)) if m else float("nan")
        row.append(f"{value:.2e}" + ("" if run.returncode == 0 else " (refused)"))
    print(f"| {c} | " + " | ".join(row) + " |")
