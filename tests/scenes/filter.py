#!/usr/bin/env python3
"""Turn one run of fosls-contact into deterministic text for a scene test.

usage: filter.py SCREEN_OUTPUT OUTPUT_DIRECTORY

Prints, one item per line, what a scene test compares with its .output
file (numbers rounded to 6 significant digits, never times):
  - from the screen output: the "Converged after N iterations" line, whether
    "no contact boundary" / a definiteness check / a contact force line was
    printed, and whether the printed KKT residuals are below 1e-10;
  - that every output file exists (the pvtu record and the vtu pieces it
    names, one per MPI process), the row counts of contact.csv and
    convergence.csv, and the x range of the active contact vertices;
  - that summary.json has all required keys, and the deterministic fields.
Numerical noise is cut: the parts of the functional are printed as fractions
of the functional with 4 decimals (a part that vanishes in exact arithmetic,
such as |div sigma + f|^2 without body force, is made of the round-off of
1/2 x^T A x, whose terms cancel by many orders of magnitude: about 1e-5 of
J); contact force components below 1e-12 times the force are 0.
"""
import json
import os
import re
import sys

REQUIRED_FILES = ["solution_0000.pvtu", "contact.csv",
                  "convergence.csv", "summary.json", "used_parameters.prm"]
REQUIRED_KEYS = ["dofs", "levels", "iterations", "converged", "rate_asymptotic",
                 "functional", "functional_eq", "functional_const",
                 "functional_compl", "contact_force", "boundary_forces",
                 "boundary_force_sum", "units", "kkt_residual",
                 "time_setup_s", "time_solve_s", "peak_rss_mb"]


def rounded(value, scale=None, cut=1e-12):
    """6 significant digits; 0 if |value| < cut * scale."""
    if value is None:
        return "null"
    if scale is not None and abs(value) < cut * abs(scale):
        return "0"
    text = "%.6g" % value
    return "0" if text in ("0", "-0") else text


def main():
    screen_file, directory = sys.argv[1], sys.argv[2]
    with open(screen_file) as f:
        screen = f.read()
    lines = screen.splitlines()

    print("# screen output")
    converged = [l.strip() for l in lines
                 if re.match(r"\s*(NOT )?[Cc]onverged after", l)]
    print("converged line: " + (converged[-1] if converged else "MISSING"))
    print("'no contact boundary' printed: %s"
          % ("yes" if "no contact boundary" in screen else "no"))
    print("definiteness check printed: %s"
          % ("yes" if "Definiteness check on level" in screen else "no"))
    print("contact force printed: %s"
          % ("yes" if "Contact force =" in screen else "no"))
    kkt = [l for l in lines if l.startswith("KKT residuals:")]
    if kkt:
        values = [float(v) for v in
                  re.findall(r"[-+]?\d+\.\d+e[-+]\d+", kkt[-1])]
        print("screen KKT residuals < 1e-10: %s"
              % ("true" if len(values) == 3 and max(values) < 1e-10 else "false"))
    else:
        print("screen KKT residuals: MISSING")

    print("# output files")
    for name in REQUIRED_FILES:
        print("%s: %s" % (name, "present" if os.path.isfile(
            os.path.join(directory, name)) else "MISSING"))
    # the pieces the pvtu record names (one per MPI process)
    try:
        with open(os.path.join(directory, "solution_0000.pvtu")) as f:
            pieces = re.findall(r'Source="([^"]+)"', f.read())
    except OSError:
        pieces = []
    print("vtu pieces named by the pvtu: %s, all present: %s"
          % ("yes" if pieces else "none",
             "yes" if pieces and all(os.path.isfile(os.path.join(directory, p))
                                     for p in pieces) else "no"))
    # the staging directory and the lock file are made beside the directory
    parent = os.path.dirname(os.path.abspath(directory))
    name = os.path.basename(os.path.abspath(directory))
    leftovers = [n for n in os.listdir(parent)
                 if n.startswith("." + name + ".staging") or n == "." + name + ".lock"]
    print("staging directory left behind: %s" % ("yes" if leftovers else "no"))

    summary = {}
    try:
        with open(os.path.join(directory, "summary.json")) as f:
            summary = json.load(f)
    except (OSError, ValueError) as e:
        print("summary.json: NOT VALID JSON (%s)" % e)

    try:
        with open(os.path.join(directory, "contact.csv")) as f:
            rows = [r.split(",") for r in f.read().splitlines()[1:] if r]
        active = [r for r in rows if r[-1].strip() == "1"]
        print("contact.csv: %d rows, %d active" % (len(rows), len(active)))
        if active:
            xs = [float(r[0]) for r in active]
            print("active contact vertices span x in [%s, %s]"
                  % (rounded(min(xs), 1), rounded(max(xs), 1)))
    except OSError:
        pass
    try:
        with open(os.path.join(directory, "convergence.csv")) as f:
            n = len([r for r in f.read().splitlines()[1:] if r])
        print("convergence.csv rows = iterations + 1: %s"
              % ("true" if n == summary.get("iterations", -2) + 1 else "false"))
    except OSError:
        pass

    print("# summary.json")
    missing = [k for k in REQUIRED_KEYS if k not in summary]
    print("required keys: " + ("all present" if not missing
                               else "MISSING " + ", ".join(missing)))
    for key in ["dimension", "dofs", "levels", "solver", "iterations",
                "converged", "active", "energy_increases"]:
        if key in summary:
            print("%s = %s" % (key, json.dumps(summary[key])))
    J = summary.get("functional")
    if J is not None:
        print("functional = " + rounded(J))
        for key in ["functional_eq", "functional_const", "functional_compl"]:
            if key in summary:
                fraction = round(summary[key] / J, 4) if J else 0.
                print("%s / functional = %.4f" % (key, fraction or 0.))
    force = summary.get("contact_force")
    if force is not None:
        size = max([abs(c) for c in force] + [1e-300])
        print("contact_force = " + " ".join(rounded(c, size) for c in force))
        norm = sum(c * c for c in force) ** 0.5
        if norm > 0:
            # frictionless contact: parallel to the obstacle normal
            print("contact_force direction = "
                  + " ".join(rounded(c / norm, 1) for c in force))
    if "kkt_residual" in summary:
        r = summary["kkt_residual"]
        print("kkt_residual < 1e-10 = %s"
              % ("true" if r is not None and r < 1e-10 else "false"))
    if "max_violation" in summary:
        print("feasible (max_violation = 0) = %s"
              % ("true" if summary["max_violation"] == 0 else "false"))
    for key in ["error_u_l2", "error_u_h1", "error_sigma_l2",
                "error_sigma_hdiv"]:
        if key in summary:
            print("%s = %s" % (key, rounded(summary[key])))


if __name__ == "__main__":
    main()
