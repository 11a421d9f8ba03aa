#!/usr/bin/python3
"""Issue 19's paired peer benchmark: CalculiX (expanded S8R shells) and shellindent on one cap.

  /usr/bin/python3 bench/calculix/peer_cap.py [--build build] [--depths 2,10]
      [--ccx-levels 0,1,2,3] [--si-sizes 1.2,0.85,0.6,0.42,0.3,0.21] [--out results] [--reuse]
  /usr/bin/python3 bench/calculix/peer_cap.py --self-test   (the analysis on closed forms)

The case: the paper's cap, [0]8, clamped, quarter model, 12.7 mm rigid sphere on the outer face,
frictionless, geometrically nonlinear, travel 0 -> 2 mm and 0 -> 10 mm. Each code runs its own
mesh sequence (CalculiX: the expanded-shell form, one C3D20R through the thickness on an O-grid
with h = 1.2 / 2^L mm at the apex, exactly what ccx makes of S8R but with exact symmetry planes
and clamped edge face (decks.shell_deck: why not the S8R keyword);
shellindent: mesh.size_apex, the rest of the case file at its defaults, contact.local none),
both single-threaded under `nice -n 19`, interleaved in one invocation (paired: the same
machine load for both). CPU time is the child's getrusage (user + system).

For each run: the force at 0.25, 0.5, 0.75 and 1.5 mm of apex mid-surface deflection (cubic
interpolation through the four nearest printed points), after cutting the run at its first
artefact (first_artefact). Each code's converged force is the Richardson extrapolation of its
three finest meshes where they are in the asymptotic range, else its finest mesh with the three
meshes' spread as a band; each mesh's error is its largest relative difference from that limit,
plus the band, over the four deflections. The cheapest mesh within 1 % is each code's entry and
the CPU ratio of the two entries is printed; with no CalculiX mesh within 1 %, a lower bound
(cost_bound) under a stated assumption.

Writes OUT/peer_cap_D{depth}.csv (one row per run) and OUT/peer_cap_summary.csv.
"""
from __future__ import annotations

import argparse
import csv
import json
import os
import re
import resource
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(HERE))
import ccxdat  # noqa: E402
import decks  # noqa: E402
import run_ccx  # noqa: E402

TARGETS = [0.25, 0.5, 0.75, 1.5]  # mm of apex deflection
WORK = HERE / "work" / "peer"


