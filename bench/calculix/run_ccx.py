#!/usr/bin/python3
"""Generate one CalculiX reference model, run it, and record its results and cost.

  /usr/bin/python3 bench/calculix/run_ccx.py --kind cap --layup "[0]8" --level 1 [--nlgeom]
      [--travel 1.0] [--penalty 1e7] [--symmetry quarter] [--tag NAME]

Writes bench/calculix/work/TAG/ (deck, ccx output, log: not committed) and
bench/calculix/results/TAG.csv (one row per printed travel), and appends one line to
bench/calculix/results/runs.csv (the model's size, CPU time, peak memory, increments).
ccx runs single-threaded (OMP_NUM_THREADS=1) under `nice -n 19`; CalculiX is installed from
Debian (calculix-ccx) when missing.
"""
from __future__ import annotations

import argparse
import csv
import json
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import ccxdat  # noqa: E402
import decks  # noqa: E402

RESULTS = HERE / "results"
WORK = HERE / "work"
RUN_FIELDS = ["tag", "kind", "layup", "symmetry", "nlgeom", "level", "h_mm", "layers", "nodes",
              "elements", "dofs", "penalty", "travel_mm", "status", "increments", "iterations",
              "cpu_s", "wall_s", "maxrss_MB", "date"]


def ensure_ccx() -> str:
    """The ccx executable; installs Debian's calculix-ccx if it is missing."""
    exe = shutil.which("ccx")
    if exe:
        return exe
    sudo = [] if os.geteuid() == 0 else ["sudo"]
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    print("run_ccx: installing calculix-ccx (Debian package)", file=sys.stderr)
    subprocess.run(sudo + ["apt-get", "install", "-y", "--no-install-recommends",
                           "calculix-ccx"], check=False, env=env)
    if not shutil.which("ccx"):
        subprocess.run(sudo + ["apt-get", "update", "-qq"], check=True, env=env)
        subprocess.run(sudo + ["apt-get", "install", "-y", "--no-install-recommends",
                               "calculix-ccx"], check=True, env=env)
    return shutil.which("ccx")


def parse_time_v(path: Path) -> dict:
    text = path.read_text()

    def grab(label):
        m = re.search(re.escape(label) + r":\s*(\S+)", text)
        return m.group(1) if m else "nan"

    wall = grab("Elapsed (wall clock) time (h:mm:ss or m:ss)")
    parts = [float(p) for p in wall.split(":")] if wall != "nan" else [float("nan")]
    wall_s = sum(p * 60 ** k for k, p in enumerate(reversed(parts)))
    return dict(cpu_s=float(grab("User time (seconds)")) + float(grab("System time (seconds)")),
                wall_s=wall_s, maxrss_MB=float(grab("Maximum resident set size (kbytes)")) / 1024)


def run_deck(deck_text: str, info: dict, tag: str, keep: bool = True) -> tuple[dict, Path]:
    """Runs ccx on the deck in WORK/tag; returns the cost record and the work directory."""
    ccx = ensure_ccx()
    work = WORK / tag
    work.mkdir(parents=True, exist_ok=True)
    (work / "job.inp").write_text(deck_text)
    (work / "info.json").write_text(json.dumps(info))
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1",
               CCX_NPROC_STIFFNESS="1", CCX_NPROC_RESULTS="1")
    with open(work / "ccx.log", "w") as log:
        proc = subprocess.run(["nice", "-n", "19", "/usr/bin/time", "-v", "-o", "time.txt",
                               ccx, "-i", "job"], cwd=work, stdout=log, stderr=subprocess.STDOUT,
                              env=env)
    cost = parse_time_v(work / "time.txt")
    log_text = (work / "ccx.log").read_text(errors="replace")
    cost["increments"] = len(re.findall(r"^\s*increment \d+ attempt", log_text, re.M))
    cost["iterations"] = len(re.findall(r"^\s*iteration \d+", log_text, re.M)) + \
        cost["increments"]
    ok = proc.returncode == 0 and "Job finished" in log_text and "*ERROR" not in log_text
    cost["status"] = "ok" if ok else f"failed (rc {proc.returncode})"
    if not keep:
        for f in work.glob("job.*"):
            if f.suffix not in (".dat", ".inp"):
                f.unlink()
    return cost, work


def write_rows(path: Path, rows: list[dict]):
    if not rows:
        return
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.8g}" if isinstance(v, float) else v) for k, v in r.items()})


def append_run(record: dict):
    RESULTS.mkdir(exist_ok=True)
    path = RESULTS / "runs.csv"
    new = not path.exists()
    with open(path, "a", newline="") as f:
        w = csv.DictWriter(f, fieldnames=RUN_FIELDS, extrasaction="ignore")
        if new:
            w.writeheader()
        w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in record.items()})


SHELL_MESH = dict(h0=1.2, b=2.4, fine_radius=6.0, growth=0.3, max_factor=4.0, blend=4.8,
                  tie_radius=None)


