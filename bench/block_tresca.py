#!/usr/bin/env python3
"""Where the Newton steps of prm/sliding_block.prm grow with the level
(doc/method.md section 7.7): the block's load path with Tresca's constant
bound s = 0.05 in place of Coulomb's, solved to the tolerance, so that no
fixed point is involved. Prints, per level 4 to --max-level, the Newton
steps of each load step (the iterations on the screen) and its residual
reduction per linear cycle (load_steps.csv's linear_rate); the runs'
output under bench/results/block_tresca/; about a minute on 7 levels.

    block_tresca.py [--max-level L] [--bin PATH]
"""
import argparse
import os

import friction
from common import BIN, RESULTS

friction.RES = os.path.join(RESULTS, "block_tresca")
SETTINGS = ["Friction/Law=Tresca", "Friction/Bound=0.05", "Solver/Stopping criterion=tolerance"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--max-level", type=int, default=7)
    ap.add_argument("--bin", default=BIN)
    args = ap.parse_args()
    os.makedirs(friction.RES, exist_ok=True)
    rows = ["| level | DoFs | Newton steps per load step | linear rate per load step |",
            "|---|---|---|---|"]
    for level in range(4, args.max_level + 1):
        r = friction.run(args.bin, "sliding_block.prm",
                         SETTINGS + ["Geometry/Levels=%d" % level], "level_%d" % level)
        rows.append("| %d | %d | %s | %s |" % (
            level, r["summary"]["dofs"], ", ".join(map(str, r["steps"])),
            ", ".join("%.2g" % step["linear_rate"] for step in r["summary"]["load_steps"])))
    print("\n".join(rows))


if __name__ == "__main__":
    main()
