# The command line (README, "Command line"): --help names every option and
# the exit codes; --version prints the program version, the git revision it
# was built from (or "unknown" outside a git checkout) and the deal.II
# version, which summary.json records too; a verbose run prints one line
# with its time as each phase ends (set-up, assembly, checks, initial
# guess, solver set-up, solve, output), a quiet one none; --print-parameters
# with a scene and --set prints the scene's values, not the defaults.
# ctest: timeout=120
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, execute, finish

exe, source = sys.argv[1], sys.argv[2]
scene = os.path.join(source, "tests/scenes/square.prm")

rc, out, err = execute([exe, "--help"])
check(rc == 0 and err == "", "--help: exit code 0, nothing on stderr")
for option in ["--set", "--print-parameters", "--help", "--version", "Exit codes:",
               "  0  ", "  1  ", "  2  ", "Solver/Threads"]:
    check(option in out, "--help mentions '%s'" % option.strip())

rc, out, err = execute([exe, "--version"])
lines = out.splitlines()
check(rc == 0 and err == "" and len(lines) == 3, "--version: exit code 0, three lines")
version = re.fullmatch(r"fosls-contact (\d+\.\d+\.\d+)", lines[0]) if lines else None
revision = re.fullmatch(r"git revision (\S+)", lines[1]) if len(lines) > 1 else None
deal_ii = re.fullmatch(r"deal\.II (\d+\.\d+\.\d+)", lines[2]) if len(lines) > 2 else None
check(bool(version and revision and deal_ii),
      "--version: 'fosls-contact X.Y.Z', 'git revision R', 'deal.II X.Y.Z'")

rc, out, err = execute([exe, scene, "--set", "Output/Directory=verbose",
                        "--set", "Geometry/Levels=3"])
check(rc == 0 and err == "", "verbose run: exit code 0, nothing on stderr")
with open("verbose/summary.json") as f:
    summary = json.load(f)
check(revision is not None and summary.get("git_revision") == revision.group(1)
      and deal_ii is not None and summary.get("deal_ii_version") == deal_ii.group(1),
      "summary.json: git_revision and deal_ii_version as --version prints them")
phases = [re.sub(r" \.\.\. \d+\.\d\d s$", "", l) for l in out.splitlines()
          if re.search(r" \.\.\. \d+\.\d\d s$", l)]
print("phases: " + "; ".join(phases))
check(phases == ["Setup: mesh, DoFs, levels", "Functional weights", "Assembly",
                 "Checks: data, rigid motions, definiteness", "Initial guess",
                 "Setup: solver", "Solve", "Output"],
      "verbose run: one line per phase, in order")
rc, out, err = execute([exe, scene, "--set", "Output/Directory=quiet",
                        "--set", "Geometry/Levels=3", "--set", "Output/Verbose=false"])
check(rc == 0 and out == "", "Output/Verbose = false: no phase lines (nothing on stdout)")

rc, out, err = execute([exe, "--print-parameters", scene, "--set", "Geometry/Levels=2"])
parameters = json.loads(out) if rc == 0 else {}
check(parameters.get("Geometry", {}).get("Levels", {}).get("value") == "2"
      and parameters.get("Boundary conditions", {}).get("Contact boundary ids", {})
      .get("value") == "2",
      "--print-parameters SCENE --set: the scene's values with the --set")
finish()
