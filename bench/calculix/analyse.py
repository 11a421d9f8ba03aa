#!/usr/bin/python3
"""The 3-D cap reference from the mesh sequences: Richardson extrapolation and error bands.

  /usr/bin/python3 bench/calculix/analyse.py

Reads results/runs.csv and the per-run CSVs of the cap runs tagged
cap_<layup>_<symmetry>_<lin|nl>_L<level> (run_ccx.py's default tags). For every lay-up,
kinematics and printed travel, with the levels L (in-plane size 0.4 / 2^L mm under the contact,
the top ply split in 2^L layers):

* three levels or more: the observed order p = log2((F1 - F0) / (F2 - F1)) of the three
  finest; if the differences keep their sign and shrink (the asymptotic range), the Richardson
  limit F2 + (F2 - F1) / (2^p - 1) is the reference and its band is 1.25 |limit - F2| (the
  grid-convergence index's safety factor; Roache 1994); otherwise the finest value with the
  largest difference of the coarser levels from it as the band;
* two levels: the finer value, band |F1 - F0|.

The same for the apex mid-surface deflection and the approach (travel minus deflection).
Side checks (tags with suffixes, e.g. _K2e7 for the doubled penalty, _outer1 for the refined
outer zone) are listed with their relative effect on the force in results/cap_checks.csv.

Writes results/cap_reference.csv and results/cap_checks.csv and prints the tables.
"""
from __future__ import annotations

import csv
import math
import re
import sys
from collections import defaultdict
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results"
BASE = re.compile(r"^cap_(?P<layup>[\w-]+)_(?P<sym>quarter|half|full)_(?P<kin>lin|nl)_L(?P<lev>\d)$")
LAYUP_OF = {"08": "[0]8", "0-902S": "[0/90]2S", "45--452S": "[45/-45]2S"}


def read_csv(path: Path) -> list[dict]:
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in r.items():
            try:
                r[k] = float(v)
            except (TypeError, ValueError):
                pass
    return rows


def extrapolate(values: list[float]) -> tuple[float, float, float, str]:
    """(reference, band, observed order, how) from values on levels 0, 1, 2, ... (h halving)."""
    v = [x for x in values if np.isfinite(x)]
    if len(v) == 1:
        return v[0], float("nan"), float("nan"), "one level"
    if len(v) == 2:
        return v[1], abs(v[1] - v[0]), float("nan"), "two levels"
    f0, f1, f2 = v[-3:]
    d1, d2 = f1 - f0, f2 - f1
    if d1 * d2 > 0 and abs(d2) < abs(d1):
        p = math.log2(d1 / d2)
        lim = f2 + d2 / (2 ** p - 1)
        return lim, 1.25 * abs(lim - f2), p, "Richardson"
    return f2, max(abs(f2 - f1), abs(f2 - f0)), float("nan"), "not asymptotic"


def main():
    runs = read_csv(RESULTS / "runs.csv")
    latest = {}
    for r in runs:  # the last record of a tag wins (reruns)
        if r["status"] == "ok":
            latest[r["tag"]] = r
    groups = defaultdict(dict)
    checks = []
    for tag, r in latest.items():
        m = BASE.match(tag)
        if m:
            groups[(LAYUP_OF.get(m["layup"], m["layup"]), m["kin"], m["sym"])][int(m["lev"])] = tag
    ref_rows = []
    for (layup, kin, sym), levels in sorted(groups.items()):
        data = {L: read_csv(RESULTS / f"{levels[L]}.csv") for L in sorted(levels)}
        travels = sorted({round(r["travel_mm"], 6) for rows in data.values() for r in rows})
        for t in travels:
            per = {}
            for L, rows in data.items():
                hit = [r for r in rows if abs(r["travel_mm"] - t) < 1e-6]
                if hit:
                    per[L] = hit[0]
            if not per:
                continue
            Ls = sorted(per)
            F = [per[L]["force_N"] for L in Ls]
            W = [per[L]["apex_mid_w_mm"] for L in Ls]
            A = [per[L]["approach_mm"] for L in Ls]
            f, fb, p, how = extrapolate(F)
            w, wb, pw, _ = extrapolate(W)
            a, ab, pa, _ = extrapolate(A)
            fin = per[Ls[-1]]
            radius = np.nanmean([fin.get("a_x_mm", np.nan), fin.get("a_y_mm", np.nan)])
            row = dict(layup=layup, kinematics="linear" if kin == "lin" else "nonlinear",
                       symmetry=sym, travel_mm=t, force_N=f, force_band_pct=100 * fb / f,
                       force_order=p, method=how, levels="".join(map(str, Ls)),
                       apex_mid_w_mm=w, apex_w_band_pct=100 * wb / w if w else float("nan"),
                       approach_mm=a, approach_band_mm=ab, contact_radius_mm=radius)
            for L, x in zip(Ls, F):
                row[f"F_L{L}"] = x
            for L, x in zip(Ls, W):
                row[f"w_L{L}"] = x
            ref_rows.append(row)
    # side checks: the same case with one setting changed, against its base tag
    for tag, r in latest.items():
        m = re.match(r"^(cap_.*_L\d)_(\w+)$", tag)
        if not m or m.group(1) not in latest:
            continue
        base = read_csv(RESULTS / f"{m.group(1)}.csv")
        alt = read_csv(RESULTS / f"{tag}.csv")
        for ra in alt:
            rb = [x for x in base if abs(x["travel_mm"] - ra["travel_mm"]) < 1e-6]
            if rb:
                checks.append(dict(base=m.group(1), variant=m.group(2), travel_mm=ra["travel_mm"],
                                   force_base_N=rb[0]["force_N"], force_variant_N=ra["force_N"],
                                   force_change_pct=100 * (ra["force_N"] / rb[0]["force_N"] - 1),
                                   w_change_pct=100 * (ra["apex_mid_w_mm"]
                                                       / rb[0]["apex_mid_w_mm"] - 1)))
    for name, rows in (("cap_reference.csv", ref_rows), ("cap_checks.csv", checks)):
        if not rows:
            continue
        keys = []
        for r in rows:
            keys += [k for k in r if k not in keys]
        with open(RESULTS / name, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=keys)
            w.writeheader()
            for r in rows:
                w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    print(f"{'layup':11s} {'kin':9s} {'travel':>6s} {'F_ref':>9s} {'band%':>6s} {'p':>5s} "
          f"{'w_ref':>7s} {'band%':>6s} {'approach':>8s} {'a_c':>5s}  levels F")
    for r in ref_rows:
        levs = " ".join(f"{r[k]:.0f}" for k in sorted(r) if k.startswith("F_L"))
        print(f"{r['layup']:11s} {r['kinematics']:9s} {r['travel_mm']:6.3f} {r['force_N']:9.1f} "
              f"{r['force_band_pct']:6.2f} {r['force_order']:5.2f} {r['apex_mid_w_mm']:7.4f} "
              f"{r['apex_w_band_pct']:6.2f} {r['approach_mm']:8.4f} {r['contact_radius_mm']:5.2f}"
              f"  {levs}")
    for c in checks:
        print(f"check {c['base']} {c['variant']}: travel {c['travel_mm']:.3f} force "
              f"{c['force_change_pct']:+.2f} %, apex w {c['w_change_pct']:+.2f} %")
    return 0


if __name__ == "__main__":
    sys.exit(main())
