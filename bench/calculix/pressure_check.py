#!/usr/bin/python3
"""The shell against the solid under a load with no local part (issue 20, docs/theory/
local-indentation.md 6.7): a uniform pressure on the paper's cap, linear.

  /usr/bin/python3 bench/calculix/pressure_check.py [--build build] [--levels 0,1,2]
      [--sizes 1,0.5,0.25] [--layup "[0]8"] [--pressure 0.1] [--tie] [--patch A]

Under the indenter shellindent's apex mid-surface deflection at equal force differs from the
solid's by two parts that the contact comparison cannot separate: the shell's short-wave
(Reissner-Mindlin) compliance under a patch a fifth of the thickness wide, and whatever else
differs between a shell and a solid cap (the clamped edge, the transverse normal strain). A
pressure over the whole cap has no short-wave part: the ratio of the apex mid-surface
deflections measures the second alone. The solid's face pressure carries the same resultant as
the shell's mid-surface pressure (decks._pressure_deck).

The solid is the C3D20R cap of run_ccx.py as one O-grid to the edge (refined everywhere with the
level: a convergent sequence); --tie uses the contact reference's meshes instead (a fine zone
tied at 4 mm to a fixed outer zone), whose outer zone this load exercises. One linear increment
each (level 2: 94,000 nodes, about 6 min and 4 GB). shellindent: `static` at the given apex
sizes. Prints each model's apex mid-surface deflection and writes
results/pressure_check_LAYUP.csv.

--patch A replaces the uniform pressure by Hertz's pressure p0 (1 - r^2/A^2)^0.5 on the plan disc
r < A (mm) carrying 1000 N (the whole cap): the contact's load without the contact, whose short-
wave part the shell's Reissner-Mindlin shear carries. The solid takes one value per outer face (at
its centroid), the shell nodal forces p(r_i) times each node's tributary area (a quarter of each
of its elements' areas, from a first run's mesh), both scaled to 1000 N. Writes
results/patch_check_LAYUP_A.csv.
"""
from __future__ import annotations

import argparse
import csv
import re
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import ccxdat  # noqa: E402
import numpy as np  # noqa: E402
import decks  # noqa: E402
import run_ccx  # noqa: E402

RESULTS = HERE / "results"
WORK = HERE / "work" / "pressure"


PATCH_FORCE = 1000.0  # N on the whole cap under --patch


def solid_apex(layup: str, level: int, pressure: float, tie: bool, patch: float = 0.0) -> dict:
    """The solid cap's apex mid-surface deflection (mm, positive inwards). The reaction printed
    is the clamped nodes' (the loads on those nodes go to the support without it)."""
    mesh = decks.Mesh(level=level)
    if not tie:
        mesh.tie_radius = None
    case = decks.Case(kind="cap", layup=layup, symmetry="quarter", points=[],
                      pressure=PATCH_FORCE if patch else pressure, patch_radius=patch, mesh=mesh)
    deck = decks.solid_deck(case)
    tag = (f"pressure_{decks.layup_slug(layup)}_L{level}" + ("_tie" if tie else "")
           + (f"_patch{patch:g}" if patch else ""))
    cost, work = run_ccx.run_deck(deck.text, deck.info, tag)
    if cost["status"] != "ok":
        raise SystemExit(f"{tag}: ccx {cost['status']}, see {work}/ccx.log")
    dat = ccxdat.read_dat(str(work / "job.dat"))
    t = max(dat[("u", "NAPEX")])
    w = -float(dat[("u", "NAPEX")][t][0][3])
    reaction = abs(float(dat[("rf_total", "NFIX")][t][2])) * deck.info["factor"]
    return dict(model=f"C3D20R level {level}" + (" tied" if tie else ""), nodes=deck.info["nodes"], apex_w_mm=w,
                reaction_N=reaction, cpu_s=cost.get("cpu_s", 0.0))


def shell_case(layup: str, size: float, load: str) -> str:
    return (f"material: paper-carbon-epoxy\n"
            f"laminate: {{layup: \"{layup}\", ply_thickness: 0.475 mm, reference: mid}}\n"
            f"shell: {{type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: clamped}}\n"
            f"mesh: {{element: mitc4, size_apex: {size:g} mm, size_edge: {2 * size:g} mm, "
            f"refine_radius: 13 mm, symmetry: quarter}}\n"
            f"kinematics: linear\n"
            + load + "output: {vtu_every: 0}\n")


