#!/usr/bin/env python3
# A contact zone the mesh does not resolve is named (ContactZone::resolved):
# fewer than 3 contact vertices in contact in 2D, 5 in 3D, give a warning
# line on the screen and "resolved": false in summary.json's contact_zone;
# the run still ends normally (exit code 0). Cases: the square of
# prm/square.prm (6 levels) under a wedge obstacle whose tip touches the
# vertex at x = 0.5 only (gap 0.0095 + |x - 0.5| with the push 0.01: u.n = g
# there and a contact force of exactly 0, since one vertex carries no
# traction of its own), and a blunter wedge (0.005 + |x - 0.5| / 2: one
# vertex, a force of 0.0028); the cube of prm/cube3d.prm (3 levels) under
# a pyramid touching one vertex. Resolved and without a warning: the square
# and the cube on their flat foundations.
# ctest: sanitize
import os
import sys
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish

R = Runner(sys.argv)
CASES = [("square, wedge touching one vertex", "prm/square.prm",
          ["Data/Gap=0.0095 + abs(x - 0.5)"], False),
         ("square, blunt wedge", "prm/square.prm", ["Data/Gap=0.005 + 0.5*abs(x - 0.5)"], False),
         ("cube, pyramid touching one vertex", "prm/cube3d.prm",
          ["Data/Gap=0.0095 + abs(x - 0.5) + abs(y - 0.5)"], False),
         ("square, flat foundation", "prm/square.prm", [], True),
         ("cube, flat foundation", "prm/cube3d.prm", [], True)]
for label, prm, settings, resolved in CASES:
    run = R.run(prm, settings, label.split(",")[0] + ("_flat" if resolved else "_point"))
    zone = run["contact_zone"] or {}
    warned = [l for l in run.screen.splitlines() if l.startswith("Warning: only")]
    print("%s: %s vertices in contact" % (label, zone.get("vertices_in_contact")))
    check(run.ok(), label + ": exit code 0, nothing on stderr")
    if resolved:
        check(zone.get("resolved") is True and not warned,
              label + ": resolved, no warning")
    else:
        check(zone.get("resolved") is False and len(warned) == 1,
              label + ": one warning line, contact_zone.resolved false")
finish()