def case_from_args(a) -> decks.Case:
    if a.kind in ("shell", "expanded"):
        mesh = decks.Mesh(level=a.level, single_layer=a.kind == "expanded", **SHELL_MESH)
    else:
        mesh = decks.Mesh(level=a.level, top_split=a.top_split, outer_level=a.outer_level)
    if a.kind == "block":
        # the cap's contact zone (b, h, nested levels) and a steeper far field: the block
        # must be large against the contact (50 mm) and stays affordable only if graded fast
        mesh.fine_radius, mesh.growth, mesh.max_factor = 1.5, 1.0, a.block_max_factor
        mesh.tie_radius = None
    if a.no_tie:
        mesh.tie_radius = None
    points = [float(p) for p in a.points.split(",")] if a.points else None
    case = decks.Case(kind="cap" if a.kind == "expanded" else a.kind, layup=a.layup, symmetry=a.symmetry, nlgeom=a.nlgeom,
                      travel=a.travel, penalty=a.penalty, mesh=mesh, solver=a.solver,
                      block_depth=a.block_size, block_radius=a.block_size,
                      slave_radius=a.slave_radius, indenter_extent=a.indenter_extent,
                      inc0=a.inc0, inc_max=a.inc_max)
    if points:
        case.points = points
    return case


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--kind", choices=["cap", "block", "shell", "expanded"], default="cap",
                   help="cap: the C3D20R solid; block: the Hertz block; shell: S8R (full model "
                        "only); expanded: one C3D20R\nthrough the thickness on the shell mesh "
                        "(what ccx makes of S8R), quarter models allowed")
    p.add_argument("--layup", choices=list(decks.LAYUPS), default="[0]8")
    p.add_argument("--symmetry", choices=["quarter", "half", "full"], default="quarter")
    p.add_argument("--level", type=int, default=0)
    p.add_argument("--top-split", type=int, default=None)
    p.add_argument("--outer-level", type=int, default=0, help="refinement of the outer zone")
    p.add_argument("--no-tie", action="store_true", help="one O-grid to the edge")
    p.add_argument("--nlgeom", action="store_true")
    p.add_argument("--travel", type=float, default=1.0)
    p.add_argument("--points", default=None, help="comma-separated travels to print (mm)")
    p.add_argument("--penalty", type=float, default=1e7, help="MPa/mm")
    p.add_argument("--solver", default="SPOOLES")
    p.add_argument("--slave-radius", type=float, default=5.0)
    p.add_argument("--indenter-extent", type=float, default=5.0)
    p.add_argument("--block-size", type=float, default=50.0)
    p.add_argument("--block-max-factor", type=float, default=40.0)
    p.add_argument("--inc0", type=float, default=0.02)
    p.add_argument("--inc-max", type=float, default=0.05)
    p.add_argument("--tag", default=None)
    p.add_argument("--dry", action="store_true", help="write the deck only")
    a = p.parse_args(argv)
    case = case_from_args(a)
    tag = a.tag or "{}_{}_{}_{}_L{}".format(
        a.kind, decks.layup_slug(a.layup), a.symmetry,
        "nl" if a.nlgeom else "lin", a.level)
    t0 = time.time()
    deck = decks.shell_deck(case) if a.kind == "shell" else decks.solid_deck(case)
    print(f"{tag}: {deck.info['nodes']} nodes, {deck.info['elements']} elements, "
          f"{deck.info['layers']} layers, deck in {time.time() - t0:.1f} s", file=sys.stderr)
    if a.dry:
        (WORK / tag).mkdir(parents=True, exist_ok=True)
        (WORK / tag / "job.inp").write_text(deck.text)
        return 0
    cost, work = run_deck(deck.text, deck.info, tag)
    rows = []
    if (work / "job.dat").exists():
        rows = ccxdat.results(ccxdat.read_dat(str(work / "job.dat")), deck.info)
    RESULTS.mkdir(exist_ok=True)
    write_rows(RESULTS / f"{tag}.csv", rows)
    info = deck.info
    record = dict(tag=tag, kind=info["kind"], layup=info["layup"], symmetry=info["symmetry"],
                  nlgeom=int(info["nlgeom"]), level=info["level"], h_mm=info["h"],
                  layers=info["layers"], nodes=info["nodes"], elements=info["elements"],
                  dofs=info["dofs"], penalty=a.penalty, travel_mm=max(
                      (r["travel_mm"] for r in rows), default=0.0),
                  date=time.strftime("%Y-%m-%d %H:%M"), **cost)
    append_run(record)
    print(json.dumps(record), file=sys.stderr)
    for r in rows:
        print(" ".join(f"{k}={v:.5g}" for k, v in r.items()))
    return 0 if cost["status"] == "ok" else 1


if __name__ == "__main__":
    sys.exit(main())
