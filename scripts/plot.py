#!/usr/bin/env python3
"""Plot a fosls-contact run: the contact pressure and the convergence history.

    scripts/plot.py RUN_DIR [-o OUT_DIR]

RUN_DIR is a run's Output/Directory (it holds contact.csv, convergence.csv
and summary.json). Writes, into OUT_DIR (default RUN_DIR):

  contact_pressure.png  -sigma_nn at the contact vertices, in the scene's
                        units (named on the axes as summary.json's "units",
                        Scaling/Unit names, has them), against x in 2D and
                        against the distance
                        from the contact point in 3D; with Hertz's pressure
                        where the scene declares a Hertz comparison
                        (summary.json "hertz"), and the vertices in contact
                        marked.
  convergence.png       J and the energy norm of the correction per
                        iteration (convergence.csv).
  load_path.png         runs along a load path (Data/Load steps,
                        summary.json "load_steps"): the normal contact
                        force against the constant the path changes (the
                        first, by name, if it changes several), the steps
                        joined in their order, so that unloading shows.

Exit code 0, or 1 with one line on stderr if the run directory is missing
or incomplete.
"""
import argparse
import csv
import json
import math
import os
import sys


def fail(message):
    sys.stderr.write("plot.py: error: %s\n" % message)
    sys.exit(1)


def read_run(directory):
    try:
        with open(os.path.join(directory, "summary.json")) as f:
            summary = json.load(f)
        with open(os.path.join(directory, "convergence.csv")) as f:
            history = list(csv.DictReader(f))
        with open(os.path.join(directory, "contact.csv")) as f:
            contact = list(csv.DictReader(f))
    except (OSError, ValueError) as e:
        fail("cannot read the run in '%s': %s" % (directory, e))
    return summary, history, contact


def unit_label(summary, kind):
    """The unit of a quantity of @p kind ("length", "stress", "functional",
    ...) for an axis label: " [mm]" with summary.json's "units"
    (Scaling/Unit names), " (scene units)" where they are not named."""
    unit = (summary.get("units") or {}).get(kind, "")
    return " [%s]" % unit if unit else " (scene units)"


def hertz_pressure(hertz, r):
    a, p0 = hertz["a"], hertz["p0"]
    return p0 * math.sqrt(1. - (r / a) ** 2) if a and abs(r) < a else 0.


def distance_in_plane(row, hertz, dim):
    """Distance of a contact vertex from Hertz's contact point, in the plane
    orthogonal to the obstacle normal (and for a cylinder in 3D from its
    contact line along "axis", which is zero otherwise)."""
    p = [float(row["xyz"[d]]) - hertz["contact_point"][d] for d in range(dim)]
    for n in (hertz.get("axis", [0.] * dim), hertz["normal"]):
        pn = sum(p[d] * n[d] for d in range(dim))
        p = [p[d] - pn * n[d] for d in range(dim)]
    return math.sqrt(sum(x * x for x in p))


def plot_pressure(plt, summary, contact, out):
    dim = int(summary["dimension"])
    hertz = summary.get("hertz")
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    if not contact:
        ax.text(0.5, 0.5, "no contact boundary", ha="center", transform=ax.transAxes)
    else:
        if dim == 2:
            # signed position along the contact, measured from Hertz's point
            origin = hertz["contact_point"][0] if hertz else 0.
            coordinate = [float(r["x"]) - origin for r in contact]
            label = ("x" if not hertz else "x - x_contact") + unit_label(summary, "length")
        else:
            if hertz:
                coordinate = [distance_in_plane(r, hertz, dim) for r in contact]
            else:
                centre = [sum(float(r["xyz"[d]]) for r in contact) / len(contact)
                          for d in range(dim)]
                coordinate = [math.sqrt(sum((float(r["xyz"[d]]) - centre[d]) ** 2
                                            for d in range(dim))) for r in contact]
            label = "distance from the contact point" + unit_label(summary, "length")
        pressure = [-float(r["sigma_nn"]) for r in contact]
        active = [r["in_contact"].strip() == "1" for r in contact]
        order = sorted(range(len(contact)), key=lambda i: coordinate[i])
        if dim == 2:
            ax.plot([coordinate[i] for i in order], [pressure[i] for i in order],
                    "-", color="tab:blue", lw=1, label="computed -sigma_nn")
        else:
            ax.plot(coordinate, pressure, ".", color="tab:blue", ms=3,
                    label="computed -sigma_nn")
        ax.plot([c for c, a in zip(coordinate, active) if a],
                [p for p, a in zip(pressure, active) if a], "o", mfc="none",
                color="tab:blue", ms=5, label="in contact (u_n = g)")
        if hertz:
            a = hertz["a"]
            span = 2.5 * a if a else max(coordinate)
            lo = -span if dim == 2 else 0.
            xs = [lo + (span - lo) * k / 800. for k in range(801)]
            ax.plot(xs, [hertz_pressure(hertz, x) for x in xs], "--", color="tab:red",
                    label="Hertz (a = %.4g%s, p0 = %.4g%s)"
                    % (a, unit_label(summary, "length"), hertz["p0"],
                       unit_label(summary, "stress")))
            ax.set_xlim(lo, span)
            stress = (summary.get("units") or {}).get("stress", "")
            stress = " " + stress if stress else ""
            # (null where Hertz's pressure is 0 at every contact vertex)
            error = hertz["pressure_error"]
            ax.set_title("contact pressure; Hertz's peak %.4g%s, computed %.4g%s, "
                         "l2 error %s" % (hertz["p0"], stress, hertz["peak"], stress,
                                          "none" if error is None else "%.3g" % error),
                         fontsize=9)
        ax.set_xlabel(label)
        ax.set_ylabel("contact pressure -sigma_nn" + unit_label(summary, "stress"))
        ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "contact_pressure.png"), dpi=120)
    plt.close(fig)


