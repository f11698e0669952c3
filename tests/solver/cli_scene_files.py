# Scene files (README, "Command line"): a scene file that cannot be read is
# reported with its real cause (a FIFO, an unreadable file: not "does not
# exist" or "not found"); a garbage file gets one line without raw control
# bytes (which would reach the terminal); a JSON scene written by
# --print-parameters is read back and gives the run of the .prm scene; a
# scene that includes itself is one line (not thousands of nested reads),
# includes are relative to the including file.
# ctest: timeout=120
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, execute, finish, one_error_line

exe, source = sys.argv[1], sys.argv[2]
scene = os.path.join(source, "tests/scenes/square.prm")


def refused(label, arguments, *parts, env=None, prefix=()):
    rc, out, err = execute(list(prefix) + [exe] + arguments, env=env, timeout=60)
    check(rc == 1 and one_error_line(err, *parts),
          label + ": exit code 1, one line naming " + ", ".join(repr(p) for p in parts))
    return err


os.mkfifo("fifo.prm")
refused("a FIFO", ["fifo.prm"], "'fifo.prm' is a FIFO")
os.symlink("nowhere.prm", "dangling.prm")
refused("a dangling link", ["dangling.prm"], "symbolic link to a file that does not exist")
with open("plain.prm", "w") as f:
    f.write("# a scene\n")
refused("a path through a file", ["plain.prm/x.prm"], "a component of its path is not a directory")
# permission bits do not stop root: read the file as the user nobody
os.chmod("plain.prm", 0)
os.chmod(".", 0o755)
if os.geteuid() == 0:
    prefix = ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"]
else:
    prefix = []
refused("an unreadable file", [os.path.abspath("plain.prm")], "cannot be read: permission denied",
        prefix=prefix)

with open("garbage.prm", "wb") as f:
    f.write(b"\x01\x1b[31mset\x00\x07 \xff\xfe = 1\n")
err = refused("a garbage file", ["garbage.prm"], "garbage.prm:1: cannot read the line")
raw = [c for c in err[:-1] if ord(c) < 0x20 or ord(c) == 0x7f]
check(err.endswith("\n") and raw == [] and "\\x1b" in err,
      "a garbage file: no raw control bytes in the line (escaped as \\xNN)")
refused("a control character in --set", [scene, "--set", "Output/Directory=a\nb"],
        "control character", "a\\nb")

with open("self.prm", "w") as f:
    f.write("include self.prm\n")
refused("a file that includes itself", ["self.prm"], "self.prm:1:", "the file includes itself")
os.mkdir("sub")
with open("sub/inner.prm", "w") as f:
    f.write("include ../outer.prm\n")
with open("outer.prm", "w") as f:
    f.write("subsection Geometry\n  include sub/inner.prm\nend\n")
refused("an include cycle", ["outer.prm"], "sub/inner.prm:1:", "outer.prm' includes itself")
with open("sub/square.prm", "w") as f:
    f.write("include %s\nsubsection Geometry\n  set Level = 2\nend\n"
            % os.path.relpath(scene, "sub"))
refused("an include relative to the file, then a misspelt name", ["sub/square.prm"],
        "sub/square.prm:3:", "did you mean 'Geometry/Levels'?")

# JSON both ways
rc, out, err = execute([exe, "--print-parameters", scene, "--set", "Geometry/Levels=3",
                        "--set", "Output/Directory=from_json", "--set", "Output/Verbose=false"])
with open("scene.json", "w") as f:
    f.write(out)
rc_json, out, err = execute([exe, "scene.json"])
rc_prm, out, err_prm = execute([exe, scene, "--set", "Geometry/Levels=3",
                                "--set", "Output/Directory=from_prm",
                                "--set", "Output/Verbose=false"])
keys = ["dofs", "iterations", "functional", "contact_force", "active"]
try:
    results = [json.load(open(d + "/summary.json")) for d in ("from_json", "from_prm")]
    same = all(results[0][k] == results[1][k] for k in keys)
except (OSError, ValueError, KeyError):
    same = False
check(rc_json == 0 and err == "" and rc_prm == 0 and same,
      "the JSON of --print-parameters runs the scene: the same summary as the .prm")
bad = json.loads(open("scene.json").read() or "{}")
bad.setdefault("Solver", {})["Cycle"] = {"value": "X"}
with open("bad.json", "w") as f:
    json.dump(bad, f)
refused("an invalid value in a JSON scene", ["bad.json"],
        "bad.json (Solver/Cycle)", "valid values: 'V', 'W', 'F'")
finish()
