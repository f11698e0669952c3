#!/usr/bin/env python3
"""Work-precision study: run fosls-contact on the four
scenes over levels and solver settings, one process at a time, and collect
one row per case in bench/results/work_precision/runs.csv (copied to
doc/work_precision.csv).  doc/work_precision.md is made from that CSV by
bench/make_work_precision_report.py.

Each case writes its own output directory bench/results/work_precision/<case>/
(summary.json, convergence.csv, contact.csv; no VTU).  A case is skipped, and
recorded with status 'skipped' and the reason, when
  - the same setting failed or was skipped on the next coarser level,
  - its time predicted from the next coarser level (wall time x growth
    factor) exceeds CASE_CAP_S, or exceeds what is left of TOTAL_BUDGET_S;
and it is stopped (status 'timeout') when it runs longer than
min(CASE_CAP_S, what is left of the budget, max(STALL_FLOOR_S, STALL_FACTOR x
predicted)) -- the last term catches a solver that stalls.

    work_precision.py [--budget SECONDS] [--max-level-2d L] [--max-level-3d L] [--resume]

Small budgets/levels are for testing the scripts (e.g. --budget 120
--max-level-2d 5 --max-level-3d 4).
"""
import argparse
import csv
import json
import math
import os
import platform
import re
import shutil
import subprocess
import sys
import time

from common import BIN, RESULTS, ROOT, command, launch

RES = os.path.join(RESULTS, "work_precision")
DOC_CSV = os.path.join(ROOT, "doc", "work_precision.csv")

CASE_CAP_S = 300.0      # no single case may take longer than this
STALL_FACTOR = 4.0      # ... nor longer than this times its prediction
STALL_FLOOR_S = 30.0    # (but never less than this)
PGS_SWEEPS = 20000      # Max iterations for projected Gauss-Seidel

SCENES = {  # name: (prm file, dimension)
    "square": ("square.prm", 2),
    "mms": ("elasticity_mms.prm", 2),
    "hertz": ("hertz.prm", 2),
    "cube3d": ("cube3d.prm", 3),
}

# growth of the wall time from level J-1 to J, per solver family and dimension
GROWTH = {("mg", 2): 5.0, ("as", 2): 10.0, ("pgs", 2): 4.0,
          ("mg", 3): 9.0, ("as", 3): 20.0, ("pgs", 3): 8.0}

SECTIONS = {  # summary.json time_sections_s name -> CSV column (summed)
    "Setup: mesh, DoFs, levels": "t_setup",
    "Setup: solver": "t_setup",
    "Assembly": "t_assembly",
    "Definiteness check": "t_definiteness",
    "Initial guess": "t_initial_guess",
    "Solve": "t_solve",
    "Solve: Galerkin operators and patch setup": "t_galerkin",
    "Solve: coarse solve": "t_coarse",
    "Solve: smoothing": "t_smoothing",
}
TOP_SECTIONS = ["t_setup", "t_assembly", "t_definiteness", "t_initial_guess", "t_solve"]

FIELDS = (["case", "group", "scene", "dim", "config", "family", "level", "status",
           "note", "predicted_s", "wall_s", "dofs", "levels", "solver", "cycle",
           "projection", "krylov_steps", "stopping", "tolerance", "contact",
           "body_force", "iterations", "cycles", "converged",
           "stopped_at_round_off", "rate_per_cycle", "functional", "sqrt_functional",
           "force_y", "kkt_residual", "max_violation", "active", "error_u_h1",
           "error_sigma_hdiv", "hertz_F", "hertz_a", "hertz_p0",
           "pressure_error_l2_rel", "pressure_error_max_rel", "peak_rss_mb",
           "time_setup_s", "time_solve_s"]
          + list(dict.fromkeys(SECTIONS.values())) + ["t_output", "binary_mtime", "load1"])

T0 = time.time()
ARGS = None
rows = []
done = {}   # (scene, config, level) -> row


def log(msg):
    print(f"[{time.time() - T0:7.1f} s] {msg}", flush=True)


def write_rows():
    path = os.path.join(RES, "runs.csv")
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow(r)
    shutil.copyfile(path, DOC_CSV)


def record(row):
    rows.append(row)
    done[(row["scene"], row["config"], row["level"])] = row
    write_rows()
    return row


