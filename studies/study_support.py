"""Helpers shared by the study scripts (studies/paper_layups.py, studies/sandwich.py): running the
shellindent CLI (`sweep`, `run`, `fit`), reading its CSV/JSON results (docs/results.md,
docs/sweeps.md, docs/fitting.md) and small numerical utilities. Standard library only; the
figures are drawn by the scripts themselves (matplotlib).
"""
import csv
import json
import math
import os
import re
import resource
import subprocess
import time

STUDIES_DIR = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.path.dirname(STUDIES_DIR)


# The paper's Table 1 ply (library material paper-carbon-epoxy), in-plane constants in MPa.
PAPER_PLY = {"E1": 130e3, "E2": 10e3, "G12": 6e3, "nu12": 0.3}


# Plausible exponents of T = C1 h^C2 for a shell under a sphere (the smoke tests' check): a
# point load on a linear shell gives 1, the growing contact patch a little more, membrane
# stiffening at most 3 (the w^3 term of a clamped plate, ../shared/benchmarks/point-loads.md 4.2).
C2_PHYSICAL_RANGE = (0.9, 3.0)


class StudyError(RuntimeError):
    """A study step failed; the message says which and why (the script exits with status 1)."""


def default_exe():
    """The CLI built by the documented build command (README), if no --exe is given."""
    return os.path.join(SOURCE_DIR, "build", "shellindent")


def children_cpu_seconds():
    """User + system CPU time of the finished child processes (the cases of a sweep are children
    of the sweep, which waits for them): a measure of the work less sensitive to the load."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_cli(exe, args, log_path=None):
    """Runs `exe args...`; returns (exit code, wall seconds, stdout, stderr). Never raises on a
    non-zero exit: the caller decides (a variant that fails is a result to report)."""
    start, cpu0 = time.monotonic(), children_cpu_seconds()
    proc = subprocess.run([exe] + args, capture_output=True, text=True)
    wall = time.monotonic() - start
    run_cli.last_cpu_s = children_cpu_seconds() - cpu0
    if log_path:
        with open(log_path, "w") as f:
            f.write("$ " + " ".join([exe] + args) + "\n" + proc.stdout + proc.stderr)
    return proc.returncode, wall, proc.stdout, proc.stderr


def run_sweep(exe, study_yaml, out_dir, jobs, quick):
    """`shellindent sweep STUDY --out DIR -j N [--quick]` (docs/sweeps.md). Returns a dict with
    the exit code, wall time, the last stderr lines and the parsed sweep.json (None if absent)."""
    os.makedirs(out_dir, exist_ok=True)
    args = ["sweep", study_yaml, "--out", out_dir, "-j", str(jobs)] + (["--quick"] if quick else [])
    code, wall, _, err = run_cli(exe, args, os.path.join(out_dir, "sweep.log"))
    cpu = run_cli.last_cpu_s
    doc_path = os.path.join(out_dir, "sweep.json")
    doc = load_json(doc_path) if code in (0, 1) and os.path.exists(doc_path) else None
    tail = [line for line in err.strip().splitlines() if line.strip()][-3:]
    return {"exit_code": code, "wall_s": wall, "cpu_s": cpu, "stderr_tail": tail, "doc": doc,
            "dir": out_dir}


def measured_wall_time(run):
    """(wall seconds, when measured) of a sweep. A rerun over existing results skips the finished
    cases (docs/sweeps.md, resuming) and takes no time; then the time of the run that computed
    them is reported, kept in DIR/timing.json."""
    path = os.path.join(run["dir"], "timing.json")
    log = os.path.join(run["dir"], "sweep.log")
    skipped = os.path.exists(log) and "already done, skipped" in open(log).read()
    if skipped and os.path.exists(path):
        t = load_json(path)
        run["cpu_s"] = t.get("cpu_s")
        return t["wall_s"], f"{t['measured']}, load {t['load_average'][0]:.1f} (reused)"
    now = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    with open(path, "w") as f:
        json.dump({"wall_s": run["wall_s"], "cpu_s": run["cpu_s"], "measured": now,
                   "load_average": os.getloadavg()}, f)
    return run["wall_s"], f"{now}, load {os.getloadavg()[0]:.1f}"


def fit_cli(exe, csv_path, x, y, model, json_path, extra=()):
    """`shellindent fit CSV --model M --x X --y Y --json OUT` (docs/fitting.md); returns the JSON
    document, with the exit code under "exit_code" (0 = converged)."""
    args = ["fit", csv_path, "--model", model, "--x", x, "--y", y, "--json", json_path]
    code, _, out, err = run_cli(exe, args + list(extra))
    if code == 2 or not os.path.exists(json_path):
        raise StudyError(f"shellindent fit {csv_path} {x} -> {y} ({model}): {err.strip()}")
    doc = load_json(json_path)
    doc["exit_code"] = code
    return doc


def fit_parameters(doc):
    """{name: value} of a fit JSON document."""
    return {p["name"]: p["value"] for p in doc["parameters"]}


def poly_value(coefficients, x):
    """a0 + a1 x + a2 x^2 + ..."""
    return sum(a * x ** k for k, a in enumerate(coefficients))


def poly_coefficients(fit_doc):
    """a0, a1, ... of a `shellindent fit --model poly` JSON document."""
    p = fit_parameters(fit_doc)
    return [p[f"a{k}"] for k in range(len(p))]


def load_json(path):
    with open(path) as f:
        return json.load(f)


def read_csv(path):
    """Rows of a CSV file with a header, numbers converted where they parse ('#' lines skipped)."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return [{k: to_number(v) for k, v in r.items()} for r in rows]


