# Units: the program solves a dimensionless problem (x/L, u/L, sigma/S with
# L the largest side of the coarse mesh's box and S = mu, doc/method.md
# section 1), so one physical problem written in any consistent units gives
# the same answer, converted. Three scenes (the square, the half disc of
# prm/hertz.prm and the 3D Hertz block of prm/ball3d.prm, all with
# nu = 0.3) are run in
#   (a) mu = 1, the body's size 1 (E = 2.6);
#   (b) SI: steel E = 210e9 Pa, a body of 0.1 m;
#   (c) mm/N/MPa: E = 210000 MPa, a body of 100 mm;
#   (d) a body 1000 times larger with the same strain, E = 2.6;
#   (e), (f) E times 1e9 with lengths times 1e-3, and E times 1e-9 with
#   lengths times 1e3;
# and, on 2 MPI processes, (a) against (b) (2D and 3D). Every push, gap and radius
# scales with the body. After conversion (displacements / s, stresses / m
# with s and m the length and modulus factors, force / (m s^(dim-1)),
# J / s^dim), J and its parts, the contact force, u_n and sigma_nn at every
# contact vertex (contact.csv), the largest |u| and von Mises stress
# (summary.json) agree with (a) to 1e-8 relative, with the same active set
# and the same iterations (one more or less where a run ends at its
# round-off floor).
# Also in SI units: nu = 0.4999, 0.49999999 and 0.5 (lambda = inf) on the
# square, stable and converged, with forces approaching the incompressible
# one; and gravity (rho g = 7850 * 9.81 N/m^3, no push) on the 0.1 m steel
# square against the same dimensionless problem in unit scale.
# ctest: timeout=600 mpirun cost=20
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fosls_runs import Runner, check, finish, relative_difference, rounded

R = Runner(sys.argv)
NU = 0.3
E_UNIT = 2. * (1. + NU)  # mu = 1


def square(s):
    return ["Geometry/Box upper corner=%r, %r" % (s, s),
            "Data/Dirichlet values=0; %r" % (-0.01 * s),
            "Geometry/Levels=5"]


def half_disc(s):
    return ["Geometry/Radius=%r" % (0.5 * s), "Geometry/Center=0, %r" % s,
            "Data/Constants=push=%r, R=%r, c=%r" % (0.01 * s, 0.5 * s, s),
            "Data/Gap=y - (c - R)", "Geometry/Levels=3"]


def ball(s):
    return ["Geometry/Box lower corner=%r, %r, 0" % (-s, -s),
            "Geometry/Box upper corner=%r, %r, %r" % (s, s, s),
            "Data/Constants=push=%r, R=%r" % (0.05 * s, 2. * s),
            "Geometry/Levels=3"]


SCENES = [("square", "prm/square.prm", square, 2),
          ("half disc", "prm/hertz.prm", half_disc, 2),
          ("3D Hertz block", "prm/ball3d.prm", ball, 3)]
# (label, length factor s, Young's modulus)
SYSTEMS = [("(b) SI", 0.1, 210e9), ("(c) mm/N/MPa", 100., 210000.),
           ("(d) 1000 x larger", 1000., E_UNIT),
           ("(e) E x 1e9, lengths x 1e-3", 1e-3, E_UNIT * 1e9),
           ("(f) E x 1e-9, lengths x 1e3", 1e3, E_UNIT * 1e-9)]


def material(E, nu=NU):
    return ["Material/mu=", "Material/lambda=", "Material/E=%r" % E, "Material/nu=%r" % nu]


def contact_rows(run):
    with open(os.path.join(run.directory, "contact.csv")) as f:
        return list(csv.DictReader(f))


