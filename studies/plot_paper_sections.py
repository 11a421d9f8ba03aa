#!/usr/bin/python3
"""Figure of the source paper's lay-up sweep: bending and transverse-shear stiffness of
[theta/-theta]2S against theta, with [0/90]2S marked.

Usage: plot_paper_sections.py paper_sections.csv out.png
Reads the CSV written by `shellindent section --paper`. Needs python3-matplotlib (Debian).
"""
import csv
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    angle_rows, cross_ply = [], None
    for r in rows:
        m = re.fullmatch(r"\[(\d+)/-?\d+\]2S", r["layup"])
        if r["layup"] == "[0/90]2S":
            cross_ply = r
        elif m:
            angle_rows.append((float(m.group(1)), r))
    angle_rows.sort()
    theta = [t for t, _ in angle_rows]

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    for key, label, style in [("D11_Nmm", "D11", "o-"), ("D22_Nmm", "D22", "s-"),
                              ("D66_Nmm", "D66", "^-"), ("D16_Nmm", "D16", "v--")]:
        ax1.plot(theta, [float(r[key]) / 1e3 for _, r in angle_rows], style, label=label)
        if cross_ply:
            ax1.plot([45], [float(cross_ply[key]) / 1e3], "k" + style[0], mfc="none")
    ax1.set_xlabel(r"lay-up angle $\theta$ of $[\theta/-\theta]_{2S}$ (deg)")
    ax1.set_ylabel("bending stiffness (N m)")
    ax1.set_title("VAM / CLT bending stiffness (open black: [0/90]2S)")
    ax1.legend()
    ax1.grid(alpha=0.3)

    for key, label, style in [("G11_vam_N/mm", "G11 VAM", "o-"), ("G22_vam_N/mm", "G22 VAM", "s-"),
                              ("G11_eq_N/mm", "G11 equilibrium", "o:"),
                              ("G22_eq_N/mm", "G22 equilibrium", "s:"),
                              ("G11_fsdt_N/mm", "G11 FSDT 5/6", "o--")]:
        ax2.plot(theta, [float(r[key]) for _, r in angle_rows], style, label=label)
    ax2.set_xlabel(r"lay-up angle $\theta$ (deg)")
    ax2.set_ylabel("transverse shear stiffness (N/mm)")
    ax2.set_title("Transverse shear stiffness G")
    ax2.legend(fontsize=8)
    ax2.grid(alpha=0.3)
    fig.suptitle("Paper carbon/epoxy, 8 x 0.475 mm plies")
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)
    print(f"wrote {png_path}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