def write_csv(path, columns, rows):
    """Writes rows (dicts) with the given columns; floats with 10 significant digits."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(columns)
        for r in rows:
            w.writerow([fmt_cell(r.get(c)) for c in columns])


def fmt_cell(v):
    if v is None:
        return ""
    return f"{v:.10g}" if isinstance(v, float) else str(v)


def to_number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return text


def column(rows, name):
    return [r[name] for r in rows]


def interpolate(xs, ys, x):
    """Linear interpolation of y at x on the first bracketing interval of xs (the first passage
    of a depth, as path_grid.csv does); None outside the data."""
    for i in range(1, len(xs)):
        lo, hi = xs[i - 1], xs[i]
        if min(lo, hi) <= x <= max(lo, hi):
            t = 0.0 if hi == lo else (x - lo) / (hi - lo)
            return ys[i - 1] + t * (ys[i] - ys[i - 1])
    return None


def case_dirs(sweep_dir):
    """{case number: directory} of a sweep's cases (DIR/cases/NNN_<values>/)."""
    cases = os.path.join(sweep_dir, "cases")
    if not os.path.isdir(cases):
        return {}
    return {int(d.split("_")[0]): os.path.join(cases, d) for d in sorted(os.listdir(cases))
            if re.match(r"\d+_", d)}


def load_path(case_dir):
    """(path.csv rows, events list) of a run directory; ([], []) if the run wrote no path."""
    path_csv = os.path.join(case_dir, "path.csv")
    events = os.path.join(case_dir, "events.json")
    rows = read_csv(path_csv) if os.path.exists(path_csv) else []
    ev = load_json(events) if os.path.exists(events) else []
    return rows, ev.get("events", ev) if isinstance(ev, dict) else ev


def theta_of(layup):
    """theta (deg) of "[theta/-theta]2S" ([0/0]2S is theta = 0), else None."""
    m = re.fullmatch(r"\[(\d+)/-?(\d+)\]2S", str(layup).strip())
    return float(m.group(1)) if m and m.group(1) == m.group(2) else None


def clt_bending_stiffness(angles_deg, ply_t, ply=PAPER_PLY):
    """D11, D22, D12, D66 (N mm) of a laminate of equal plies (bottom first) by classical
    lamination theory: plane-stress reduced stiffnesses Q, transformed per ply, integrated
    z^2 dz (Jones, Mechanics of Composite Materials, 2nd ed., sec. 2.6 and 4.2). A hand check
    independent of the toolkit's section analysis."""
    e1, e2, g12, nu12 = ply["E1"], ply["E2"], ply["G12"], ply["nu12"]
    d = 1 - nu12 * nu12 * e2 / e1
    q11, q22, q12, q66 = e1 / d, e2 / d, nu12 * e2 / d, g12
    z0 = -len(angles_deg) * ply_t / 2
    out = {"D11": 0.0, "D22": 0.0, "D12": 0.0, "D66": 0.0}
    for i, a in enumerate(angles_deg):
        c, s = math.cos(math.radians(a)), math.sin(math.radians(a))
        qb = {"D11": q11 * c**4 + 2 * (q12 + 2 * q66) * s * s * c * c + q22 * s**4,
              "D22": q11 * s**4 + 2 * (q12 + 2 * q66) * s * s * c * c + q22 * c**4,
              "D12": (q11 + q22 - 4 * q66) * s * s * c * c + q12 * (s**4 + c**4),
              "D66": (q11 + q22 - 2 * q12 - 2 * q66) * s * s * c * c + q66 * (s**4 + c**4)}
        za, zb = z0 + i * ply_t, z0 + (i + 1) * ply_t
        for k in out:
            out[k] += qb[k] * (zb**3 - za**3) / 3
    return out


def effective_bending_stiffness(d):
    """(eta, D_eff) with eta = (D12 + 2 D66) / sqrt(D11 D22) and D_eff = sqrt(D11 D22 (1+eta)/2),
    the isotropic-equivalent stiffness of an orthotropic plate under a point load (Olsson 2002,
    J. Sandwich Struct. Mater. 4, 3-29; exact for eta = 1, i.e. an isotropic plate)."""
    eta = (d["D12"] + 2 * d["D66"]) / math.sqrt(d["D11"] * d["D22"])
    return eta, math.sqrt(d["D11"] * d["D22"] * (1 + eta) / 2)