def same_answer(base, run, s, m, dim, label):
    """run is base in units scaled by s (lengths) and m (stresses)."""
    check(base.ok() and run.ok() and base["converged"] and run["converged"],
          label + ": both run and converge")
    it_a, it_b = base["iterations"], run["iterations"]
    floor = base["stopped_at_round_off"] or run["stopped_at_round_off"]
    check(it_a == it_b or (floor and abs(it_a - it_b) == 1),
          label + ": the same iterations (%d, %d)" % (it_a, it_b))
    check(base["active"] == run["active"], label + ": the same active set size")
    J = base["functional"]
    differences = {
        "J": relative_difference(J, run["functional"] / s ** dim),
        "J parts": max(abs(base[k] - run[k] / s ** dim) / J
                       for k in ("functional_eq", "functional_const", "functional_compl")),
        "force": relative_difference(base["contact_force"],
                                     [f / (m * s ** (dim - 1)) for f in run["contact_force"]]),
        "max |u|": relative_difference(base["max_displacement"], run["max_displacement"] / s),
        "max von Mises": relative_difference(base["max_von_mises"], run["max_von_mises"] / m)}
    a, b = contact_rows(base), contact_rows(run)
    check(len(a) == len(b) and all(x["in_contact"] == y["in_contact"] for x, y in zip(a, b)),
          label + ": the same contact vertices, active at the same ones")
    if len(a) == len(b):
        differences["u_n"] = relative_difference([float(x["u_n"]) for x in a],
                                                 [float(y["u_n"]) / s for y in b])
        differences["sigma_nn"] = relative_difference([float(x["sigma_nn"]) for x in a],
                                                      [float(y["sigma_nn"]) / m for y in b])
    failed = [k for k, d in differences.items() if not d <= 1e-8]
    check(not failed,
          label + ": J, its parts, force, u_n, sigma_nn, max |u|, max von Mises agree "
          "to 1e-8" + (" (not: %s)" % ", ".join(failed) if failed else ""))


for name, prm, scale, dim in SCENES:
    base = R.run(prm, scale(1.) + material(E_UNIT), name=name.replace(" ", "_") + "_a")
    print("%s (a): iterations %d, active %d, J %s, force %s"
          % (name, base["iterations"], base["active"], rounded(base["functional"]),
             rounded(base["contact_force"][-1])))
    for label, s, E in SYSTEMS:
        run = R.run(prm, scale(s) + material(E), name=name.replace(" ", "_") + "_" + label[1])
        same_answer(base, run, s, E / E_UNIT, dim, name + " " + label)

# on 2 processes
for name, prm, scale, dim in SCENES:
    base = R.run(prm, scale(1.) + material(E_UNIT), name=name.replace(" ", "_") + "_a_np2",
                 processes=2)
    run = R.run(prm, scale(0.1) + material(210e9), name=name.replace(" ", "_") + "_b_np2",
                processes=2)
    same_answer(base, run, 0.1, 210e9 / E_UNIT, dim, name + " (b) SI on 2 processes")

# nearly incompressible steel in SI units
forces = {}
for nu in [0.4999, 0.49999999, 0.5]:
    run = R.run("prm/square.prm", square(0.1) + material(210e9, nu), name="nu_%r" % nu)
    check(run.ok() and run.finite() and run["converged"],
          "SI square, nu = %r: runs, finite, converged" % nu)
    forces[nu] = run["contact_force"][-1]
    print("SI square, nu = %r: iterations %d, force %s N/m"
          % (nu, run["iterations"], rounded(forces[nu], 4)))
d1 = relative_difference(forces[0.4999], forces[0.5])
d2 = relative_difference(forces[0.49999999], forces[0.5])
print("force difference to nu = 0.5: nu = 0.4999 %s, nu = 0.49999999 %s"
      % (rounded(d1, 2), rounded(d2, 2)))
check(d2 < d1 and d2 < 1e-6, "the forces approach the incompressible one")

# gravity in SI: rho g on the 0.1 m steel square (no push), against the
# unit-scale square with the dimensionless body force f L / S
rho_g = 7850. * 9.81
mu_steel = 210e9 / E_UNIT
si = R.run("prm/square.prm", square(0.1)[:1] + square(0.1)[2:] + material(210e9) +
           ["Data/Dirichlet values=0; 0", "Data/Constants=rho=7850, g=9.81",
            "Data/Body force=0; -rho*g"], name="gravity_si")
unit = R.run("prm/square.prm", square(1.)[:1] + square(1.)[2:] + material(E_UNIT) +
             ["Data/Dirichlet values=0; 0", "Data/Body force=0; %r" % (-rho_g * 0.1 / mu_steel)],
             name="gravity_unit")
print("gravity on the 0.1 m steel square: contact force %s N/m (weight %s N/m)"
      % (rounded(si["contact_force"][-1], 4), rounded(rho_g * 0.01, 4)))
same_answer(unit, si, 0.1, mu_steel, 2, "gravity, SI against unit scale")
finish()