# ----------------------------------------------------------------- configs
def config(name):
    """Solver settings of a configuration name: (family, --set dict, description)."""
    s = {}
    tol = re.search(r"-tol(1e-\d+)", name)
    parts = re.sub(r"-tol1e-\d+", "-tol", name).split("-")
    if name == "as":
        return "as", {"Solver/Type": "active set"}, dict(solver="active set")
    if name == "pgs":
        return "pgs", {"Solver/Type": "projected gauss seidel",
                       "Solver/Max iterations": str(PGS_SWEEPS)}, \
            dict(solver="projected gauss seidel")
    # mg-<cycle>-<projection>[-disc][-tol<t>][-nocontact][-bf|-bf0|-nobf]
    # plain-<cycle>-<projection>: Krylov steps 0
    kind, cyc, proj = parts[:3]
    s["Solver/Cycle"] = cyc
    s["Solver/Projection"] = proj
    desc = dict(solver="monotone multigrid", cycle=cyc, projection=proj,
                krylov_steps=0 if kind == "plain" else 50,  # the default
                stopping="tolerance", tolerance="1e-8", contact="scene",
                body_force="scene")
    if kind == "plain":
        s["Solver/Krylov steps"] = "0"
    for p in parts[3:]:
        if p == "disc":
            s["Solver/Stopping criterion"] = "discretization accuracy"
            desc["stopping"] = "discretization accuracy"
        elif p == "tol":
            s["Solver/Tolerance"] = tol.group(1)
            desc["tolerance"] = tol.group(1)
        elif p == "nocontact":
            # square: the bottom side becomes traction free
            s["Boundary conditions/Contact boundary ids"] = ""
            s["Boundary conditions/Neumann boundary ids"] = "0, 1, 2"
            desc["contact"] = "no"
        elif p == "bf":
            s["Data/Body force"] = "0; -0.01"
            desc["body_force"] = "0; -0.01"
        elif p == "bf0":
            s["Data/Body force"] = "0; 0"
            desc["body_force"] = "0; 0 (declared, zero)"
        elif p == "nobf":
            s["Data/Body force"] = ""
            desc["body_force"] = "none"
        else:
            raise ValueError(name)
    return "mg", s, desc


# ----------------------------------------------------------------- one run
def hertz_pressure(out, force):
    """Contact pressure -sigma_nn at the contact vertices against Hertz's
    profile for the computed force (mu = lambda = 1, R = 0.5, plane strain)."""
    mu, lam, R = 1.0, 1.0, 0.5
    E = mu * (3 * lam + 2 * mu) / (lam + mu)
    nu = lam / (2 * (lam + mu))
    Es = E / (1 - nu ** 2)
    F = abs(force)
    a = math.sqrt(4 * F * R / (math.pi * Es))
    p0 = 2 * F / (math.pi * a)
    with open(os.path.join(out, "contact.csv")) as f:
        c = sorted(((float(r["x"]), -float(r["sigma_nn"])) for r in csv.DictReader(f)))
    exact = [p0 * math.sqrt(max(0.0, 1 - x * x / (a * a))) for x, _ in c]
    # trapezoidal rule in x for the L2 norms
    num = den = 0.0
    for i in range(len(c) - 1):
        h = c[i + 1][0] - c[i][0]
        num += 0.5 * h * ((c[i][1] - exact[i]) ** 2 + (c[i + 1][1] - exact[i + 1]) ** 2)
        den += 0.5 * h * (exact[i] ** 2 + exact[i + 1] ** 2)
    emax = max(abs(p - e) for (_, p), e in zip(c, exact))
    return dict(hertz_F=F, hertz_a=a, hertz_p0=p0,
                pressure_error_l2_rel=math.sqrt(num / den),
                pressure_error_max_rel=emax / p0)


def fill_from_summary(row, out):
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    for k in FIELDS:
        if k in s and not isinstance(s[k], (list, dict)):
            row[k] = s[k]
    row["solver"] = s["solver"]
    row["force_y"] = s["contact_force"][-1]
    row["sqrt_functional"] = math.sqrt(max(s["functional"], 0.0))
    sec = s.get("time_sections_s", {})
    for col in set(SECTIONS.values()):
        row[col] = 0.0
    for name, col in SECTIONS.items():
        row[col] += sec.get(name, 0.0)
    row["t_output"] = row["wall_s"] - sum(row[c] for c in TOP_SECTIONS)
    if row["scene"] == "hertz":
        row.update(hertz_pressure(out, row["force_y"]))