def plot_convergence(plt, summary, history, out):
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    iterations = [int(r["iteration"]) for r in history]
    J = [float(r["functional"]) for r in history]
    correction = [float(r["correction"]) for r in history]
    ax.semilogy(iterations, [max(j, 1e-300) for j in J], "o-", label="J")
    ax.semilogy(iterations[1:], [max(c, 1e-300) for c in correction[1:]], "s-",
                label="|x_k - x_{k-1}|_A")
    ax.set_xlabel("iteration")
    # (the energy norm of the correction is the square root of a J)
    unit = (summary.get("units") or {}).get("functional", "")
    ax.set_ylabel("J" + unit_label(summary, "functional") + ", |x_k - x_{k-1}|_A"
                  + (" [(%s)^(1/2)]" % unit if unit else ""))
    ax.set_title("%s: %d iterations, %s" % (
        summary.get("solver", "solver"), int(summary.get("iterations", 0)),
        "converged" if summary.get("converged") else "NOT converged"), fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "convergence.png"), dpi=120)
    plt.close(fig)


def plot_load_path(plt, summary, out):
    """load_path.png, for a run along a load path; the file name, or None."""
    steps = summary.get("load_steps") or []
    if not steps or not steps[0]["constants"]:
        return None
    name = sorted(steps[0]["constants"])[0]
    load = [s["constants"][name] for s in steps]
    force = [s["normal_force"] for s in steps]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(load, force, "o-")
    for s, x, y in zip(steps, load, force):
        ax.annotate(str(s["step"]), (x, y), textcoords="offset points", xytext=(4, -10),
                    fontsize=7)
    ax.set_xlabel(name + " (Data/Constants)")
    ax.set_ylabel("normal contact force" + unit_label(summary, "force"))
    ax.set_title("load path: %d steps (numbered)" % len(steps), fontsize=9)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    path = os.path.join(out, "load_path.png")
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def main():
    parser = argparse.ArgumentParser(description="Plot a fosls-contact run.")
    parser.add_argument("run_dir", help="the run's Output/Directory")
    parser.add_argument("-o", "--out", help="where to write the PNG files "
                        "(default: the run directory)")
    args = parser.parse_args()
    if not os.path.isdir(args.run_dir):
        fail("'%s' is not a directory" % args.run_dir)
    summary, history, contact = read_run(args.run_dir)
    out = args.out or args.run_dir
    os.makedirs(out, exist_ok=True)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        # another python3 first on PATH (a virtual environment, pyenv):
        # the system's, where apt installs python3-matplotlib, has it
        system = "/usr/bin/python3"
        if os.path.exists(system) and os.path.realpath(sys.executable) != system:
            os.execv(system, [system] + sys.argv)
        fail("matplotlib is missing (scripts/setup.sh installs python3-matplotlib)")
    plot_pressure(plt, summary, contact, out)
    plot_convergence(plt, summary, history, out)
    written = [os.path.join(out, "contact_pressure.png"), os.path.join(out, "convergence.png")]
    load_path = plot_load_path(plt, summary, out)
    if load_path:
        written.append(load_path)
    print("wrote %s" % ", ".join(written))


if __name__ == "__main__":
    main()
