#!/usr/bin/python3
"""shellindent on the cap against the 3-D CalculiX reference (issue 20).

  /usr/bin/python3 bench/calculix/compare_shellindent.py [--build build] [--size-apex 0.5]
      [--laws none,hertz,anisotropic:plate,anisotropic:shell+fbar] [--layups ...]
      [--kinematics linear,nonlinear]

For every lay-up, kinematics and local law (`anisotropic:SUPPORT` for contact.local: anisotropic
with contact.local_support: SUPPORT) it writes a case file (work/si/), runs
`build/shellindent run CASE --out DIR`, and compares its force with the reference of
results/cap_reference.csv (analyse.py): at equal travel (0.1, 0.25, 0.5, 1 mm) and at equal apex
mid-surface deflection (the reference's force interpolated at shellindent's apex deflection:
path.csv's apex_mid_w_mm, the laminate's mid-plane, which differs from the shell's apex_w_mm
with the elastic face; past the reference's last deflection, shellindent's force interpolated at
the reference's deflection instead).
Writes results/shellindent_vs_3d.csv and prints the table.
"""
from __future__ import annotations

import argparse
import csv
import os
import resource
import subprocess
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import decks  # noqa: E402

ROOT = HERE.parent.parent
RESULTS = HERE / "results"
WORK = HERE / "work" / "si"
TRAVELS = [0.1, 0.25, 0.5, 1.0]
QUARTER = {"[0]8": True, "[0/90]2S": True, "[45/-45]2S": False}


def local_keys(law: str) -> str:
    """The contact keys of a law token: `hertz`, `anisotropic:plate` (law and its support), and
    either with `+fbar` (contact.fbar: true, the face's Poisson rise from the shell's strains)."""
    law, plus, option = law.partition("+")
    name, _, support = law.partition(":")
    keys = f"local: {name}" + (f", local_support: {support}" if support else "")
    return keys + (f", {option}: true" if plus else "")


def case_text(layup: str, kinematics: str, law: str, size_apex: float, depth_max: float,
              depths: list[float], refine_radius: float = 13.0) -> str:
    sym = "quarter" if QUARTER[layup] else "full"
    dl = ", ".join(f"{d:g} mm" for d in depths)
    return (f"material: paper-carbon-epoxy\n"
            f"laminate: {{layup: \"{layup}\", ply_thickness: 0.475 mm, reference: mid}}\n"
            f"shell: {{type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: clamped}}\n"
            f"mesh: {{element: mitc4, size_apex: {size_apex:g} mm, size_edge: 2 mm, "
            f"refine_radius: {refine_radius:g} mm, symmetry: {sym}}}\n"
            f"kinematics: {kinematics}\n"
            f"indenter: {{shape: sphere, radius: 12.7 mm}}\n"
            f"contact: {{surface: outer, solver: kinsol, {local_keys(law)}}}\n"
            f"path: {{method: natural, depth_max: {depth_max:g} mm, step: 0.05 mm, "
            f"depths: [{dl}]}}\n"
            f"output: {{vtu_every: 0, formats: [csv]}}\n")