def case(scene, cfg, level, group):
    """Run (or skip) one case, unless the same (scene, cfg, level) ran already."""
    if (scene, cfg, level) in done:
        return done[(scene, cfg, level)]
    prm, dim = SCENES[scene]
    family, sets, desc = config(cfg)
    name = f"{scene}_{cfg}_L{level}"
    row = {"case": name, "group": group, "scene": scene, "dim": dim, "config": cfg,
           "family": family, "level": level, **desc}
    max_level = ARGS.max_level_3d if dim == 3 else ARGS.max_level_2d
    if level > max_level:
        return None
    prev = done.get((scene, cfg, level - 1))
    predicted = None
    if prev is not None:
        if prev["status"] != "ok":
            return skip(row, f"level {level - 1} was {prev['status']}")
        predicted = float(prev["wall_s"]) * GROWTH[(family, dim)]
        row["predicted_s"] = round(predicted, 1)
    left = ARGS.budget - (time.time() - T0)
    if predicted is not None and predicted > CASE_CAP_S:
        return skip(row, f"predicted {predicted:.0f} s > case cap {CASE_CAP_S:.0f} s "
                    f"(level {level - 1}: {prev['wall_s']:.1f} s x {GROWTH[(family, dim)]:g})")
    if left < 5 or (predicted is not None and predicted > left):
        return skip(row, f"total budget: predicted {predicted or 0:.0f} s, "
                    f"{max(left, 0):.0f} s left")
    timeout = min(CASE_CAP_S, left)
    if predicted is not None:
        timeout = min(timeout, max(STALL_FLOOR_S, STALL_FACTOR * predicted))
    out = os.path.join(RES, name)
    shutil.rmtree(out, ignore_errors=True)
    sets = dict(sets)
    sets.update({"Geometry/Levels": str(level), "Output/Directory": out,
                 "Output/Write vtu": "false", "Output/Verbose": "false"})
    if prm == "hertz.prm":
        sets.setdefault("Geometry/Grading", "1")  # the study's ungraded half disc
    cmd = command(prm, sets)
    row["binary_mtime"] = wait_for_binary()
    row["load1"] = round(os.getloadavg()[0], 2)
    t = time.time()
    try:
        try:
            p = launch(cmd, capture_output=True, text=True, timeout=timeout)
        except OSError:  # relinked between the check and the start: once more
            row["binary_mtime"] = wait_for_binary()
            t = time.time()
            p = launch(cmd, capture_output=True, text=True, timeout=timeout)
        row["wall_s"] = round(time.time() - t, 3)
        if p.returncode != 0:
            row["status"] = "error"
            row["note"] = (p.stderr.strip().splitlines() or ["?"])[-1][:200]
        else:
            row["status"] = "ok"
            fill_from_summary(row, out)
            if str(row.get("converged")).lower() != "true":
                row["note"] = f"not converged after {row['iterations']} iterations"
    except subprocess.TimeoutExpired:
        row["wall_s"] = round(time.time() - t, 3)
        row["status"] = "timeout"
        row["note"] = (f"stopped after {timeout:.0f} s (predicted "
                       f"{predicted if predicted is not None else float('nan'):.0f} s)")
    log(f"{name}: {row['status']} {row.get('note', '')} wall {row['wall_s']} s "
        f"dofs {row.get('dofs', '-')} it {row.get('iterations', '-')}")
    return record(row)


CHECKED = None


def wait_for_binary():
    """The binary may be relinked under us (another build): wait until it has
    not changed for 5 s and can be executed; returns its modification time."""
    global CHECKED
    for _ in range(120):
        try:
            m = os.stat(BIN).st_mtime
            if m == CHECKED:
                return time.strftime("%H:%M:%S", time.localtime(m))
            if time.time() - m > 5:
                launch([BIN, "--help"], capture_output=True, timeout=30)
                CHECKED = m
                return time.strftime("%H:%M:%S", time.localtime(m))
        except (OSError, subprocess.TimeoutExpired):
            pass
        time.sleep(5)
    sys.exit("build/fosls-contact stays busy or missing")


def skip(row, note):
    row["status"] = "skipped"
    row["note"] = note
    log(f"{row['case']}: skipped ({note})")
    return record(row)


def sweep(scene, cfgs, levels, group):
    for L in levels:
        for c in cfgs:
            case(scene, c, L, group)


# ----------------------------------------------------------------- the study
MG_MATRIX = [f"mg-{c}-{p}{s}" for p in "abcd" for c in "VW" for s in ("", "-disc")]
PLAIN = ["plain-V-b", "plain-W-b"]
DEFAULT = "mg-W-b"
DISC = "mg-W-b-disc"
TOLS = ["1e-2", "1e-3", "1e-4", "1e-5", "1e-6", "1e-7", "1e-8", "1e-9", "1e-10"]


