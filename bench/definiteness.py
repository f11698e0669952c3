#!/usr/bin/env python3
"""Where does the augmented functional stop being positive definite?

Runs the square scene (prm/square.prm) for several complementarity weights
C_compl and levels and prints the smallest relative eigenvalue of the contact
Schur complement that the program's definiteness check computes (negative:
the run is refused). Usage: bench/definiteness.py [path/to/fosls-contact]
"""
import re
import subprocess
import sys
import tempfile
from pathlib import Path

root = Path(__file__).resolve().parent.parent
exe = sys.argv[1] if len(sys.argv) > 1 else str(root / "build" / "fosls-contact")
weights = ["0.05", "0.1", "0.2", "0.3", "0.5", "1", "10"]
levels = [2, 3, 4, 5, 6]
pattern = re.compile(r"Schur complement(?: =|\s+)\s*(-?[0-9.eE+-]+)")

print("| C_compl | " + " | ".join(f"level {l}" for l in levels) + " |")
print("|---|" + "---|" * len(levels))
for c in weights:
    row = []
    for l in levels:
        with tempfile.TemporaryDirectory() as out:
            run = subprocess.run(
                [exe, str(root / "prm" / "square.prm"),
                 "--set", f"Functional weights/C_compl={c}",
                 "--set", f"Geometry/Levels={l}",
                 "--set", "Solver/Type=active set",
                 "--set", "Output/Write vtu=false",
                 "--set", f"Output/Directory={out}/o"],
                capture_output=True, text=True)
        text = run.stdout + run.stderr
        m = pattern.search(text)
        value = float(m.group(1)) if m else float("nan")
        row.append(f"{value:.2e}" + ("" if run.returncode == 0 else " (refused)"))
    print(f"| {c} | " + " | ".join(row) + " |")
