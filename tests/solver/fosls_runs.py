"""Helpers for the solver tests in tests/solver: python3 scripts that run
fosls-contact several times (with --set) and compare the runs with each
other, with the active set solver (the reference) or with formulas.

Every script is called as

    python3 tests/solver/<name>.py FOSLS_CONTACT_EXECUTABLE SOURCE_DIR

by tests/run_and_compare.sh (mode "unit") in a fresh work directory. It
prints deterministic text only (iteration counts, active-set sizes, numbers
rounded to a few digits, one "what: ok" / "what: FAILED" line per
assertion; never times), which the driver compares with
tests/solver/<name>.output, and exits with 1 if an assertion failed, so a
test fails even if its .output file was regenerated carelessly. Each run
leaves run_NN_<name>.cmd (the command line), .screen, .stderr and its
output directory in the work directory, for inspection.
"""
import csv
import json
import math
import os
import re
import signal
import subprocess
import sys

_failures = [0]


def check(condition, what):
    """Print 'what: ok' or 'what: FAILED' and count failures."""
    print("%s: %s" % (what, "ok" if condition else "FAILED"))
    sys.stdout.flush()
    if not condition:
        _failures[0] += 1
    return condition


def check_refused(run, what, pattern):
    """A bad scene: exit code 1, one line on stderr containing @p pattern,
    no summary.json."""
    lines = run.stderr.strip().splitlines()
    return check(run.returncode == 1 and len(lines) == 1 and pattern in lines[0]
                 and not run.summary, what + ": one line naming it, exit code 1, no summary")


def finish():
    """Exit with 1 if a check failed."""
    if _failures[0]:
        print("%d check(s) FAILED" % _failures[0])
    sys.stdout.flush()
    sys.exit(1 if _failures[0] else 0)


def rounded(value, digits=6):
    """@p value with @p digits significant digits, as text ('null' if None)."""
    if value is None:
        return "null"
    text = "%.*g" % (digits, value)
    return "0" if text in ("0", "-0") else text


def relative_difference(a, b):
    """|a - b| / max(|a|, |b|) for numbers or vectors (Euclidean norms);
    0 if both are 0, inf if one is missing."""
    if a is None or b is None:
        return math.inf
    if isinstance(a, (list, tuple)):
        num = math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))
        den = max(math.sqrt(sum(x * x for x in a)),
                  math.sqrt(sum(y * y for y in b)))
    else:
        num, den = abs(a - b), max(abs(a), abs(b))
    return 0. if num == 0 else num / den


class Run:
    """One finished run: summary.json, convergence.csv, screen, stderr and
    exit code."""

    def __init__(self, name, returncode, screen, stderr, directory):
        self.name = name
        self.returncode = returncode
        self.screen = screen
        self.stderr = stderr
        self.directory = directory
        self.summary = {}
        self.history = []
        try:
            with open(os.path.join(directory, "summary.json")) as f:
                self.summary = json.load(f)
        except (OSError, ValueError):
            pass
        try:
            with open(os.path.join(directory, "convergence.csv")) as f:
                lines = f.read().splitlines()
            keys = lines[0].split(",")
            self.history = [dict(zip(keys, (float(v) for v in l.split(","))))
                            for l in lines[1:] if l]
        except (OSError, ValueError, IndexError):
            pass

    def __getitem__(self, key):
        return self.summary.get(key)

    def ok(self):
        """The run ended normally with its output written: exit code 0
        and nothing on stderr, or, when the solver did not converge
        (summary.json "converged": false), exit code 2 and the one line on
        stderr that says so."""
        if not self.summary:
            return False
        if self.summary.get("converged") is False:
            lines = self.stderr.splitlines()
            return (self.returncode == 2 and len(lines) == 1
                    and "not converged" in lines[0])
        return self.returncode == 0 and self.stderr == ""

    @property
    def force(self):
        """The Euclidean norm of the contact force (None if missing)."""
        f = self.summary.get("contact_force")
        if f is None or any(c is None for c in f):
            return None
        return math.sqrt(sum(c * c for c in f))

    def finite(self):
        """No NaN/Inf anywhere: summary.json writes a non-finite number as
        null, and every number of convergence.csv must be finite."""
        keys = ["functional", "functional_eq", "functional_const",
                "functional_compl", "kkt_residual", "max_violation"]
        values = [self.summary.get(k) for k in keys]
        values += list(self.summary.get("contact_force") or [None])
        values += [v for r in self.history for v in r.values()]
        return (bool(self.summary) and bool(self.history)
                and all(v is not None and math.isfinite(v) for v in values))

    def max_increase(self):
        """The largest increase J_k - J_{k-1} in convergence.csv, relative
        to J_0 (0 if J never increases)."""
        J = [r["functional"] for r in self.history]
        if len(J) < 2:
            return 0.
        return max(0., max(J[k] - J[k - 1] for k in range(1, len(J)))) \
            / max(abs(J[0]), 1e-300)

    def max_violation_history(self):
        """The largest constraint violation of any iterate (convergence.csv)
        and of the result (summary.json)."""
        values = [r["violation"] for r in self.history]
        values.append(self.summary.get("max_violation", math.inf))
        return max(v if v is not None else math.inf for v in values)


