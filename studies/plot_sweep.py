#!/usr/bin/python3
"""Figures of a parameter study written by `shellindent sweep` (docs/sweeps.md): the contact-law
coefficients C1 and C2 of T = C1 h^C2 (with their 95 % intervals) against the varied parameter,
and the force-depth paths T_N(h) of all cases.

Usage: plot_sweep.py SWEEP_DIR [KEY] [out.png]
Reads SWEEP_DIR/sweep.json and SWEEP_DIR/cases/*/path.csv. KEY is the varied key on the x axis of
the C1, C2 plots (default: the first varied key with more than one value); lay-ups
"[theta/-theta]2S" are plotted against theta, other lay-ups are marked on the right. Writes out.png
(default SWEEP_DIR/sweep.png). Needs python3-matplotlib (Debian).
"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from study_support import theta_of  # noqa: E402  (lay-up -> theta, shared with the studies)
from result_columns import DEPTH_MM, FORCE_N  # noqa: E402


def x_value(case, key):
    text = str(case.get(key, ""))
    if key == "laminate.layup":
        return theta_of(text)
    try:
        return float(text.split()[0])
    except (ValueError, IndexError):
        return None


def default_key(doc):
    keys = [c for c in doc["columns"][1:] if c != "status"]
    for k in keys[: keys.index("reason")] if "reason" in keys else keys:
        if len({str(c.get(k)) for c in doc["cases"]}) > 1:
            return k
    return keys[0]


def plot_coefficients(ax, doc, key, name):
    pts = [(x_value(c, key), c) for c in doc["cases"] if "C1" in c]
    line = sorted((x, c) for x, c in pts if x is not None)
    other = [c for x, c in pts if x is None]
    for a, (p, unit) in zip(ax, (("C1", "N/mm^C2"), ("C2", "-"))):
        if line:
            xs = [x for x, _ in line]
            ys = [c[p] for _, c in line]
            lo = [c[p] - c[p + "_lo"] for _, c in line]
            hi = [c[p + "_hi"] - c[p] for _, c in line]
            a.errorbar(xs, ys, yerr=[lo, hi], fmt="o-", capsize=3, label="95 % interval")
        xmax = max([x for x, _ in line], default=0)
        for i, c in enumerate(other):
            a.errorbar([xmax + 10 * (i + 1)], [c[p]],
                       yerr=[[c[p] - c[p + "_lo"]], [c[p + "_hi"] - c[p]]],
                       fmt="s", capsize=3, label=str(c.get(key)))
        a.set_xlabel("theta (deg)" if key == "laminate.layup" else key)
        a.set_ylabel(f"{p} ({unit})")
        a.set_title(f"{name}: {p} of T = C1 h^C2")
        a.grid(True, alpha=0.3)
        a.legend(fontsize=8)


def plot_paths(ax, directory, doc):
    cases_dir = os.path.join(directory, "cases")
    for sub in sorted(os.listdir(cases_dir)):
        path = os.path.join(cases_dir, sub, "path.csv")
        if not os.path.exists(path):
            continue
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        ax.plot([float(r[DEPTH_MM]) for r in rows],
                [float(r[FORCE_N]) / 1000 for r in rows], "-", label=sub)
    ax.set_xlabel("depth h (mm)")
    ax.set_ylabel("contact force T_N (kN)")
    ax.set_title(f"{doc['name']}: T_N(h)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)


def main(directory, key, png_path):
    with open(os.path.join(directory, "sweep.json")) as f:
        doc = json.load(f)
    key = key or default_key(doc)
    fig, ax = plt.subplots(1, 3, figsize=(16, 4.5))
    plot_coefficients(ax[:2], doc, key, doc["name"])
    plot_paths(ax[2], directory, doc)
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)
    print("wrote", png_path)


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    d = sys.argv[1]
    k = sys.argv[2] if len(sys.argv) > 2 else None
    out = sys.argv[3] if len(sys.argv) > 3 else os.path.join(d, "sweep.png")
    main(d, k, out)