def run_shellindent(exe: str, case: Path, out: Path, threads: int = 1) -> tuple[float, int]:
    """Runs one case; returns (CPU seconds of the child from getrusage, exit code)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OPENBLAS_NUM_THREADS="1")
    with open(out.with_suffix(".log"), "w") as log:
        rc = subprocess.run(["nice", "-n", "19", exe, "run", str(case), "--out", str(out),
                             "--threads", str(threads)], stdout=log, stderr=subprocess.STDOUT,
                            env=env).returncode
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, rc


def read_csv(path: Path) -> list[dict]:
    with open(path) as f:
        return [{k: (float(v) if _num(v) else v) for k, v in r.items()} for r in csv.DictReader(f)]


def _num(v: str) -> bool:
    try:
        float(v)
        return True
    except (TypeError, ValueError):
        return False


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--build", default=str(ROOT / "build"))
    p.add_argument("--size-apex", type=float, default=0.5)
    p.add_argument("--laws", default="none,hertz")
    p.add_argument("--layups", default="[0]8,[0/90]2S,[45/-45]2S")
    p.add_argument("--kinematics", default="linear,nonlinear")
    p.add_argument("--reference", default=str(RESULTS / "cap_reference.csv"))
    p.add_argument("--out", default=str(RESULTS / "shellindent_vs_3d.csv"))
    a = p.parse_args(argv)
    exe = str(Path(a.build) / "shellindent")
    ref = read_csv(Path(a.reference))
    WORK.mkdir(parents=True, exist_ok=True)
    rows = []
    for layup in a.layups.split(","):
        for kin in a.kinematics.split(","):
            mine = [r for r in ref if r["layup"] == layup and r["kinematics"] == kin]
            if not mine:
                print(f"no reference for {layup} {kin}", file=sys.stderr)
                continue
            rt = np.array([r["travel_mm"] for r in mine])
            rf = np.array([r["force_N"] for r in mine])
            rw = np.array([r["apex_mid_w_mm"] for r in mine])
            for law in a.laws.split(","):
                tag = f"{decks.layup_slug(layup)}_{kin}_" \
                      f"{law.replace(':', '-').replace('+', '-')}_" \
                      f"{a.size_apex:g}"
                case = WORK / f"{tag}.yaml"
                case.write_text(case_text(layup, kin, law, a.size_apex, 1.0, TRAVELS))
                out = WORK / tag
                cpu, rc = run_shellindent(exe, case, out)
                if rc != 0:
                    print(f"{tag}: shellindent failed (rc {rc}), see {out}.log", file=sys.stderr)
                    continue
                path = read_csv(out / "path.csv")
                d = np.array([r["depth_mm"] for r in path])
                f = np.array([r["force_N"] for r in path])
                # The laminate's mid-plane (the elastic face's mid-plane kernel added to the
                # shell's deflection) where the run reports it, as the solid's apex_mid_w_mm is.
                wcol = "apex_mid_w_mm" if "apex_mid_w_mm" in path[0] else "apex_w_mm"
                w = np.array([r[wcol] for r in path])
                for t in TRAVELS:
                    k = int(np.argmin(abs(d - t)))
                    if abs(d[k] - t) > 1e-9 or not np.any(abs(rt - t) < 1e-9):
                        continue
                    j = int(np.argmin(abs(rt - t)))
                    order = np.argsort(rw)
                    f_at_w = float(np.interp(w[k], rw[order], rf[order])) \
                        if rw.min() <= w[k] <= rw.max() else float("nan")
                    ratio_w = f[k] / f_at_w
                    # Past the reference's last deflection (its path ends at 1 mm of travel):
                    # the same comparison the other way, shellindent's force at the solid's
                    # deflection, where shellindent's path reaches it.
                    if np.isnan(ratio_w) and w.min() <= rw[j] <= w.max():
                        mine_order = np.argsort(w)
                        ratio_w = float(np.interp(rw[j], w[mine_order], f[mine_order])) / rf[j]
                    rows.append(dict(layup=layup, kinematics=kin, law=law,
                                     size_apex_mm=a.size_apex, travel_mm=t, si_force_N=f[k],
                                     ref_force_N=rf[j], ratio_travel=f[k] / rf[j],
                                     si_apex_w_mm=w[k], ref_apex_w_mm=rw[j],
                                     ref_force_at_si_w_N=f_at_w,
                                     ratio_deflection=ratio_w, si_cpu_s=cpu))
    if rows:
        with open(a.out, "w", newline="") as fo:
            wr = csv.DictWriter(fo, fieldnames=list(rows[0]))
            wr.writeheader()
            for r in rows:
                wr.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    print(f"{'layup':11s} {'kin':9s} {'law':22s} {'travel':>6s} {'F_si':>9s} {'F_3D':>9s} "
          f"{'ratio':>6s} {'w_si':>7s} {'w_3D':>7s} {'ratio@w':>7s}")
    for r in rows:
        print(f"{r['layup']:11s} {r['kinematics']:9s} {r['law']:22s} {r['travel_mm']:6.2f} "
              f"{r['si_force_N']:9.1f} {r['ref_force_N']:9.1f} {r['ratio_travel']:6.3f} "
              f"{r['si_apex_w_mm']:7.4f} {r['ref_apex_w_mm']:7.4f} {r['ratio_deflection']:7.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