class Runner:
    """Runs the executable on scenes of the source tree with --set."""

    def __init__(self, argv):
        if len(argv) != 3:
            sys.exit("usage: %s FOSLS_CONTACT SOURCE_DIR" % argv[0])
        self.exe, self.source = argv[1], argv[2]
        self.count = 0

    def run(self, prm, settings=(), name=None, processes=1, timeout=None,
            stop="tolerance"):
        """Run @p prm (relative to the source directory) with the
        "Section/Name=value" strings @p settings and Solver/Stopping
        criterion = @p stop (None: the program's default; the tests compare
        solvers converged to Solver/Tolerance, and solver/default_stop the
        default stop with that), on @p processes MPI
        processes (mpirun from $MPIRUN, more processes than cores allowed);
        the output goes to ./run_NN_<name>, without vtu files. A run that
        takes longer than @p timeout seconds (a hang, e.g. a deadlock
        between MPI processes) is killed with all its processes; its
        returncode is then None."""
        self.count += 1
        directory = "run_%02d" % self.count + ("_" + name if name else "")
        stopping = [] if stop is None or any(
            s.startswith("Solver/Stopping criterion") for s in settings) else [
            "Solver/Stopping criterion=" + stop]
        command = command_line(self.exe, os.path.join(self.source, prm),
                               ["Output/Directory=" + directory,
                                "Output/Write vtu=false"] + stopping + list(settings),
                               processes)
        with open(directory + ".cmd", "w") as f:
            f.write(" ".join("'%s'" % c if " " in c or ";" in c else c
                             for c in command) + "\n")
        with open(directory + ".screen", "w") as out, \
                open(directory + ".stderr", "w") as err:
            # (a session of its own, so that mpirun and the processes it
            # started can be killed together)
            process = subprocess.Popen(command, stdout=out, stderr=err,
                                       start_new_session=True)
            try:
                returncode = process.wait(timeout=timeout)
            except subprocess.TimeoutExpired:
                # mpirun ends its processes on SIGTERM (they are not all in
                # its process group); whatever is left of the session then
                # gets SIGKILL
                process.terminate()
                try:
                    process.wait(timeout=10)
                except subprocess.TimeoutExpired:
                    pass
                try:
                    os.killpg(process.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                process.wait()
                returncode = None
        with open(directory + ".screen") as f:
            screen = f.read()
        with open(directory + ".stderr") as f:
            stderr = f.read()
        return Run(name or directory, returncode, screen, stderr, directory)


# Tolerances shared by the scripts.
#
# J is evaluated as 1/2 x^T A x - b^T x + c, whose terms are far larger than
# J at the solution (J is the squared discretization error): on the square
# at 6 levels consecutive iterates at the round-off floor show J going up by
# up to 3.3e-10 J_0 (1.2e-15 absolute). "J never increases" is therefore
# checked on convergence.csv up to MONOTONE_TOLERANCE * J_0, and exactly by
# the solver's own count (summary.json energy_increases, which compares the
# change of each sub-step with the round-off of its own terms).
MONOTONE_TOLERANCE = 1e-8
# Feasibility: every bound and fixed value holds to 1e-12 relative to the
# data scale of the scenes (the push 0.01 of the top side), i.e. 1e-14
# absolute. The solvers project exactly, so the measured value is 0.
VIOLATION_TOLERANCE = 1e-14


def solves(run):
    """J at the start and after every iteration of each monotone multigrid
    solve on the screen (with friction one solve per Tresca problem: a
    problem that the Coulomb fixed point solves on to Solver/Tolerance is
    one solve in two runs, the second starting where the first ended)."""
    result = []
    continued = False
    for line in run.screen.splitlines():
        start = re.search(r"monotone multigrid: start\s+J = (\S+)", line)
        step = re.search(r"monotone multigrid: it\s+\d+\s+J = (\S+)", line)
        if "solved on to Solver/Tolerance" in line:
            continued = True
        elif start and continued and result:
            continued = False
        elif start:
            result.append([float(start.group(1))])
        elif step and result:
            result[-1].append(float(step.group(1)))
    return result


def newton_steps(run):
    """The iterations (Newton steps) of each solve on the screen."""
    return [len(J) - 1 for J in solves(run)]


def monotone(run):
    """J never increases within a solve on the screen (as printed, 7 digits)."""
    return all(J[k] <= J[k - 1] for J in solves(run) for k in range(1, len(J)))


def same_steps(a, b, tolerance):
    """Two runs' load steps with friction: the same stick and slip
    vertices, forces to @p tolerance of the normal force and J to
    @p tolerance."""
    a, b = a["load_steps"] or [], b["load_steps"] or []
    return len(a) == len(b) > 0 and all(
        (r["stick_vertices"], r["slip_vertices"]) == (s["stick_vertices"], s["slip_vertices"])
        and abs(r["normal_force"] - s["normal_force"]) <= tolerance * r["normal_force"]
        and abs(r["tangential_force"] - s["tangential_force"]) <= tolerance * r["normal_force"]
        and relative_difference(r["functional"], s["functional"]) <= tolerance
        for r, s in zip(a, b))


def check_monotone_feasible(run, label, scale=0.01,
                            monotone_tolerance=MONOTONE_TOLERANCE):
    """The common checks of every multigrid run: it ran (exit code 0,
    nothing on stderr), no NaN/Inf, J never increased (solver count, and
    convergence.csv up to @p monotone_tolerance J_0), every iterate is
    feasible (violations up to 1e-12 @p scale)."""
    check(run.ok(), label + ": exit code 0, nothing on stderr")
    check(run.finite(), label + ": no NaN/Inf in summary.json and "
          "convergence.csv")
    check(run["energy_increases"] == 0, label + ": energy_increases == 0")
    check(run.max_increase() <= monotone_tolerance,
          label + ": J_k <= J_{k-1} + %g J_0 in convergence.csv"
          % monotone_tolerance)
    check(run.max_violation_history() <= VIOLATION_TOLERANCE * scale / 0.01,
          label + ": every iterate feasible (violation <= %g)"
          % (VIOLATION_TOLERANCE * scale / 0.01))


def level_visits_follow(run, visits_at_depth, coarsest_exact=True):
    """summary.json's level_visits are those of a cycle that visits level
    J - k visits_at_depth(k) times per visit of the finest level J, down to
    the coarsest level it visits, C, which is visited as often as level
    C + 1 (once per visit: it is solved exactly), and the levels below C
    not at all. C: with @p coarsest_exact (the linear cycle of the default
    solver) the finest level below J with at most 200 DoFs (level 0 if
    there is none), otherwise level 0 (the plain cycle)."""
    visits, dofs = run["level_visits"], run["level_dofs"]
    J = len(visits) - 1
    C = 0
    if coarsest_exact:
        C = max([l for l in range(1, J) if dofs[l] <= 200] or [0])
    return (visits[C] == visits[C + 1] and
            all(visits[l] == 0 for l in range(C)) and
            all(visits[l] == visits[J] * visits_at_depth(J - l)
                for l in range(C + 1, J + 1)))


def describe(run, label, keys=("iterations", "cycles", "converged",
                               "active", "feasibility_dampings")):
    """One deterministic line: the integer/boolean fields @p keys."""
    print("%s: %s" % (label, ", ".join(
        "%s %s" % (k, json.dumps(run[k])) for k in keys)))


def compare_with_reference(run, reference, label, force_tolerance=1e-8,
                           functional_tolerance=1e-8, kkt_tolerance=1e-8):
    """The run reached the reference's KKT point: relative differences of
    the contact force vector and of J, the KKT residual, same number of
    active constraints."""
    check(reference.ok() and reference["converged"] is True,
          label + ": the reference (active set) converged")
    dF = relative_difference(run["contact_force"], reference["contact_force"])
    dJ = relative_difference(run["functional"], reference["functional"])
    check(dF <= force_tolerance,
          label + ": |F - F_ref| / |F_ref| <= %g" % force_tolerance)
    check(dJ <= functional_tolerance,
          label + ": |J - J_ref| / J_ref <= %g" % functional_tolerance)
    check(run["kkt_residual"] is not None
          and run["kkt_residual"] <= kkt_tolerance,
          label + ": KKT residual <= %g" % kkt_tolerance)
    check(run["active"] == reference["active"],
          label + ": active constraints as the reference (%s)"
          % reference["active"])


def check_flat_contact_run(run, max_iterations, n_contact_vertices):
    """The checks of a multigrid run on a flat obstacle that the whole
    contact boundary touches (cube3d_convergence, deep_hierarchy): converged
    within @p max_iterations to a KKT residual < 1e-10, monotone and
    feasible, and all @p n_contact_vertices contact vertices in contact
    (last column of contact.csv)."""
    describe(run, "multigrid", ("dofs", "iterations", "cycles", "converged",
                                "active"))
    check(run["converged"] is True and run["iterations"] <= max_iterations,
          "converged within %d iterations" % max_iterations)
    check(run["kkt_residual"] is not None and run["kkt_residual"] < 1e-10,
          "KKT residual < 1e-10")
    check_monotone_feasible(run, "multigrid")
    with open(os.path.join(run.directory, "contact.csv")) as f:
        rows = [r.split(",") for r in f.read().splitlines()[1:] if r]
    check(len(rows) == n_contact_vertices
          and all(r[-1].strip() == "1" for r in rows),
          "all %d bottom vertices in contact" % n_contact_vertices)


def check_plain_cycle(runner, label, prm, scene):
    """Run the paper's plain cycle (Krylov steps = 0, at most 100 cycles)
    and the active set solver on one scene; check that the cycle converged
    to the active set solver's force (1e-6 relative). Returns the run."""
    reference = runner.run(prm, scene + ["Solver/Type=active set"],
                           "reference")
    run = runner.run(prm, scene + ["Solver/Krylov steps=0",
                                   "Solver/Max iterations=100"],
                     "plain_cycle")
    check(run.ok() and run["converged"] is True,
          label + ": converged within 100 cycles")
    check(relative_difference(run["contact_force"],
                              reference["contact_force"]) <= 1e-6,
          label + ": |F - F_ref| / |F_ref| <= 1e-6")
    return run


def command_line(exe, prm, settings=(), processes=1):
    """The command that runs @p exe on @p prm with the "Section/Name=value"
    strings @p settings, on @p processes MPI processes (mpirun from
    $MPIRUN, --quiet: no report of its own on a non-zero exit code)."""
    command = [exe, prm]
    for s in settings:
        command += ["--set", s]
    if processes > 1:
        command = [os.environ.get("MPIRUN", "mpirun"), "--quiet", "--oversubscribe",
                   "-np", str(processes)] + command
    return command


def execute(command, env=None, timeout=300, stdout=subprocess.PIPE):
    """Run @p command (a list) with the extra environment variables @p env;
    return (exit code, stdout text, stderr text). A run that takes longer
    than @p timeout seconds is killed (exit code None)."""
    environment = dict(os.environ)
    environment.update(env or {})
    try:
        p = subprocess.run(command, env=environment, stdout=stdout,
                           stderr=subprocess.PIPE, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "", ""
    decode = lambda b: b.decode("utf-8", "backslashreplace") if b else ""
    return p.returncode, decode(p.stdout), decode(p.stderr)


def one_error_line(stderr, *parts):
    """stderr is exactly one line, 'fosls-contact: error in ...', and
    contains every string of @p parts."""
    lines = stderr.splitlines()
    return (len(lines) == 1 and lines[0].startswith("fosls-contact: error in ")
            and all(p in lines[0] for p in parts))


def leftovers(directory):
    """What a run may leave beside @p directory: its staging directories and
    its lock file."""
    parent = os.path.dirname(os.path.abspath(directory)) or "."
    name = os.path.basename(os.path.abspath(directory))
    return sorted(n for n in os.listdir(parent)
                  if n.startswith("." + name + ".staging") or n == "." + name + ".lock")


def check_hertz(run, label, shape, E, nu, radius, centre, normal, factor=1., axis=None,
                length=None):
    """summary.json's "hertz" of @p run (scene section Hertz comparison with
    @p shape, @p radius, contact point @p centre; obstacle @p normal;
    material @p E, @p nu; Force factor @p factor; for a cylinder in 3D its
    @p axis and contact @p length) as recomputed from the contact force and
    contact.csv to 1e-8: Hertz's a and p0, the contact edge, peak, l2
    pressure error at the vertices and L2 error on the boundary (the
    vertices weighted by contact.csv's boundary_share); and Hertz's a
    between the last vertex in contact and the next. Prints one line;
    returns (peak, p0, a, inside, outside)."""
    h = run["hertz"] or {}
    dim = len(centre)
    E_star = E / (1. - nu * nu)
    F = factor * abs(sum(f * n for f, n in zip(run["contact_force"], normal)))
    if axis:
        F /= length
    if shape == "cylinder":
        a = math.sqrt(4. * F * radius / (math.pi * E_star))
        p0 = 2. * F / (math.pi * a)
    else:
        a = (3. * F * radius / (4. * E_star)) ** (1. / 3.)
        p0 = 3. * F / (2. * math.pi * a * a)
    with open(os.path.join(run.directory, "contact.csv")) as f:
        rows = list(csv.DictReader(f))
    unit_axis = [x / math.sqrt(sum(y * y for y in axis)) for x in axis] if axis else [0.] * dim

    def r_of(row):
        p = [float(row["xyz"[d]]) - centre[d] for d in range(dim)]
        for n in (unit_axis, normal):
            pn = sum(p[d] * n[d] for d in range(dim))
            p = [p[d] - pn * n[d] for d in range(dim)]
        return math.sqrt(sum(x * x for x in p))

    def hertz(r):
        return p0 * math.sqrt(1. - r * r / (a * a)) if r < a else 0.

    inside = max(r_of(x) for x in rows if x["in_contact"] == "1")
    outside = min(r_of(x) for x in rows if x["in_contact"] == "0" and r_of(x) > inside)
    peak = max(-float(x["sigma_nn"]) for x in rows)
    error = math.sqrt(sum((-float(x["sigma_nn"]) - hertz(r_of(x))) ** 2 for x in rows) /
                      sum(hertz(r_of(x)) ** 2 for x in rows))
    # the same weighted by each vertex's share of the contact boundary
    share = [float(x["boundary_share"]) for x in rows]
    error_boundary = math.sqrt(
        sum(w * (-float(x["sigma_nn"]) - hertz(r_of(x))) ** 2 for w, x in zip(share, rows)) /
        sum(w * hertz(r_of(x)) ** 2 for w, x in zip(share, rows)))
    expected = {"force": F, "contact_modulus": E_star, "a": a, "p0": p0,
                "edge_inside": inside, "edge_outside": outside, "peak": peak,
                "pressure_error": error, "pressure_error_boundary": error_boundary,
                "force_factor": factor}
    wrong = [k for k, v in expected.items() if not relative_difference(h.get(k), v) <= 1e-8]
    check(not wrong, label + ": summary.json's hertz entries as recomputed from "
          "contact.csv to 1e-8" + (" (not: %s)" % ", ".join(wrong) if wrong else ""))
    print("%s: F %s, a %s between %s and %s, p0 %s, peak %s, pressure error %s"
          % (label, rounded(F, 5), rounded(a, 4), rounded(inside, 4), rounded(outside, 4),
             rounded(p0, 4), rounded(peak, 4), rounded(error, 3)))
    check(inside < a < outside, label + ": Hertz's a between the last vertex in contact "
          "and the next")
    return peak, p0, a, inside, outside


def check_same(runs, label, tolerance, last_tolerance=None):
    """All @p runs converged to the first one's contact force and functional,
    to @p tolerance (the last one to @p last_tolerance if given)."""
    check(all(r.ok() and r["converged"] is True for r in runs), label + ": all converged")
    tolerances = [tolerance] * (len(runs) - 2) + [last_tolerance or tolerance]
    check(all(relative_difference(r["contact_force"], runs[0]["contact_force"]) <= t and
              relative_difference(r["functional"], runs[0]["functional"]) <= t
              for r, t in zip(runs[1:], tolerances)),
          label + ": the same contact force and J to %g" % tolerance +
          (" (the last one to %g)" % last_tolerance if last_tolerance else ""))


def in_contact(run):
    """The number of contact vertices of @p run in contact (contact.csv)."""
    with open(os.path.join(run.directory, "contact.csv")) as f:
        return sum(1 for row in csv.DictReader(f) if row["in_contact"] == "1")


def check_shipped(run, label):
    """A shipped Hertz scene: converged, monotone and feasible, and at least
    8 contact vertices in contact (enough to compare with Hertz)."""
    describe(run, label, ("dofs", "converged", "active"))
    check(run["converged"] is True, label + ": converged")
    check_monotone_feasible(run, label)
    n = in_contact(run)
    print("%s: %d contact vertices in contact" % (label, n))
    check(n >= 8, label + ": at least 8 contact vertices in contact")


# prm/cattaneo_mindlin.prm's load path: the normal force P and the pulls Q
# of its load steps (the press, 0.5 f P and 0.8 f P)
CATTANEO_MINDLIN_P = 0.01
CATTANEO_MINDLIN_LOADS = [0., 0.0015, 0.0024]


def cattaneo_mindlin_2d(rows, normal_force, tangential_force, f=0.3, radius=2., e_star=4.):
    """Hertz's and Cattaneo-Mindlin's figures for one step's 2D contact
    table @p rows (sorted by x; the pull along +x), for the friction
    coefficient @p f, the cylinder's @p radius and E* = @p e_star (those of
    prm/cattaneo_mindlin.prm: E* = 4 mu for nu = 1/2): a, c,
    Q/(f P) ("ratio"), the pressure's relative L2 error, the tangential
    traction's relative to |f p| ("of_fp") and to |q| ("of_q", pulled
    only), the stick zone's ends midway between its outermost stick vertex
    and the next one ("from", "to") and their distances from -c and c in
    those vertex spacings ("from_error", "to_error")."""
    a = math.sqrt(4 * normal_force * radius / (math.pi * e_star))
    p0 = 2 * normal_force / (math.pi * a)
    ratio = tangential_force / (f * normal_force)
    c = a * math.sqrt(1 - ratio)

    def p(x):
        return p0 * math.sqrt(1 - x * x / (a * a)) if abs(x) < a else 0.

    def q(x):
        return f * p(x) - (f * p0 * (c / a) * math.sqrt(1 - x * x / (c * c)) if abs(x) < c else 0.)

    x = [float(r["x"]) for r in rows]
    w = [float(r["boundary_share"]) for r in rows]
    p_h = [-float(r["sigma_nn"]) for r in rows]
    q_h = [float(r["traction_t_x"]) for r in rows]   # Q points along +x

    def l2(values):
        return math.sqrt(sum(wi * v * v for wi, v in zip(w, values)))

    result = {"a": a, "c": c, "ratio": ratio,
              "pressure_error": l2([ph - p(xi) for ph, xi in zip(p_h, x)]) / l2([p(xi) for xi in x]),
              "of_fp": l2([qh - q(xi) for qh, xi in zip(q_h, x)]) / l2([f * p(xi) for xi in x])}
    if ratio > 1e-6:   # (pressed, q = 0 up to round-off)
        result["of_q"] = l2([qh - q(xi) for qh, xi in zip(q_h, x)]) / l2([q(xi) for xi in x])
    stick = [i for i, r in enumerate(rows) if r["in_contact"] == "1" and r["status"] == "1"]
    lo, hi = min(stick), max(stick)
    result["from"], result["to"] = (x[lo] + x[lo - 1]) / 2, (x[hi] + x[hi + 1]) / 2
    result["from_error"] = abs(result["from"] + c) / (x[lo] - x[lo - 1])
    result["to_error"] = abs(result["to"] - c) / (x[hi + 1] - x[hi])
    return result
