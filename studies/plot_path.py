#!/usr/bin/python3
"""Figures of an indentation path written by `shellindent run`: contact force against depth
(with the apex deflection), contact radius against depth, and force against the apex curvatures
k11 and k22 (the paper's Figs 7 and 10), with the located events marked.

Usage: plot_path.py RESULTS_DIR [out.png]
Reads RESULTS_DIR/path.csv and RESULTS_DIR/events.json (docs/results.md); writes out.png
(default RESULTS_DIR/force_depth.png). Needs python3-matplotlib (Debian).
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def column(rows, name):
    return [float(r[name]) for r in rows]


def main(directory, png_path):
    with open(os.path.join(directory, "path.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    events_path = os.path.join(directory, "events.json")
    events = json.load(open(events_path)) if os.path.exists(events_path) else []
    depth = column(rows, "depth_mm")
    force = [F / 1000 for F in column(rows, "force_N")]
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.2))
    ax[0].plot(depth, force, "o-", ms=3, label="contact force $T_N$")
    for e in events:
        if e["type"] in ("monitor_max", "limit_point"):
            ax[0].plot(e["depth_mm"], e["force_N"] / 1000, "rv", ms=9, label=e["type"])
    ax[0].set_xlabel("depth h (mm)")
    ax[0].set_ylabel("force (kN)")
    ax[0].grid(True, alpha=0.3)
    ax[0].legend()
    ax[1].plot(depth, column(rows, "contact_radius_mm"), "s-", ms=3)
    ax[1].set_xlabel("depth h (mm)")
    ax[1].set_ylabel("contact radius (mm)")
    ax[1].grid(True, alpha=0.3)
    for key, label in (("k11_per_mm", "$\\kappa_{11}$"), ("k22_per_mm", "$\\kappa_{22}$")):
        ax[2].plot(column(rows, key), force, "-", label=label)
    for e in events:
        if e["type"] == "inflection":
            ax[2].plot(e[e["against"]], e["force_N"] / 1000, "kx", ms=9)
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
