# A closed standard output (`fosls-contact scene.prm | head -1`) does not
# kill the run: it goes on without its screen output, writes its files and
# exits with 0 (SIGPIPE's default action would kill it, exit code -13,
# without files).
# Twice: the reading end closed before the start (the first line fails),
# and after the first line, as `head -1` does.
# ctest: timeout=120
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import check, finish

exe, source = sys.argv[1], sys.argv[2]
scene = os.path.join(source, "tests/scenes/square.prm")


def command(directory):
    return [exe, scene, "--set", "Output/Directory=" + directory, "--set", "Geometry/Levels=5"]


read_end, write_end = os.pipe()
os.close(read_end)
p = subprocess.run(command("closed"), stdout=write_end, stderr=subprocess.PIPE)
os.close(write_end)
print("--- stdout closed before the start: exit code %d" % p.returncode)
check(p.returncode == 0 and p.stderr == b"", "closed before the start: exit code 0, nothing on stderr")
check(os.path.isfile("closed/summary.json"), "closed before the start: the files are written")

p = subprocess.Popen(command("head"), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
first = p.stdout.readline()
p.stdout.close()
err = p.stderr.read()
p.wait()
print("--- stdout closed after the first line: exit code %d" % p.returncode)
check(first.startswith(b"Scene:"), "the first line is the scene's")
check(p.returncode == 0 and err == b"", "closed after the first line: exit code 0, nothing on stderr")
check(os.path.isfile("head/summary.json"), "closed after the first line: the files are written")
finish()
