"""Figures of studies/paper_layups.py, the analogues of the source paper's Figs 7-12, plus the
force-depth paths of the variants. Each function draws one PNG (dpi 100, for docs/figures/) and
returns its path. Inputs are the per-case dicts of paper_layups.case_results.
"""
import math
import os

import matplotlib

import paper_data
from study_support import poly_coefficients, poly_value

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from result_columns import DEPTH_MM, FORCE_N, K11_PER_MM, K12_PER_MM, K22_PER_MM, STABLE  # noqa: E402

DPI = 100
# The three lay-ups of the paper's Figs 7, 10 and 11 (angle ply, cross ply, "symmetric" ply).
PAPER_FIG10_LAYUPS = ("[45/-45]2S", "[0/90]2S", "[30/-30]2S")
CURVATURES = ((K11_PER_MM, "k11"), (K12_PER_MM, "k12 + k21"), (K22_PER_MM, "k22"))


def save(fig, directory, name):
    path = os.path.join(directory, name)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path


def by_layup(cases, layups):
    found = {c["layup"]: c for c in cases if c["rows"]}
    return [found[lay] for lay in layups if lay in found]


def force_depth(cases, directory):
    """Fig 7 analogue: T_N(h) of every lay-up with its fitted power law (dashed)."""
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for c in cases:
        if not c["rows"]:
            continue
        h = [r[DEPTH_MM] for r in c["rows"]]
        line, = ax.plot(h, [r[FORCE_N] / 1000 for r in c["rows"]], "-", label=c["layup"])
        if isinstance(c.get("C1"), float):
            ax.plot(h, [c["C1"] * x ** c["C2"] / 1000 for x in h], "--", color=line.get_color(),
                    lw=0.8)
        unstable = [r for r in c["rows"] if r.get(STABLE) == 0]
        if unstable:  # issue 15 item 5: unstable points marked apart from the stable path
            ax.plot([r[DEPTH_MM] for r in unstable], [r[FORCE_N] / 1000 for r in unstable], "x",
                    color="red", ms=5)
    stability = any(c.get("stability") for c in cases)
    ax.set_xlabel("depth h (mm)")
    ax.set_ylabel("contact force T_N (kN)")
    ax.set_title("T_N(h) per lay-up (solid), fitted C1 h^C2 (dashed)" +
                 ("; unstable points: red x" if stability else ""))
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    return save(fig, directory, "paper_fig07_force_depth.png")


def coefficient_panel(ax, theta_rows, fits, cases, name, paper_eq):
    """One of Figs 8-9: ours with 95 % intervals and the cubic in degrees; the paper's Table 2 and
    its eq 82/83 read with theta in radians (the only reading that gives finite values)."""
    angle = sorted((c for c in cases if c["theta_deg"] is not None and isinstance(c.get(name), float)),
                   key=lambda c: c["theta_deg"])
    xs = [c["theta_deg"] for c in angle]
    ax.errorbar(xs, [c[name] for c in angle],
                yerr=[[c[name] - c[name + "_lo"] for c in angle],
                      [c[name + "_hi"] - c[name] for c in angle]],
                fmt="o", capsize=3, label=f"ours, {name} (95 % interval)")
    grid = [i * 0.9 for i in range(101)]
    coeffs = poly_coefficients(fits[f"{name}_theta_deg"])
    ax.plot(grid, [poly_value(coeffs, t) for t in grid], "-", label="ours, cubic in theta (deg)")
    paper = [r[f"paper_{name}"] for r in theta_rows]
    ax.plot([r["theta_deg"] for r in theta_rows], paper, "s", mfc="none", label="paper Table 2")
    ax.plot(grid, [poly_value(paper_eq, math.radians(t)) for t in grid], ":",
            label=f"paper eq {82 if name == 'C1' else 83} (theta in rad)")
    ax.set_xlabel("lay-up angle theta (deg), [theta/-theta]2S")
    ax.set_ylabel(name + (" (N/mm^C2, log scale)" if name == "C1" else " (-)"))
    if name == "C1":  # ours and the paper's differ by ~30x (report: magnitude)
        ax.set_yscale("log")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)


def coefficients_theta(theta_rows, fits, cases, directory, paper_eqs):
    """Figs 8-9 analogue: C1 and C2 against theta."""
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    coefficient_panel(ax[0], theta_rows, fits, cases, "C1", paper_eqs[0])
    coefficient_panel(ax[1], theta_rows, fits, cases, "C2", paper_eqs[1])
    return save(fig, directory, "paper_fig08_09_coefficients_theta.png")


