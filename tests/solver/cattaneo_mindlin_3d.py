#!/usr/bin/env python3
# prm/cattaneo_mindlin_3d.prm, the scene of Cattaneo and Mindlin's problem
# in 3D (a rigid sphere pressed into an incompressible half-space, then
# pulled sideways), pressed only and without friction (its Coulomb load
# path takes minutes: bench/friction.py runs it, doc/friction_results.md):
#  - prm/meshes/make_cattaneo_mindlin_3d.py writes the shipped meshes (of
#    prm/cattaneo_mindlin_3d.prm and, with --finest 64, of
#    prm/cattaneo_mindlin_3d_fine.prm), with --core K cells of the
#    finest width from the center out (--finest 32 --core 4: the nodes
#    0, 1/32, ..., 1/8, 1/4, 1/2 in each direction), and refuses a --core
#    that is not a power of 2 from 2 to N/2;
#  - the half-space's far field on the box's top and sides carries the
#    pressure of Hertz's sphere: on 2 levels, where the contact radius
#    (Hertz's a = 0.080) spans 2.5 vertex spacings (1/32), the normal force
#    is the scene's P to 3% (measured: 2.6% low) and the pressure's
#    relative L2 error on the contact boundary at most 0.25 (measured:
#    0.23);
#  - J never increases, every iterate feasible.
# ctest: timeout=300 cost=10
import filecmp
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, check_monotone_feasible, finish, rounded

R = Runner(sys.argv)
for name, options in [("cattaneo_mindlin_3d.msh", []),
                      ("cattaneo_mindlin_3d_fine.msh", ["--finest", "64"])]:
    generated = os.path.join(os.getcwd(), name)
    subprocess.run([sys.executable, os.path.join(R.source, "prm", "meshes",
                                                 "make_cattaneo_mindlin_3d.py")] + options +
                   [generated], check=True)
    check(filecmp.cmp(generated, os.path.join(R.source, "prm", "meshes", name), shallow=False),
          "prm/meshes/make_cattaneo_mindlin_3d.py %swrites prm/meshes/%s" % (
              " ".join(options) + " " if options else "", name))

core = os.path.join(os.getcwd(), "core.msh")
generator = [sys.executable, os.path.join(R.source, "prm", "meshes", "make_cattaneo_mindlin_3d.py")]
subprocess.run(generator + ["--finest", "32", "--core", "4", core], check=True)
with open(core) as f:
    lines = f.read().split("$Nodes\n")[1].split("$EndNodes")[0].split("\n")[1:-1]
xs = sorted({round(float(line.split()[1]) * 32) for line in lines})
check(xs == [-16, -8, -4, -3, -2, -1, 0, 1, 2, 3, 4, 8, 16],
      "--finest 32 --core 4: the nodes' x in 1/32: %s" % xs)
for bad in ["3", "32", "1"]:
    refused = subprocess.run(generator + ["--finest", "32", "--core", bad, core],
                             capture_output=True, text=True)
    check(refused.returncode != 0 and "--core must be a power of 2" in refused.stderr,
          "--core %s is refused" % bad)

P = 0.001365
run = R.run("prm/cattaneo_mindlin_3d.prm",
            ["Friction/Law=none", "Data/Load steps=", "Data/Constants=P=0.001365, Q=0, f=0.3, "
             "R=2, mu=1"], "pressed")
check(run.returncode == 0, "the pressed sphere runs")
hertz = run["hertz"]
force = run["contact_force"][2]
error = hertz["pressure_error_boundary"]
print("pressed: %d DoFs, normal force / P = %s, Hertz's a = %s, pressure error %s "
      "(relative L2 on the contact boundary)" % (
          run["dofs"], rounded(force / P, 4), rounded(hertz["a"], 3), rounded(error, 2)))
check(abs(force / P - 1) <= 0.03, "the normal force is P (to 3%)")
check(error <= 0.25, "the pressure error is at most 0.25")
check_monotone_feasible(run, "pressed")
finish()
