"""What the bench scripts share: the repository's paths, the program and how
to start it, and the templates of the reports they write.

    from common import ROOT, BIN, run, load_template

BIN is build/fosls-contact, or the program that the environment variable
FOSLS_CONTACT_BIN names (another build, e.g. that of a git worktree
without one of its own).

A scene is named by its file in prm/; settings are "Subsection/Name=value"
strings or a dict {"Subsection/Name": value}, each given to the program as
one --set, in their order.
"""
import json
import os
import re
import shutil
import string
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.join(ROOT, "build")
BIN = os.path.abspath(os.environ.get("FOSLS_CONTACT_BIN")
                      or os.path.join(BUILD, "fosls-contact"))
RESULTS = os.path.join(ROOT, "bench", "results")
MPIRUN = shutil.which("mpirun") or "mpirun"
# Open MPI refuses to start as root (containers, CI) without these two
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def scene_file(scene):
    """The path of the scene prm/@p scene."""
    return os.path.join(ROOT, "prm", scene)


def command(scene, settings=(), binary=None, processes=1):
    """The command line of a run of @p binary (default: build/fosls-contact)
    on prm/@p scene with @p settings, on @p processes MPI processes."""
    if isinstance(settings, dict):
        settings = [f"{k}={v}" for k, v in settings.items()]
    cmd = [binary or BIN, scene_file(scene)]
    for s in settings:
        cmd += ["--set", s]
    if processes > 1:
        cmd = [MPIRUN, "--oversubscribe", "-np", str(processes)] + cmd
    return cmd


def launch(cmd, threads=None, **kwargs):
    """subprocess.run(@p cmd, **kwargs) in the environment ENV, with
    DEAL_II_NUM_THREADS = @p threads if given."""
    env = dict(ENV, DEAL_II_NUM_THREADS=str(threads)) if threads else ENV
    return subprocess.run(cmd, env=env, **kwargs)


def run(scene, settings, out, binary=None, processes=1, threads=None,
        allow_not_converged=False):
    """One run of @p binary on prm/@p scene into the output directory @p out
    (Output/Directory, then @p settings): its summary.json, with the wall
    time of the whole run as "wall_s". A run that fails ends the script
    with its command and stderr; so does one that does not converge (exit
    code 2) unless @p allow_not_converged."""
    if isinstance(settings, dict):
        settings = [f"{k}={v}" for k, v in settings.items()]
    cmd = command(scene, [f"Output/Directory={out}"] + list(settings), binary, processes)
    start = time.time()
    p = launch(cmd, threads, capture_output=True, text=True)
    wall = time.time() - start
    if p.returncode != 0 and not (allow_not_converged and p.returncode == 2):
        sys.exit(f"failed: {' '.join(cmd)}\n{p.stderr}")
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    summary["wall_s"] = wall
    return summary


def levels(text):
    """"6-10" or "6,7,8" -> a sorted list of levels (the --levels options)."""
    if "-" in text:
        first, last = (int(x) for x in text.split("-"))
        return list(range(first, last + 1))
    return sorted(int(x) for x in text.split(","))


def load_template(path):
    """The blocks of the report template @p path: {name: string.Template}. A
    block is the text between its line `@@ name` and the next such line,
    without the last line end (so a block that ends a paragraph ends with an
    empty line, and a block meant to be put inside a sentence runs up to
    the next `@@` line)."""
    blocks = {}
    with open(path) as f:
        parts = re.split(r"^@@ (\w+)\n", f.read(), flags=re.M)
    for name, text in zip(parts[1::2], parts[2::2]):
        blocks[name] = string.Template(text[:-1] if text.endswith("\n") else text)
    return blocks