def main():
    global ARGS
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--budget", type=float, default=31 * 60.0,
                    help="total seconds for all cases (default 1860)")
    ap.add_argument("--max-level-2d", type=int, default=9)
    ap.add_argument("--max-level-3d", type=int, default=6)
    ap.add_argument("--resume", action="store_true",
                    help="keep the cases of an interrupted run in runs.csv")
    ARGS = ap.parse_args()
    os.makedirs(RES, exist_ok=True)
    if not os.path.exists(BIN):
        sys.exit("build/fosls-contact missing: run scripts/setup.sh")

    # process start (library loading, MPI) without any work
    t = time.time()
    launch([BIN, "--print-parameters"], capture_output=True)
    startup = time.time() - t
    git = subprocess.run(["git", "-C", ROOT, "describe", "--always", "--dirty"],
                         capture_output=True, text=True).stdout.strip()
    mem = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2 ** 30
    meta = {"case": "_meta", "group": "meta", "scene": "", "config": "", "level": 0,
            "status": "meta", "wall_s": round(startup, 3),
            "note": f"cpus={os.cpu_count()}; mem_gb={mem:.1f}; "
                    f"cpu={platform.processor() or platform.machine()}; git={git}; "
                    f"budget_s={ARGS.budget:.0f}; case_cap_s={CASE_CAP_S:.0f}; "
                    f"pgs_sweeps={PGS_SWEEPS}"}
    rows.append(meta)
    if ARGS.resume and os.path.exists(os.path.join(RES, "runs.csv")):
        # keep the finished cases of an interrupted run (budget counts anew)
        with open(os.path.join(RES, "runs.csv")) as f:
            for r in csv.DictReader(f):
                if r["case"] != "_meta" and r["status"] != "skipped":
                    for k in ("wall_s", "predicted_s"):
                        r[k] = float(r[k]) if r[k] else None
                    r["level"] = int(r["level"])
                    record(r)
    log(f"process start without work: {startup:.2f} s; {meta['note']}")

    # 1. all solver settings on the small levels
    for L in range(3, 7):
        sweep("square", MG_MATRIX + PLAIN + ["pgs", "as"], [L], "matrix")
        sweep("mms", ["mg-V-b", "mg-W-b", "mg-V-b-disc", "mg-W-b-disc"] + PLAIN
              + ["pgs", "as"], [L], "matrix")
    sweep("hertz", MG_MATRIX + PLAIN + ["pgs", "as"], [3], "matrix")
    sweep("cube3d", MG_MATRIX + PLAIN + ["pgs", "as"], [3, 4], "matrix")
    # 2. default solver, discretization-accuracy stop and active set, up the levels
    sweep("square", [DEFAULT, DISC, "as"], range(7, 9), "levels")
    sweep("square", ["pgs"], range(7, 10), "levels")
    sweep("mms", [DEFAULT, DISC, "as"], range(7, 9), "levels")
    sweep("hertz", [DEFAULT, DISC, "as"], [4], "levels")
    sweep("cube3d", [DEFAULT, DISC, "as"], [5], "levels")
    # 3. tolerance sweep
    for scene, L in [("square", 7), ("hertz", 3), ("square", 8)]:
        for tol in TOLS:
            case(scene, DEFAULT if tol == "1e-8" else f"{DEFAULT}-tol{tol}", L, "tolerance")
    # 4. cost of each effect (square: contact, body force; mms: body force)
    for L in [6, 7, 8]:
        for c in ["mg-W-b-nocontact", "mg-W-b-bf0", "mg-W-b-bf", "mg-W-b-nocontact-bf"]:
            case("square", c, L, "effects")
        case("mms", "mg-W-b-nobf", L, "effects")
    # 5. the expensive finest levels, most important first
    sweep("square", [DEFAULT, DISC], [9], "levels")
    sweep("mms", [DEFAULT, DISC], [9], "levels")
    sweep("cube3d", [DEFAULT], [6], "levels")
    sweep("hertz", [DISC, DEFAULT, "as"], [5], "levels")
    sweep("square", ["as"], [9], "levels")
    sweep("mms", ["as"], [9], "levels")
    sweep("cube3d", [DISC, "as"], [6], "levels")
    sweep("hertz", [DISC, DEFAULT, "as"], [6, 7, 8, 9], "levels")
    sweep("cube3d", ["as"], [6], "levels")
    meta["note"] += f"; total_s={time.time() - T0:.0f}; startup_s={startup:.3f}"
    write_rows()
    log("done")


if __name__ == "__main__":
    main()
