# Processes started at the same time, without mpirun, all start: each runs
# as an isolated Open MPI singleton, and isolated singletons name their
# session directories the same, so that one process's clean-up in
# MPI_Finalize can remove the directory another's MPI_Init is creating (the
# start then fails: "A call to mkdir was unable to create the desired
# directory"; 1 in 160 runs, four at a time). The program creates none
# (app/main.cc).
# Four streams of 40 runs of the square with 2 levels, side by side: every
# run ends normally with nothing on stderr.
# ctest: cost=50
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, command_line, finish

R = Runner(sys.argv)
streams, runs = 4, 40
prm = os.path.join(R.source, "tests/scenes/square.prm")
failed, stderr_lines = 0, 0
processes = []
for s in range(streams):
    # one shell loop per stream: the runs of a stream one after the other
    commands = []
    for k in range(runs):
        directory = "stream_%d_run_%02d" % (s, k)
        commands.append(" ".join("'%s'" % c for c in command_line(
            R.exe, prm, ["Output/Directory=" + directory, "Output/Write vtu=false",
                         "Geometry/Levels=2"])) +
            " > %s.screen 2> %s.stderr || echo failed" % (directory, directory))
    processes.append(subprocess.Popen(["bash", "-c", "; ".join(commands)],
                                      stdout=subprocess.PIPE, text=True))
for p in processes:
    out, _ = p.communicate(timeout=600)
    failed += out.count("failed")
for name in os.listdir("."):
    if name.endswith(".stderr"):
        with open(name) as f:
            stderr_lines += len(f.read().splitlines())
print("--- %d streams of %d runs" % (streams, runs))
check(failed == 0, "every run exits with 0")
check(stderr_lines == 0, "nothing on stderr")
finish()