def vtu_mesh(path: Path):
    """Points (N, 3) and quadrangles (E, 4) of a shellindent VTU file: ASCII, or raw appended
    data (large meshes) with a UInt64 byte count before each array."""
    data = path.read_bytes()
    def array(pattern, dtype):
        tag = re.search(rb"<DataArray[^>]*" + pattern + rb"[^>]*>", data)
        offset = re.search(rb'offset="(\d+)"', tag.group(0))
        if offset is None:  # ASCII: the values up to the closing tag
            end = data.index(b"</DataArray>", tag.end())
            return np.array(data[tag.end():end].split(), float).astype(dtype)
        start = data.index(b"_", data.index(b"<AppendedData")) + 1 + int(offset.group(1))
        size = int(np.frombuffer(data, np.uint64, 1, start)[0])
        return np.frombuffer(data, dtype, size // np.dtype(dtype).itemsize, start + 8)
    points = array(rb'NumberOfComponents="3" format="(?:ascii|appended)"(?: offset="0")?', float)
    return points.reshape(-1, 3), array(rb'Name="connectivity"', np.int64).reshape(-1, 4)


def patch_loads(points: np.ndarray, quads: np.ndarray, a: float) -> str:
    """The case's `loads`: Hertz's pressure at each node inside the disc r < a times its
    tributary area (whole-shell forces: a node on one symmetry plane stands for two quarter
    tributaries, the apex for four), scaled to PATCH_FORCE."""
    area = np.zeros(len(points))
    for q in quads:
        x, y = points[q, 0], points[q, 1]
        area[q] += 0.125 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
    r2 = (points[:, 0] ** 2 + points[:, 1] ** 2) / a ** 2
    on_x, on_y = np.abs(points[:, 0]) < 1e-9, np.abs(points[:, 1]) < 1e-9
    copies = np.where(on_x, 1, 2) * np.where(on_y, 1, 2)  # mirror images in the whole cap
    inside = np.nonzero(r2 < 1.0)[0]
    whole = np.sqrt(1.0 - r2[inside]) * area[inside] * 4.0 / copies[inside]
    whole *= PATCH_FORCE / float(np.dot(whole, copies[inside]))
    return "loads:\n" + "".join(
        f"  - {{type: point, at: [{x:.9g} mm, {y:.9g} mm, {z:.9g} mm], "
        f"force: [0 N, 0 N, {-f:.12g} N]}}\n"
        for (x, y, z), f in zip(points[inside], whole)) + "load: {steps: 1}\n"


def run_static(exe: str, name: str, text: str) -> Path:
    WORK.mkdir(parents=True, exist_ok=True)
    case = WORK / f"{name}.yaml"
    case.write_text(text)
    out = WORK / name
    proc = subprocess.run([exe, "static", str(case), "--out", str(out)], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        raise SystemExit(f"{name}: shellindent failed: {proc.stderr[-400:]}")
    return out


def shell_apex(exe: str, layup: str, size: float, pressure: float, patch: float = 0.0) -> dict:
    name = f"shell_{decks.layup_slug(layup)}_{size:g}"
    uniform = f"load: {{type: pressure, pressure: {pressure:g} MPa, steps: 1}}\n"
    out = run_static(exe, name, shell_case(layup, size, uniform))
    if patch:
        points, quads = vtu_mesh(out / "static.vtu")
        name += f"_patch{patch:g}"
        out = run_static(exe, name, shell_case(layup, size, patch_loads(points, quads, patch)))
    with open(out / "static.csv") as f:
        last = list(csv.DictReader(f))[-1]
    return dict(model=f"shellindent MITC4 {size:g} mm", nodes=0,
                apex_w_mm=float(last["apex_deflection_mm"]),
                reaction_N=float(last.get("reaction_N", "nan")), cpu_s=0.0)


def number_list(kind, positive: bool):
    """An argparse type: comma-separated numbers of `kind`, refused with argparse's message."""
    def parse(text: str):
        try:
            values = [kind(v) for v in text.split(",")]
        except ValueError:
            raise argparse.ArgumentTypeError(f"'{text}': comma-separated {kind.__name__}s")
        if any(v < 0 or (positive and v == 0) for v in values):
            raise argparse.ArgumentTypeError(f"'{text}': the values must be "
                                             + ("positive" if positive else "0 or more"))
        return values
    return parse


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", default="build")
    p.add_argument("--levels", type=number_list(int, False), default=[0, 1, 2])
    p.add_argument("--sizes", type=number_list(float, True), default=[1, 0.5, 0.25])
    p.add_argument("--layup", choices=list(decks.LAYUPS), default="[0]8")
    p.add_argument("--pressure", type=lambda t: number_list(float, True)(t)[0], default=0.1,
                   help="MPa on the mid-surface")
    p.add_argument("--tie", action="store_true", help="the contact reference's tied meshes")
    p.add_argument("--patch", type=lambda t: number_list(float, True)(t)[0], default=0.0,
                   help="Hertz patch radius, mm (1000 N on the whole cap) instead of the pressure")
    a = p.parse_args(argv)
    rows = [shell_apex(str(Path(a.build) / "shellindent"), a.layup, s, a.pressure, a.patch)
            for s in a.sizes]
    rows += [solid_apex(a.layup, lv, a.pressure, a.tie, a.patch) for lv in a.levels]
    ref = rows[-1]["apex_w_mm"]
    RESULTS.mkdir(exist_ok=True)
    name = (f"patch_check_{decks.layup_slug(a.layup)}_{a.patch:g}" if a.patch else
            f"pressure_check_{decks.layup_slug(a.layup)}") + ("_tie" if a.tie else "")
    run_ccx.write_rows(RESULTS / f"{name}.csv",
                       [{**r, "w_over_finest_solid": r["apex_w_mm"] / ref} for r in rows])
    for r in rows:
        print(f"{r['model']:28s} apex w {r['apex_w_mm']:.6g} mm  reaction {r['reaction_N']:.6g} N"
              f"  w / finest solid {r['apex_w_mm'] / ref:.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
