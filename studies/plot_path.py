#!/usr/bin/python3
"""Figures of an indentation path written by `shellindent run`: contact force against depth
(with the apex deflection), contact radius against depth, and force against the apex curvatures
k11 and k22 (the paper's Figs 7 and 10), with the located events marked.

Usage: plot_path.py RESULTS_DIR [out.png]
Reads RESULTS_DIR/path.csv and RESULTS_DIR/events.json (docs/results.md), and path_grid.csv
where the run wrote one (pseudo-arclength: the curves are drawn through its 0.1 mm grid,
interpolated on the branch by cubic Hermite, with the converged points as markers, unless a
snap-back makes the depth turn back); writes
out.png (default RESULTS_DIR/force_depth.png). Needs python3-matplotlib (Debian).
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from result_columns import (  # noqa: E402
    CONTACT_RADIUS_MM, DEPTH_MM, FORCE_N, K11_PER_MM, K22_PER_MM)


def column(rows, name):
    return [float(r[name]) for r in rows]


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main(directory, png_path):
    rows = read_rows(os.path.join(directory, "path.csv"))
    grid_path = os.path.join(directory, "path_grid.csv")
    # The grid reports a depth once: where a snap-back makes the path pass depths again, the
    # curve is drawn through the points themselves.
    monotone = all(b >= a for a, b in zip(column(rows, DEPTH_MM), column(rows, DEPTH_MM)[1:]))
    curve = read_rows(grid_path) if monotone and os.path.exists(grid_path) else rows
    events_path = os.path.join(directory, "events.json")
    events = json.load(open(events_path)) if os.path.exists(events_path) else []
    depth = column(rows, DEPTH_MM)
    force = [F / 1000 for F in column(rows, FORCE_N)]
    curve_force = [F / 1000 for F in column(curve, FORCE_N)]
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.2))
    line = ax[0].plot(column(curve, DEPTH_MM), curve_force, "-", label="contact force $T_N$")
    ax[0].plot(depth, force, "o", ms=3, color=line[0].get_color(), label="converged points")
    for e in events:
        if e["type"] in ("monitor_max", "limit_point"):
            ax[0].plot(e[DEPTH_MM], e[FORCE_N] / 1000, "rv", ms=9, label=e["type"])
    ax[0].set_xlabel("depth h (mm)")
    ax[0].set_ylabel("force (kN)")
    ax[0].grid(True, alpha=0.3)
    ax[0].legend()
    ax[1].plot(depth, column(rows, CONTACT_RADIUS_MM), "s-", ms=3)
    ax[1].set_xlabel("depth h (mm)")
    ax[1].set_ylabel("contact radius (mm)")
    ax[1].grid(True, alpha=0.3)
    for key, label in ((K11_PER_MM, "$\\kappa_{11}$"), (K22_PER_MM, "$\\kappa_{22}$")):
        ax[2].plot(column(curve, key), curve_force, "-", label=label)
    for e in events:
        if e["type"] == "inflection":
            ax[2].plot(e[e["against"]], e[FORCE_N] / 1000, "kx", ms=9)
    ax[2].set_xlabel("apex curvature (1/mm); x = inflection (critical force)")
    ax[2].set_ylabel("force (kN)")
    ax[2].grid(True, alpha=0.3)
    ax[2].legend()
    fig.suptitle(os.path.basename(os.path.normpath(directory)))
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)
    print("wrote", png_path)


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    out = sys.argv[2] if len(sys.argv) == 3 else os.path.join(sys.argv[1], "force_depth.png")
    main(sys.argv[1], out)
