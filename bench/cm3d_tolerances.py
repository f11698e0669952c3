#!/usr/bin/env python3
"""The tolerances of prm/cattaneo_mindlin_3d_fine.prm (Tresca problems to
Solver/Tolerance = 1e-6, the Coulomb fixed point to Fixed point tolerance =
1e-4) against the defaults (1e-8, 1e-6), on the coarser mesh of
prm/cattaneo_mindlin_3d.prm (2 levels), where both run in about a minute
and a half: each step's stick disc (the program's Cattaneo-Mindlin line),
Tresca problems, normal and tangential force, and the largest relative
difference of the forces. Prints the table (the runs' output under
bench/results/cm3d_tolerances/).

    cm3d_tolerances.py [--bin PATH]
"""
import argparse
import os
import re

import friction
from common import BIN, RESULTS

friction.RES = os.path.join(RESULTS, "cm3d_tolerances")
SETTINGS = {"defaults (1e-8, 1e-6)": [],
            "the fine scene's (1e-6, 1e-4)": ["Solver/Tolerance=1e-6",
                                               "Friction/Fixed point tolerance=1e-4"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--bin", default=BIN)
    args = ap.parse_args()
    os.makedirs(friction.RES, exist_ok=True)
    runs = {name: friction.run(args.bin, "cattaneo_mindlin_3d.prm", settings,
                               "default" if not settings else "loose")
            for name, settings in SETTINGS.items()}
    rows = ["| tolerances | step | Tresca problems | normal force | tangential force "
            "| stick zone along Q | wall time of the run [s] |", "|---|---|---|---|---|---|---|"]
    for name, r in runs.items():
        problems = re.findall(r"Friction \(Coulomb\): .*, (\d+) Tresca problems", r["screen"])
        zones = ["(pressed)" if float(m.group(1)) <= 1e-6 else
                 "%s to %s" % (m.group(3), m.group(4)) if m.group(3) else "no vertex sticks"
                 for m in friction.CATTANEO_MINDLIN.finditer(r["screen"])]
        for k, step in enumerate(r["summary"]["load_steps"]):
            rows.append("| %s | %d | %d | %.10g | %.10g | %s | %s |" % (
                name if k == 0 else "", k + 1, int(problems[k]),
                step["normal_force"], step["tangential_force"],
                zones[k] if k < len(zones) else "", "%.1f" % r["wall"] if k == 0 else ""))
    a, b = (r["summary"]["load_steps"] for r in runs.values())
    normal = max(abs(s["normal_force"] - t["normal_force"]) / s["normal_force"]
                 for s, t in zip(a, b))
    tangential = max(abs(s["tangential_force"] - t["tangential_force"]) / s["tangential_force"]
                     for s, t in zip(a[1:], b[1:]))
    print("\n".join(rows))
    print("\nlargest relative difference: normal force %.1e, tangential force %.1e (pulled steps)"
          % (normal, tangential))


if __name__ == "__main__":
    main()
