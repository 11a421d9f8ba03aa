#!/usr/bin/python3
"""Markdown tables of the committed results (for README.md and docs/).

  /usr/bin/python3 bench/calculix/report.py [hertz|reference|checks|shellindent|peer|runs ...]
"""
from __future__ import annotations

import csv
import sys
from pathlib import Path

RESULTS = Path(__file__).resolve().parent / "results"


def rows(name):
    p = RESULTS / name
    if not p.exists():
        return []
    with open(p) as f:
        return list(csv.DictReader(f))


def num(v, fmt):
    try:
        x = float(v)
    except (TypeError, ValueError):
        return v or ""
    return "-" if x != x else format(x, fmt)


def table(head, body):
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    out += ["| " + " | ".join(r) + " |" for r in body]
    return "\n".join(out)


def hertz():
    body = [[r["tag"], num(r["h_mm"], ".2f"), num(r["travel_mm"], ".3f"),
             num(r["hertz_a_mm"], ".2f"), num(r["force_N"], ".1f"), num(r["hertz_N"], ".1f"),
             num(r["ratio"], ".4f"), num(r["finite_block_pct"], ".2f"),
             num(r["ratio_rel_5a"], ".4f"), num(r["ratio_rel_10a"], ".4f")]
            for r in rows("hertz.csv")]
    return table(["run", "h mm", "travel mm", "Hertz a mm", "F 3-D N", "F Hertz N",
                  "ratio", "block % (est.)", "ratio, approach to 5a", "ratio, to 10a"], body)


def reference():
    body = []
    for r in rows("cap_reference.csv"):
        levels = " / ".join(num(r[k], ".0f") for k in sorted(r) if k.startswith("F_L") and r[k])
        body.append([r["layup"], r["kinematics"], num(r["travel_mm"], ".3f"),
                     num(r["force_N"], ".0f"), num(r["force_band_pct"], ".2f"),
                     r["method"] + (f" p={float(r['force_order']):.2f}"
                                    if r["force_order"] not in ("", "nan") else ""),
                     num(r["apex_mid_w_mm"], ".4f"), num(r["apex_w_band_pct"], ".2f"),
                     num(r["approach_mm"], ".4f"), num(r["contact_radius_mm"], ".2f"), levels])
    return table(["lay-up", "kinematics", "travel mm", "force N", "band %", "estimate",
                  "apex mid w mm", "band %", "approach mm", "contact radius mm",
                  "force on L0 / L1 / L2 N"], body)


def checks():
    body = [[r["base"], r["variant"], num(r["travel_mm"], ".3f"), num(r["force_change_pct"], "+.2f"),
             num(r["w_change_pct"], "+.2f")] for r in rows("cap_checks.csv")]
    return table(["base run", "variant", "travel mm", "force change %", "apex w change %"], body)


def shellindent():
    body = [[r["layup"], r["kinematics"], r["law"], num(r["travel_mm"], ".2f"),
             num(r["si_force_N"], ".0f"), num(r["ref_force_N"], ".0f"), num(r["ratio_travel"], ".3f"),
             num(r["si_apex_w_mm"], ".4f"), num(r["ratio_deflection"], ".3f")]
            for r in rows("shellindent_vs_3d.csv")]
    return table(["lay-up", "kinematics", "contact.local", "travel mm", "F shellindent N",
                  "F 3-D N", "ratio at travel", "shellindent apex w mm",
                  "ratio at apex w"], body)


def peer():
    out = []
    for d in ("2", "10"):
        body = [[r["code"], r["mesh"], r["unknowns"], num(r["cpu_s"], ".2f"),
                 num(r["F_at_w0.25_N"], ".0f"), num(r["F_at_w0.5_N"], ".0f"),
                 num(r["F_at_w0.75_N"], ".0f"), num(r["F_at_w1.5_N"], ".0f"),
                 num(r["max_err_pct"], ".2f"), r["status"]] for r in rows(f"peer_cap_D{d}.csv")]
        if body:
            out.append(f"0 -> {d} mm\n\n" + table(
                ["code", "mesh", "unknowns", "CPU s", "F(w=0.25) N", "F(w=0.5) N",
                 "F(w=0.75) N", "F(w=1.5) N", "max error %", "status"], body))
    body = [[r["depth_max_mm"], r["calculix_mesh"], num(r["calculix_cpu_s"], ".1f"),
             r["shellindent_mesh"], num(r["shellindent_cpu_s"], ".2f"), num(r["cpu_ratio"], ".1f"),
             r["load"]] for r in rows("peer_cap_summary.csv")]
    if body:
        out.append(table(["0 -> mm", "CalculiX mesh", "CPU s", "shellindent mesh", "CPU s",
                          "CPU ratio", "load avg"], body))
    return "\n\n".join(out)


def runs():
    body = [[r["tag"], r["nodes"], r["elements"], r["layers"], r["increments"], r["iterations"],
             num(r["cpu_s"], ".0f"), num(r["wall_s"], ".0f"), num(r["maxrss_MB"], ".0f"), r["status"]]
            for r in rows("runs.csv")]
    return table(["run", "nodes", "elements", "layers", "increments", "iterations", "CPU s",
                  "wall s", "peak MB", "status"], body)


def main(argv):
    parts = argv or ["hertz", "reference", "checks", "shellindent", "peer", "runs"]
    for p in parts:
        print(f"### {p}\n\n{globals()[p]()}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