def critical_points(case, against):
    return [(e[FORCE_N], e) for e in case["events"]
            if e.get("type") == "inflection" and e.get("against") == against]


def force_curvature(cases, directory):
    """Fig 10 analogue: T_N against the apex curvatures, the critical force (first inflection of
    T_N against k11 / k22, events.json) marked."""
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.2))
    for c in by_layup(cases, PAPER_FIG10_LAYUPS):
        for a, (col, label) in zip(ax, CURVATURES):
            k = [r[col] for r in c["rows"]]
            line, = a.plot(k, [r[FORCE_N] / 1000 for r in c["rows"]], "-", label=c["layup"])
            for force, e in critical_points(c, col)[:1]:
                a.plot([e[col]], [force / 1000], "o", ms=8, mfc="none", color=line.get_color())
            a.set_xlabel(f"apex curvature {label} (1/mm)")
            a.set_ylabel("T_N (kN)")
            a.grid(True, alpha=0.3)
    ax[0].set_title("T_N vs k11 (o: critical force, inflection)")
    ax[1].set_title("T_N vs k12")
    ax[2].set_title("T_N vs k22 (o: critical force, inflection)")
    ax[0].legend(fontsize=8)
    return save(fig, directory, "paper_fig10_force_curvature.png")


def curvature_depth(cases, directory):
    """Fig 11 analogue: apex curvatures against the depth."""
    fig, ax = plt.subplots(1, 3, figsize=(14, 4.2), sharey=False)
    for a, c in zip(ax, by_layup(cases, PAPER_FIG10_LAYUPS)):
        h = [r[DEPTH_MM] for r in c["rows"]]
        for col, label in CURVATURES:
            a.plot(h, [r[col] for r in c["rows"]], "-", label=label)
        a.set_title(c["layup"])
        a.set_xlabel("depth h (mm)")
        a.set_ylabel("apex curvature (1/mm)")
        a.grid(True, alpha=0.3)
        a.legend(fontsize=8)
    return save(fig, directory, "paper_fig11_curvature_depth.png")


def energy_theta(theta_rows, fits, directory, depth_max, paper_eq85):
    """Fig 12 analogue: strain energy at depth_max against theta, the LOOCV-chosen polynomial."""
    fig, ax = plt.subplots(figsize=(7, 4.5))
    xs = [r["theta_deg"] for r in theta_rows]
    ax.plot(xs, [r["energy_J"] for r in theta_rows], "o", label=f"ours, energy at {depth_max:g} mm")
    fit = fits["energy"]
    grid = [i * 0.9 for i in range(101)]
    coeffs = poly_coefficients(fit)
    degree = len(coeffs) - 1
    tag = " (interpolation)" if fit["interpolation"] else ""
    ax.plot(grid, [poly_value(coeffs, t) for t in grid], "-",
            label=f"ours, degree {degree} by LOOCV{tag}")
    ax.plot(grid, [poly_value(paper_eq85, math.radians(t)) for t in grid], ":",
            label="paper eq 85 (theta in rad), 0-10 mm")
    ax.set_xlabel("lay-up angle theta (deg), [theta/-theta]2S")
    ax.set_ylabel("indentation energy (J)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    return save(fig, directory, "paper_fig12_energy_theta.png")


def variants_force_depth(results, directory, layups=("[0/0]2S", "[0/90]2S")):
    """T_N(h) of every variant for the lay-ups run by all of them."""
    fig, ax = plt.subplots(1, len(layups), figsize=(6 * len(layups), 4.2))
    for a, layup in zip(ax, layups):
        for name, cases in results.items():
            for c in by_layup(cases, [layup]):
                a.plot([r[DEPTH_MM] for r in c["rows"]],
                       [r[FORCE_N] / 1000 for r in c["rows"]], "-", label=name)
        a.set_title(f"{layup}: the paper's choices one at a time")
        a.set_xlabel("depth h (mm)")
        a.set_ylabel("T_N (kN)")
        a.grid(True, alpha=0.3)
        a.legend(fontsize=8)
    return save(fig, directory, "paper_variants_force_depth.png")


def draw_all(results, theta_rows, fits, directory, depth_max):
    """All figures; returns {key: path}."""
    cases = results["default"]
    return {
        "fig07": force_depth(cases, directory),
        "fig08_09": coefficients_theta(theta_rows, fits, cases, directory,
                                       (paper_data.EQ82_C1, paper_data.EQ83_C2)),
        "fig10": force_curvature(cases, directory),
        "fig11": curvature_depth(cases, directory),
        "fig12": energy_theta(theta_rows, fits, directory, depth_max, paper_data.EQ85_ENERGY_J),
        "variants": variants_force_depth(results, directory),
    }