def child_cpu(cmd, cwd=None, env=None, log=None) -> tuple[float, float, int]:
    """Runs cmd; (CPU s from getrusage of the child, wall s, exit code)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.time()
    with open(log, "w") as f:
        rc = subprocess.run(cmd, cwd=cwd, env=env, stdout=f, stderr=subprocess.STDOUT).returncode
    wall = time.time() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), wall, rc


def interp4(x: np.ndarray, y: np.ndarray, x0: float) -> float:
    """Cubic through the four points nearest x0 (x increasing)."""
    if len(x) < 4 or x0 < x.min() or x0 > x.max():
        return float("nan")
    k = np.argsort(abs(x - x0))[:4]
    xs, ys = x[k], y[k]
    out = 0.0
    for i in range(4):
        li = 1.0
        for j in range(4):
            if j != i:
                li *= (x0 - xs[j]) / (xs[i] - xs[j])
        out += li * ys[i]
    return float(out)


def ccx_increment_max(depth: float) -> float:
    """The largest increment, a fraction of the step: 0.125 mm of travel at 2 mm, 0.25 mm at
    10 mm. Every converged increment is printed (no *TIME POINTS: with time points ccx 2.20
    met one after a cut-back with an increment of size zero and stopped, on decimal and on
    binary fractions of the step alike), so this also bounds the spacing that interp4 reads."""
    return min(1 / 16, 0.25 / depth)


def run_ccx_shell(level: int, depth: float) -> dict:
    """The expanded-shell form: one C3D20R through the thickness on the shell's O-grid (what
    CalculiX makes of S8R, written out so that the quarter model's symmetry planes and the
    clamped edge face are exact; decks.shell_deck says why the S8R keyword model is not used)."""
    mesh = decks.Mesh(level=level, single_layer=True, **run_ccx.SHELL_MESH)
    case = decks.Case(kind="cap", layup="[0]8", symmetry="quarter", nlgeom=True, travel=depth,
                      points=[], mesh=mesh, slave_radius=14.0, indenter_extent=14.0,
                      inc0=1 / 128, inc_max=ccx_increment_max(depth))
    deck = decks.solid_deck(case)
    work = run_dir("ccx", level, depth)
    work.mkdir(parents=True, exist_ok=True)
    (work / "job.inp").write_text(deck.text)
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1",
               CCX_NPROC_STIFFNESS="1", CCX_NPROC_RESULTS="1")
    cpu, wall, rc = child_cpu(["nice", "-n", "19", run_ccx.ensure_ccx(), "-i", "job"],
                              cwd=work, env=env, log=work / "ccx.log")
    dat = ccxdat.read_dat(str(work / "job.dat")) if (work / "job.dat").exists() else {}
    w, f, travel = [0.0], [0.0], [0.0]
    for t in sorted(dat.get(("rf_total", "NIND"), {})):
        f.append(-dat[("rf_total", "NIND")][t][2] * 4)
        w.append(-dat[("u", "NAPEX")][t][0, 3])
        travel.append(t * depth)
    log = (work / "ccx.log").read_text(errors="replace")
    ok = rc == 0 and "Job finished" in log
    reached = max(dat.get(("rf_total", "NIND"), {0.0: 0}).keys()) * depth
    return dict(code="calculix", mesh=f"C3D20R-1 L{level} h={mesh.h:g}mm", h_mm=mesh.h,
                unknowns=deck.info["dofs"], cpu_s=cpu, wall_s=wall,
                status="ok" if ok and reached >= depth - 1e-6 else f"failed at {reached:g} mm",
                w=np.array(w), f=np.array(f), travel=np.array(travel))


def run_si(exe: str, size: float, depth: float) -> dict:
    work = run_dir("si", size, depth)
    work.mkdir(parents=True, exist_ok=True)
    case = work / "case.yaml"
    case.write_text("material: paper-carbon-epoxy\n"
                    "laminate: {layup: \"[0]8\", ply_thickness: 0.475 mm, reference: mid}\n"
                    f"mesh: {{size_apex: {size:g} mm, symmetry: quarter}}\n"
                    f"path: {{depth_max: {depth:g} mm}}\n"
                    "output: {vtu_every: 0, formats: [csv]}\n")
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    cpu, wall, rc = child_cpu(["nice", "-n", "19", exe, "run", str(case), "--out",
                               str(work / "out"), "--threads", "1"], env=env,
                              log=work / "run.log")
    log = (work / "run.log").read_text(errors="replace")
    m = re.search(r"(\d+) shell unknowns", log)
    grid = work / "out" / "path_grid.csv"
    w, f, travel = np.array([0.0]), np.array([0.0]), np.array([0.0])
    if grid.exists():
        with open(grid) as fh:
            rows = list(csv.DictReader(fh))
        w = np.array([float(r["apex_w_mm"]) for r in rows])
        f = np.array([float(r["force_N"]) for r in rows])
        travel = np.array([float(r["depth_mm"]) for r in rows])
    return dict(code="shellindent", mesh=f"MITC4 size_apex={size:g}mm", h_mm=size,
                unknowns=int(m.group(1)) if m else -1, cpu_s=cpu, wall_s=wall,
                status="ok" if rc == 0 else f"failed (rc {rc})", w=w, f=f, travel=travel)


def first_artefact(travel: np.ndarray, f: np.ndarray) -> int | None:
    """Index of the first printed point after which the force's slope against the travel falls
    below half of the previous segment's: the cap stiffens as the contact grows, so such a fall
    is no mechanics but a solver's failure (ccx 2.20 accepts an increment after 60 contact
    iterations without convergence and goes on on a softer path; seen at 0.96 mm on level 2).
    The first 0.1 mm (the contact's start) is not judged."""
    for i in range(2, len(f) - 1):
        if travel[i] < 0.1:
            continue
        before = (f[i] - f[i - 1]) / (travel[i] - travel[i - 1])
        after = (f[i + 1] - f[i]) / (travel[i + 1] - travel[i])
        if before > 0 and after < 0.5 * before:
            return i
    return None


def drop_artefact(r: dict) -> None:
    """Cuts a run's curve at its first artefact (first_artefact) and says so in its status: the
    deflections beyond the cut have no force (interp4 gives NaN there), those before it count."""
    i = first_artefact(r["travel"], r["f"])
    if i is None:
        return
    r["status"] = f"ok, cut at an artefact at {r['travel'][i]:.3g} mm of travel"
    for key in ("w", "f", "travel"):
        r[key] = r[key][: i + 1]


def usable(r: dict) -> bool:
    """Finished, possibly cut at an artefact (drop_artefact)."""
    return r["status"].startswith("ok")


def run_dir(kind: str, v: float, depth: float) -> Path:
    return WORK / (f"ccx_D{depth:g}_L{int(v)}" if kind == "ccx" else f"si_D{depth:g}_s{v:g}")


def save_run(kind: str, v: float, depth: float, r: dict) -> None:
    """The run's record (its curve and cost) beside its output, for --reuse."""
    rec = {k: (val.tolist() if isinstance(val, np.ndarray) else val) for k, val in r.items()}
    (run_dir(kind, v, depth) / "run.json").write_text(json.dumps(rec))


def load_run(kind: str, v: float, depth: float) -> dict | None:
    """A run recorded by an earlier invocation (its CPU time is the one measured then)."""
    path = run_dir(kind, v, depth) / "run.json"
    if not path.exists():
        return None
    r = json.loads(path.read_text())
    for key in ("w", "f", "travel"):
        r[key] = np.array(r[key])
    return r


def richardson(h: list[float], f: list[float]) -> tuple[float, float] | None:
    """(limit, order p) of f(h) = f* + C h^p through three runs, h decreasing, for any ratios of
    the sizes: d2/d1 = (h2^p - h1^p) / (h1^p - h0^p) is monotone in p and solved by bisection.
    None outside the asymptotic range: the differences change sign or do not shrink."""
    d1, d2 = f[1] - f[0], f[2] - f[1]
    if not (d1 * d2 > 0 and abs(d2) < abs(d1)):
        return None

    def ratio(p):
        return (h[2] ** p - h[1] ** p) / (h[1] ** p - h[0] ** p)

    lo, hi = 0.05, 12.0
    if not ratio(hi) < d2 / d1 < ratio(lo):
        return None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if ratio(mid) > d2 / d1 else (lo, mid)
    p = 0.5 * (lo + hi)
    c = d2 / (h[2] ** p - h[1] ** p)
    return f[2] - c * h[2] ** p, p


def converged(runs: list[dict]) -> tuple[np.ndarray, np.ndarray, str]:
    """Each target's limit and its band: Richardson through the three finest runs (band 0); where
    they are not in the asymptotic range, the finest run with the spread of the three as its band
    (a run's error then counts the band: the finest cannot certify itself beyond its spread)."""
    ok = sorted([r for r in runs if usable(r)], key=lambda r: -r["h_mm"])
    fine = ok[-3:]
    lim, band, how = [], [], []
    for k in range(len(TARGETS)):
        f = [r["F"][k] for r in fine]
        if len(fine) < 3 or not all(np.isfinite(f)):
            lim.append(float("nan"))
            band.append(float("nan"))
            how.append("fewer than three forces")
            continue
        fit = richardson([r["h_mm"] for r in fine], f)
        lim.append(fit[0] if fit else f[2])
        band.append(0.0 if fit else max(abs(f[1] - f[0]), abs(f[2] - f[1])))
        how.append(f"Richardson p={fit[1]:.2f}" if fit else
                   f"finest, band {100 * band[-1] / abs(f[2]):.2g} % (not asymptotic)")
    return np.array(lim), np.array(band), "; ".join(how)


def cost_bound(rs: list[dict]) -> dict | None:
    """Without a limit: the cheapest run that is not shown to be more than 1 % off, assuming the
    sequence goes on converging monotonically beyond its finest run. A coarser run is shown off
    when, at some target, the forces from it to the finest are monotone in h and it differs
    from the finest by more than 1 % (the limit then lies beyond the finest). The mesh within
    1 % costs at least this run's CPU time: a lower bound on that code's entry."""
    ok = sorted([r for r in rs if usable(r)], key=lambda r: -r["h_mm"])
    if not ok:
        return None
    finest = ok[-1]

    def shown_off(i):
        for k in range(len(TARGETS)):
            seq = [r["F"][k] for r in ok[i:]]
            steps = np.diff(seq)
            if np.all(steps > 0) or np.all(steps < 0):
                if abs(seq[0] / finest["F"][k] - 1) > 0.01:
                    return True
        return False

    open_runs = [r for i, r in enumerate(ok[:-1]) if not shown_off(i)] + [finest]
    return min(open_runs, key=lambda r: r["cpu_s"])


def self_test() -> int:
    """The analysis's pure parts against closed forms, and what they must not report."""
    h = [1.2, 0.85, 0.6]  # not a constant ratio
    lim, p = richardson(h, [5 + 3 * x ** 2 for x in h])
    assert abs(lim - 5) < 1e-9 and abs(p - 2) < 1e-6, (lim, p)
    lim, p = richardson(h, [5 - 0.4 * x ** 1.3 for x in h])
    assert abs(lim - 5) < 1e-9 and abs(p - 1.3) < 1e-6, (lim, p)
    assert richardson(h, [3573, 3577, 3396]) is None  # a change of sign
    assert richardson(h, [10, 9, 7]) is None  # growing differences
    travel = np.linspace(0, 2, 17)
    hardening = 1e4 * travel ** 1.5
    assert first_artefact(travel, hardening) is None  # a stiffening curve: nothing
    flat = hardening.copy()
    flat[9:] -= 0.9 * (hardening[9:] - hardening[8])  # the slope falls by 90 % after point 8
    assert first_artefact(travel, flat) == 8, first_artefact(travel, flat)
    # the bound: a monotone sequence 3 % apart shows the coarse run off; a flat one does not
    runs = [dict(status="ok", h_mm=hh, cpu_s=c, F=[f] * len(TARGETS))
            for hh, c, f in [(1.2, 1.0, 103.0), (0.6, 5.0, 100.0)]]
    assert cost_bound(runs)["cpu_s"] == 5.0
    runs[0]["F"] = [100.5] * len(TARGETS)
    assert cost_bound(runs)["cpu_s"] == 1.0
    print("peer_cap: self-test passed")
    return 0


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--build", default=str(ROOT / "build"))
    p.add_argument("--depths", default="2,10")
    p.add_argument("--ccx-levels", default="0,1,2,3")
    p.add_argument("--si-sizes", default="1.2,0.85,0.6,0.42,0.3,0.21")
    p.add_argument("--out", default=str(HERE / "results"))
    p.add_argument("--reuse", action="store_true",
                   help="read runs recorded by an earlier invocation (work/peer/*/run.json) "
                        "instead of running them again: their CPU times are the earlier ones")
    p.add_argument("--self-test", action="store_true",
                   help="check the analysis (Richardson, artefacts, bound) on closed forms; no runs")
    a = p.parse_args(argv)
    if a.self_test:
        return self_test()
    exe = str(Path(a.build) / "shellindent")
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    summary = []
    for depth in [float(d) for d in a.depths.split(",")]:
        levels = [int(v) for v in a.ccx_levels.split(",")]
        sizes = [float(v) for v in a.si_sizes.split(",")]
        jobs = []
        for k in range(max(len(levels), len(sizes))):  # interleaved: paired under one load
            if k < len(sizes):
                jobs.append(("si", sizes[k]))
            if k < len(levels):
                jobs.append(("ccx", levels[k]))
        runs = {"calculix": [], "shellindent": []}
        for kind, v in jobs:
            r = load_run(kind, v, depth) if a.reuse else None
            if r is None:
                r = run_ccx_shell(v, depth) if kind == "ccx" else run_si(exe, v, depth)
                save_run(kind, v, depth, r)
            drop_artefact(r)
            order = np.argsort(r["w"])
            r["F"] = [interp4(r["w"][order], r["f"][order], t) for t in TARGETS]
            runs[r["code"]].append(r)
            print(f"D={depth:g} {r['code']:11s} {r['mesh']:26s} {r['unknowns']:8d} unknowns "
                  f"{r['cpu_s']:8.1f} s CPU {r['status']}", file=sys.stderr)
        rows = []
        best, bound = {}, {}
        for code, rs in runs.items():
            lim, band, how = converged(rs)
            for r in rs:
                err = max(abs(f / l - 1) + b / abs(l) for f, l, b in zip(r["F"], lim, band)) \
                    if usable(r) else float("nan")
                r["err"] = err
                rows.append(dict(depth_max_mm=depth, code=code, mesh=r["mesh"], h_mm=r["h_mm"],
                                 unknowns=r["unknowns"], cpu_s=r["cpu_s"], wall_s=r["wall_s"],
                                 status=r["status"],
                                 **{f"F_at_w{t:g}_N": f for t, f in zip(TARGETS, r["F"])},
                                 max_err_pct=100 * err, limit=how))
            within = [r for r in rs if usable(r) and r["err"] <= 0.01]
            best[code] = min(within, key=lambda r: r["cpu_s"]) if within else None
            bound[code] = None if best[code] else cost_bound(rs)
            rows.append(dict(depth_max_mm=depth, code=code, mesh="converged", h_mm=0,
                             unknowns=0, cpu_s=float("nan"), wall_s=float("nan"), status=how,
                             **{f"F_at_w{t:g}_N": f for t, f in zip(TARGETS, lim)},
                             max_err_pct=0.0, limit=how))
        with open(out / f"peer_cap_D{depth:g}.csv", "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]))
            w.writeheader()
            for r in rows:
                w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
        c, s = best["calculix"], best["shellindent"]
        cb = bound["calculix"]
        # A measured ratio needs both entries; a CalculiX sequence outside its asymptotic range
        # gives a lower bound (cost_bound: its mesh within 1 % is at least as costly).
        if c and s:
            ratio, kind = c["cpu_s"] / s["cpu_s"], "measured"
        elif cb and s:
            ratio, kind = cb["cpu_s"] / s["cpu_s"], "lower bound"
        else:
            ratio, kind = float("nan"), "none"
        summary.append(dict(depth_max_mm=depth,
                            calculix_mesh=c["mesh"] if c else "none within 1 %",
                            calculix_cpu_s=c["cpu_s"] if c else float("nan"),
                            calculix_err_pct=100 * c["err"] if c else float("nan"),
                            calculix_bound_mesh=cb["mesh"] if cb else "",
                            calculix_bound_cpu_s=cb["cpu_s"] if cb else float("nan"),
                            shellindent_mesh=s["mesh"] if s else "none within 1 %",
                            shellindent_cpu_s=s["cpu_s"] if s else float("nan"),
                            shellindent_err_pct=100 * s["err"] if s else float("nan"),
                            cpu_ratio=ratio, ratio_kind=kind,
                            date=time.strftime("%Y-%m-%d %H:%M"),
                            load=open("/proc/loadavg").read().split()[0]))
        ccx_text = (f"{c['mesh']} {c['cpu_s']:.1f} s" if c else
                    f"none within 1 %, at least {cb['mesh']} {cb['cpu_s']:.1f} s" if cb else "none")
        si_text = f"{s['mesh']} {s['cpu_s']:.2f} s" if s else "none within 1 %"
        print(f"0 -> {depth:g} mm: CalculiX {ccx_text}, shellindent {si_text}: "
              f"CPU ratio {'>= ' if kind == 'lower bound' else ''}{ratio:.1f} ({kind})")
    old = out / "peer_cap_summary.csv"  # keep the other depths' lines of an earlier run
    if old.exists():
        done = {float(r["depth_max_mm"]) for r in summary}
        with open(old) as f:
            summary = [r for r in csv.DictReader(f) if float(r["depth_max_mm"]) not in done] + summary
        summary.sort(key=lambda r: float(r["depth_max_mm"]))
    with open(out / "peer_cap_summary.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(summary[0]))
        w.writeheader()
        for r in summary:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    (out / "peer_cap_summary.json").write_text(json.dumps(summary, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
