#!/usr/bin/python3
"""The shell against the solid under a load with no local part (issue 20, docs/theory/
local-indentation.md 6.7): a uniform pressure on the paper's cap, linear.

  /usr/bin/python3 bench/calculix/pressure_check.py [--build build] [--levels 0,1,2]
      [--sizes 1,0.5,0.25] [--layup "[0]8"] [--pressure 0.1] [--tie]

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
"""
from __future__ import annotations

import argparse
import csv
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import ccxdat  # noqa: E402
import decks  # noqa: E402
import run_ccx  # noqa: E402

RESULTS = HERE / "results"
WORK = HERE / "work" / "pressure"


def solid_apex(layup: str, level: int, pressure: float, tie: bool) -> dict:
    """The solid cap's apex mid-surface deflection (mm, positive inwards). The reaction printed
    is the clamped nodes' (the loads on those nodes go to the support without it)."""
    mesh = decks.Mesh(level=level)
    if not tie:
        mesh.tie_radius = None
    case = decks.Case(kind="cap", layup=layup, symmetry="quarter", points=[],
                      pressure=pressure, mesh=mesh)
    deck = decks.solid_deck(case)
    tag = f"pressure_{decks.layup_slug(layup)}_L{level}" + ("_tie" if tie else "")
    cost, work = run_ccx.run_deck(deck.text, deck.info, tag)
    if cost["status"] != "ok":
        raise SystemExit(f"{tag}: ccx {cost['status']}, see {work}/ccx.log")
    dat = ccxdat.read_dat(str(work / "job.dat"))
    t = max(dat[("u", "NAPEX")])
    w = -float(dat[("u", "NAPEX")][t][0][3])
    reaction = abs(float(dat[("rf_total", "NFIX")][t][2])) * deck.info["factor"]
    return dict(model=f"C3D20R level {level}" + (" tied" if tie else ""), nodes=deck.info["nodes"], apex_w_mm=w,
                reaction_N=reaction, cpu_s=cost.get("cpu_s", 0.0))


def shell_case(layup: str, size: float, pressure: float) -> str:
    return (f"material: paper-carbon-epoxy\n"
            f"laminate: {{layup: \"{layup}\", ply_thickness: 0.475 mm, reference: mid}}\n"
            f"shell: {{type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: clamped}}\n"
            f"mesh: {{element: mitc4, size_apex: {size:g} mm, size_edge: {2 * size:g} mm, "
            f"refine_radius: 13 mm, symmetry: quarter}}\n"
            f"kinematics: linear\n"
            f"load: {{type: pressure, pressure: {pressure:g} MPa, steps: 1}}\n"
            f"output: {{vtu_every: 0}}\n")


def shell_apex(exe: str, layup: str, size: float, pressure: float) -> dict:
    WORK.mkdir(parents=True, exist_ok=True)
    name = f"shell_{decks.layup_slug(layup)}_{size:g}"
    case = WORK / f"{name}.yaml"
    case.write_text(shell_case(layup, size, pressure))
    out = WORK / name
    proc = subprocess.run([exe, "static", str(case), "--out", str(out)], capture_output=True,
                          text=True)
    if proc.returncode != 0:
        raise SystemExit(f"{name}: shellindent failed: {proc.stderr[-400:]}")
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
    a = p.parse_args(argv)
    rows = [shell_apex(str(Path(a.build) / "shellindent"), a.layup, s, a.pressure)
            for s in a.sizes]
    rows += [solid_apex(a.layup, lv, a.pressure, a.tie) for lv in a.levels]
    ref = rows[-1]["apex_w_mm"]
    RESULTS.mkdir(exist_ok=True)
    name = f"pressure_check_{decks.layup_slug(a.layup)}" + ("_tie" if a.tie else "")
    run_ccx.write_rows(RESULTS / f"{name}.csv",
                       [{**r, "w_over_finest_solid": r["apex_w_mm"] / ref} for r in rows])
    for r in rows:
        print(f"{r['model']:28s} apex w {r['apex_w_mm']:.6g} mm  reaction {r['reaction_N']:.6g} N"
              f"  w / finest solid {r['apex_w_mm'] / ref:.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
