#!/usr/bin/python3
"""Damage onset on the source paper's cap and on a QSI specimen, eight lay-ups (issue 16 item 6).

What it computes: the paper's cap (studies/damage_onset_cap.yaml: clamped carbon/epoxy spherical
cap, 12.7 mm sphere, nonlinear, full model) for [theta/-theta]2S, theta = 0..90 by 15 deg, and
[0/90]2S (studies/damage_onset.yaml), with the four failure criteria monitored along the path on
the refined through-thickness stresses (docs/theory/failure.md 6): per lay-up and criterion the
onset depth, force, indenter work (the quasi-statically equivalent impact energy) and mode; the
Davies-Zhang delamination threshold and where the path's force reaches it; the depths of the
impact energies. Figures: every index against the depth, the Hashin index through the thickness
at the apex at the first point past its onset, the onset forces against theta with the
threshold. The same for the eight lay-ups as a quasi-static indentation specimen: the 150 x 100 mm
plate of ASTM D7136 on its fixture, 16 mm impactor (studies/damage_onset_d7136.yaml on
studies/damage_onset_d7136_plate.yaml), with the delamination criterion's onset beside the
Davies-Zhang threshold on both specimens.

Checks (exit 1 if one fails; the quick mode is what ctest runs):
  * every case completed (reached depth_max);
  * every onset is located and bracketed by the path's own index column (the point before it
    below 1, the point at or after it at or above 1) at the depth path.csv gives;
  * its work is the path's trapezoidal work (path.csv's depth and force) at its depth;
  * the threshold is pi sqrt(32 D* G_IIc / 3) with Olsson's D* recomputed here from the D11,
    D22, D12, D66 path.json reports (Davies & Zhang 1995; Olsson 2001);
  * an impact energy is reached exactly when the path's largest work exceeds it.

Run (from the source directory, after the build of README.md):
    studies/damage_onset.py -j 2                     # writes only OUT (results/damage_onset_study)
    studies/damage_onset.py -j 2 --report-dir docs/  # ... and regenerates docs/damage-onset.md
    studies/damage_onset.py --quick                  # smoke test: 2 mm mesh, 0 -> 0.5 mm
Writes OUT/sweep/ and OUT/sweep_d7136/ (the sweeps: sweep.csv/json, cases/*/path.csv, path.json,
damage_points.csv), OUT/onsets.csv, OUT/onsets_d7136.csv and the report damage-onset.md with figures/damage_*.png in OUT/report/ or in
--report-dir. Needs /usr/bin/python3 with matplotlib.
"""
import argparse
import math
import os
import sys
import time

import matplotlib

from paper_figures import save  # one PNG at the reports' dpi
from result_columns import (DELAMINATION_INDEX, DEPTH_MM, FORCE_N, HASHIN_INDEX,
                            MAX_STRESS_INDEX, TSAI_WU_INDEX)
from study_support import (SOURCE_DIR, STUDIES_DIR, case_dirs, column, default_exe, load_json,
                           load_path, measured_wall_time, read_csv, run_sweep, theta_of,
                           write_csv)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# (spelling in path.json, path.csv column, label)
CRITERIA = (("max_stress", MAX_STRESS_INDEX, "maximum stress"),
            ("tsai_wu", TSAI_WU_INDEX, "Tsai-Wu"),
            ("hashin", HASHIN_INDEX, "Hashin"),
            ("delamination", DELAMINATION_INDEX, "Brewer-Lagace (interfaces)"))


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--quick", action="store_true", help="smoke test: the study's quick keys")
    p.add_argument("--exe", default=default_exe(), help="shellindent executable")
    p.add_argument("--out", help="results directory (default results/damage_onset_study[_quick])")
    p.add_argument("-j", "--jobs", type=int, default=2, help="cases run at once")
    p.add_argument("--report-dir", help="where the report and figures go (default OUT/report; "
                   "docs/ regenerates the tracked report)")
    return p.parse_args()


# ---- 1. Per-case results --------------------------------------------------------------------

def trapezoid_work(depth, force, h):
    """The trapezoidal work of (depth, force) up to depth h (first passage), linear force within
    a segment: what path.csv's work_Nmm integrates."""
    work = 0.0
    for i in range(1, len(depth)):
        a, b = depth[i - 1], depth[i]
        if min(a, b) <= h <= max(a, b) and a != b:
            t = (h - a) / (b - a)
            f = force[i - 1] + t * (force[i] - force[i - 1])
            return work + 0.5 * (force[i - 1] + f) * (h - a)
        work += 0.5 * (force[i - 1] + force[i]) * (b - a)
    return None


def apex_profile(case_dir, depth):
    """The apex's rows of damage_points.csv at the first converged point at or past `depth`."""
    path = os.path.join(case_dir, "damage_points.csv")
    if not os.path.exists(path):
        return []
    rows = [r for r in read_csv(path) if r["point"] == "apex"]
    after = sorted({r[DEPTH_MM] for r in rows if r[DEPTH_MM] >= depth - 1e-12})
    return [r for r in rows if after and r[DEPTH_MM] == after[0]]


def case_results(run):
    """One dict per case: lay-up, status, the path, path.json's damage (onsets, threshold,
    energies) and the apex profile at the Hashin onset."""
    doc = run["doc"]
    if doc is None:
        return []
    dirs = case_dirs(run["dir"])
    cases = []
    for c in doc["cases"]:
        case_dir = dirs.get(int(c["case"]), "")
        rows, _ = load_path(case_dir)
        path_json = os.path.join(case_dir, "path.json")
        damage = load_json(path_json).get("damage", {}) if os.path.exists(path_json) else {}
        onsets = {}
        for o in damage.get("onsets", []):
            onsets.setdefault(o["criterion"], o)  # the first by depth
        hashin = onsets.get("hashin")
        cases.append({
            "layup": c.get("laminate.layup"), "theta_deg": theta_of(c.get("laminate.layup")),
            "status": c.get("status"), "reason": c.get("reason"), "rows": rows,
            "onsets": onsets, "threshold": damage.get("threshold"),
            "energies": damage.get("impact_energies", []),
            "apex": apex_profile(case_dir, hashin["depth_mm"]) if hashin else []})
    return cases


def onset_table(cases):
    """Rows of onsets.csv: one per case and criterion (empty cells where none was found)."""
    out = []
    for c in cases:
        for name, _, _ in CRITERIA:
            o = c["onsets"].get(name, {})
            place = (f"interface {o['interface'][0]}/{o['interface'][1]}" if "interface" in o
                     else f"ply {o['ply']} {o['position']}" if "ply" in o else None)
            out.append({"layup": c["layup"], "criterion": name, "depth_mm": o.get("depth_mm"),
                        "force_N": o.get("force_N"), "work_Nmm": o.get("work_Nmm"),
                        "mode": o.get("mode"), "place": place, "node": o.get("node")})
    return out


# ---- 2. Checks ------------------------------------------------------------------------------

def olsson_threshold(t):
    """Davies-Zhang with Olsson's D* = sqrt(D11 D22 (A + 1)/2), recomputed from the stiffnesses
    path.json reports (docs/theory/failure.md 4)."""
    mean = math.sqrt(t["D11_Nmm"] * t["D22_Nmm"])
    a = (t["D12_Nmm"] + 2 * t["D66_Nmm"]) / mean
    d_star = mean * math.sqrt((1 + a) / 2)
    n = t["delaminations"]
    return math.pi * math.sqrt(32 * d_star * t["G_IIc_N_per_mm"] / (n + 2))


def checks(run, cases):
    problems = []
    if run["exit_code"] != 0:
        problems.append(f"sweep exit {run['exit_code']}: {' | '.join(run['stderr_tail'])}")
    for c in cases:
        name = c["layup"]
        if c["status"] not in ("completed", "reached_bound"):  # reached_bound: on depth_max
            problems.append(f"{name}: {c['status']} ({c['reason']})")
            continue
        depth, force = column(c["rows"], DEPTH_MM), column(c["rows"], FORCE_N)
        for crit, col, _ in CRITERIA:
            o = c["onsets"].get(crit)
            if not o:
                continue
            h = o["depth_mm"]
            if not o["located"]:
                problems.append(f"{name} {crit}: onset at {h} mm not located")
            k = next((i for i, d in enumerate(depth) if d >= h - 1e-9), None)
            index = column(c["rows"], col)
            if k is None or k == 0 or not (index[k - 1] < 1 <= index[k] + 1e-6):
                problems.append(f"{name} {crit}: onset at {h} mm not bracketed by {col}")
            w = trapezoid_work(depth, force, h)
            if w is None or abs(w - o["work_Nmm"]) > 1e-6 * (1 + abs(w)):
                problems.append(f"{name} {crit}: work {o['work_Nmm']} at the onset, the path's "
                                f"trapezoid gives {w}")
        t = c["threshold"]
        if t and abs(olsson_threshold(t) - t["load_N"]) > 1e-9 * t["load_N"]:
            problems.append(f"{name}: threshold {t['load_N']} N, Davies-Zhang with Olsson's D* "
                            f"gives {olsson_threshold(t)} N")
        for e in c["energies"]:
            beyond = e["energy_Nmm"] > e["max_work_Nmm"]
            if (e["outcome"] == "beyond_path") != beyond:
                problems.append(f"{name}: impact energy {e['energy_Nmm']} N mm is "
                                f"{e['outcome']} with the path's largest work {e['max_work_Nmm']}")
    return problems


# ---- 3. Figures -----------------------------------------------------------------------------

def finish(fig, ax, xlabel, ylabel, directory, name):
    """Labels, grid and legend of a one-axes figure, saved."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    return save(fig, directory, name)


def index_figure(cases, directory, name="damage_index_depth.png"):
    """Each criterion's largest index over the monitored nodes against the depth, per lay-up."""
    fig, axes = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
    for ax, (crit, col, label) in zip(axes.flat, CRITERIA):
        for c in cases:
            if c["rows"] and col in c["rows"][0]:
                ax.plot(column(c["rows"], DEPTH_MM), column(c["rows"], col), label=c["layup"])
        ax.axhline(1.0, color="k", lw=0.8, ls="--")
        ax.set_title(label)
        ax.set_ylabel("failure index")
        ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("indenter travel h (mm)")
    axes[0][0].legend(fontsize=7)
    return save(fig, directory, name)


def apex_figure(cases, directory):
    """The Hashin index through the thickness at the apex at the first point past its onset."""
    fig, ax = plt.subplots(figsize=(7, 5))
    for c in cases:
        if c["apex"]:
            ax.plot([r["hashin_index"] for r in c["apex"]], [r["x3_mm"] for r in c["apex"]],
                    marker=".", label=f"{c['layup']} (h = {c['apex'][0][DEPTH_MM]:.3f} mm)")
    ax.axvline(1.0, color="k", lw=0.8, ls="--")
    return finish(fig, ax, "Hashin index at the apex", "x3 (mm, outer contacted face up)",
                  directory, "damage_apex_profile.png")


def force_figure(cases, directory, name="damage_onset_force.png"):
    """Onset force per criterion against theta, with the Davies-Zhang threshold."""
    fig, ax = plt.subplots(figsize=(7, 4.5))
    angle = sorted((c for c in cases if c["theta_deg"] is not None), key=lambda c: c["theta_deg"])
    for crit, _, label in CRITERIA:
        pts = [(c["theta_deg"], c["onsets"][crit]["force_N"] / 1000) for c in angle
               if crit in c["onsets"]]
        if pts:
            ax.plot(*zip(*pts), marker="o", label=label)
    thr = [(c["theta_deg"], c["threshold"]["load_N"] / 1000) for c in angle if c["threshold"]]
    if thr:
        ax.plot(*zip(*thr), "k--", marker="s", label="Davies-Zhang threshold (Olsson D*)")
    return finish(fig, ax, "theta (deg), [theta/-theta]2S", "onset force (kN)", directory, name)


# ---- 4. Report ------------------------------------------------------------------------------

def cell(v, fmt):
    return fmt % v if isinstance(v, (int, float)) else "-"


def onset_lines(cases):
    """The onset table's rows."""
    lines = ["| lay-up | criterion | h (mm) | F (kN) | W (J) | mode | where |",
             "|---|---|---:|---:|---:|---|---|"]
    for r in onset_table(cases):
        lines.append(f"| {r['layup']} | {r['criterion']} | {cell(r['depth_mm'], '%.4f')} | "
                     f"{cell(r['force_N'] and r['force_N'] / 1000, '%.3f')} | "
                     f"{cell(r['work_Nmm'] and r['work_Nmm'] / 1000, '%.4f')} | "
                     f"{r['mode'] or '-'} | {r['place'] or '-'} |")
    return lines


def threshold_lines(cases):
    """The threshold table's rows: Davies-Zhang beside the delamination criterion's onset."""
    lines = ["| lay-up | D* (N mm) | P_c (kN) | depth at P_c (mm) | delamination onset (kN) | "
             "onset / P_c | impact energies: depth (mm) |",
             "|---|---:|---:|---:|---:|---:|---|"]
    for c in cases:
        t = c["threshold"] or {}
        onset = c["onsets"].get("delamination", {}).get("force_N")
        ratio = onset / t["load_N"] if onset and t.get("load_N") else None
        energies = ", ".join(
            f"{e['energy_Nmm'] / 1000:g} J: " +
            (f"{e['depth_mm']:.4f}" if e["outcome"] == "reached" else "beyond")
            for e in c["energies"])
        lines.append(f"| {c['layup']} | {cell(t.get('D_effective_Nmm'), '%.0f')} | "
                     f"{cell(t.get('load_N') and t['load_N'] / 1000, '%.3f')} | "
                     f"{cell(t.get('path_depth_mm'), '%.4f')} | "
                     f"{cell(onset and onset / 1000, '%.3f')} | {cell(ratio, '%.2f')} | "
                     f"{energies or '-'} |")
    return lines


def report(report_dir, args, run, cases, plate_run, plate_cases, problems, wall, measured):
    lines = [
        "# Damage onset on the source paper's cap and on a QSI specimen, eight lay-ups",
        "",
        f"Generated by `studies/damage_onset.py` on {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, "
        f"mode: {'quick' if args.quick else 'full'}. Do not edit by hand: rerun the script with "
        "`--report-dir docs/` (it rewrites this file and `docs/figures/damage_*.png`). What the "
        "criteria, the recovery and the threshold are: [theory/failure.md](theory/failure.md); "
        "the strengths and toughness of `paper-carbon-epoxy` are assumed "
        "([materials.md](materials.md)), so the numbers below are those of the model with these "
        "assumptions, not predictions for the paper's (unnamed) material.",
        "",
        "```sh",
        "studies/damage_onset.py -j 2                     # results/damage_onset_study/",
        "studies/damage_onset.py -j 2 --report-dir docs/  # the same, and rewrites this report",
        "studies/damage_onset.py --quick                  # smoke test (ctest)",
        "```",
        "",
        "## What was run",
        "",
        "`studies/damage_onset.yaml` on `studies/damage_onset_cap.yaml`: the paper's cap (clamped, "
        "base radius 25 mm, R = 80.9 mm, 8 plies of 0.475 mm, 12.7 mm sphere on the outer face), "
        "nonlinear, full model, pseudo-arclength from first touch, with `damage: {criteria: "
        "[max_stress, tsai_wu, hashin, delamination], threshold: {stiffness: olsson}, "
        "impact_energies: [...]}`: refined recovery (the zig-zag refinement and equilibrium shear) "
        "at the contact candidates, the indices at the bottom, middle and top of every ply and on "
        "every interface, each onset located where the largest index reaches 1.",
        "",
        f"Sweep exit {run['exit_code']}, wall {wall:.1f} s with `-j {args.jobs}` "
        f"(CPU {cell(run.get('cpu_s'), '%.1f')} s; measured {measured}).",
        "",
        "`studies/damage_onset_d7136.yaml` on `studies/damage_onset_d7136_plate.yaml`: the same "
        "laminates as a quasi-static indentation specimen, the 150 x 100 mm plate of ASTM D7136 on "
        "the standard's fixture (125 x 75 mm cut-out, four clamps, the plate free to lift off the "
        "frame), pressed at its centre by the 16 mm hemispherical impactor to 5 mm, nonlinear, "
        "with the same damage monitors. Sweep exit "
        f"{plate_run['exit_code']} (CPU {cell(plate_run.get('cpu_s'), '%.1f')} s).",
        "",
        "## Read this first: what converges with the mesh",
        "",
        "The recovery reads Hertz's pressure of the indenter's force on the contacted face (the "
        "laminate's anisotropic half-space sizing the contact radius) and fits the shell's "
        "strains over twice the laminate's thickness around each node (`damage.face_pressure: "
        "hertz`, `damage.patch_radius`, the defaults). Measured on three meshes of the [0/90]2S "
        "cap: the maximum-stress onset (the face's compression) is Hertz's closed form on every "
        "mesh, and the Tsai-Wu, Hashin and delamination onset forces agree within 0.6 % (the "
        "depths within 5-10 %). The patch's length is a modelling choice that moves the onsets "
        "(Hashin's by 12 % between one and two thicknesses): the numbers, and why: "
        "[theory/failure.md](theory/failure.md) section 7.",
        "",
        "## Onsets per lay-up",
        "",
        "Depth h (mm) of indenter travel, contact force F (kN), indenter work W (J: the impact "
        "energy of the same damage under quasi-static equivalence) and where (mode; ply counted "
        "from the inner face, 8 = the contacted outer ply; interface k/k+1). '-': no onset on the "
        "path.",
        ""]
    lines += onset_lines(cases)
    lines += ["", "## Davies-Zhang threshold and impact energies", "",
              "The closed-form threshold P_c = pi sqrt(32 D* G_IIc / 3) (Olsson's D*, G_IIc = the "
              "assumed 0.788 N/mm) and the depth where the path's force reaches it; the depth at "
              "each impact energy ('beyond' when the path's work never reaches it: not "
              "extrapolated). Beside it the force where the delamination criterion (Brewer-Lagace "
              "on the interfaces) first reaches 1: the two are independent estimates (a fracture-"
              "mechanics threshold for an existing crack's growth against a stress criterion for "
              "its initiation), shown side by side, not fitted to each other.", ""]
    lines += threshold_lines(cases)
    lines += ["", "## The QSI specimen: ASTM D7136 plate on its fixture", "",
              "The same criteria on the plate (ply 8 = the contacted face). The 16 mm impactor "
              "(R = 8 mm) against the cap's effective 10.98 mm (the 12.7 mm sphere on its 80.9 mm "
              "surface) raises Hertz's face pressure at a given force, so the face-compression "
              "onsets come at about (8 / 10.98)^2 = 0.53 of the cap's force; the flat plate on its "
              "125 x 75 mm window is far more compliant than the clamped cap, so every force "
              "needs more travel. The plate's mesh (1 mm under the impactor, graded to 4 mm) was "
              "not put through the cap's three-mesh convergence check.", ""]
    lines += onset_lines(plate_cases)
    lines += [""] + threshold_lines(plate_cases)
    lines += ["", "![index against depth, D7136 plate](figures/damage_d7136_index_depth.png)", "",
              "![onset forces against theta, D7136 plate](figures/damage_d7136_onset_force.png)",
              ""]
    lines += ["", "## Figures (the cap)", "",
              "![index against depth](figures/damage_index_depth.png)", "",
              "Each criterion's largest index over the monitored nodes against the indenter "
              "travel (path.csv's `<criterion>_index` columns); onset where it crosses 1.", "",
              "![Hashin index through the thickness at the apex](figures/damage_apex_profile.png)",
              "",
              "The Hashin index through the thickness at the apex (damage_points.csv: bottom, "
              "middle and top of every ply) at the first converged point at or past the Hashin "
              "onset. The governing node of the onset (the table's node) may be off the apex; "
              "the per-ply fields at every monitored node are in the VTU files "
              "(`hashin_index_ply<k>`).", "",
              "![onset forces against theta](figures/damage_onset_force.png)", "",
              "## Checks", ""]
    lines += (["All passed: every case reached depth_max; every onset located and bracketed by the "
               "path's own index column; each onset's work equal to the trapezoidal work of "
               "path.csv at its depth; each threshold equal to Davies-Zhang with Olsson's D* "
               "recomputed from the reported D11, D22, D12, D66; each impact energy reached "
               "exactly when the path's largest work exceeds it."] if not problems
              else ["FAILED:", ""] + [f"- {p}" for p in problems])
    lines.append("")
    path = os.path.join(report_dir, "damage-onset.md")
    with open(path, "w") as f:
        f.write("\n".join(lines))
    return path


def main():
    args = parse_args()
    if not os.path.exists(args.exe):
        sys.exit(f"error: no executable {args.exe} (build first, or give --exe)")
    out = os.path.abspath(args.out or os.path.join(
        SOURCE_DIR, "results", "damage_onset_study" + ("_quick" if args.quick else "")))
    report_dir = os.path.abspath(args.report_dir or os.path.join(out, "report"))
    figures_dir = os.path.join(report_dir, "figures")
    os.makedirs(figures_dir, exist_ok=True)
    run = run_sweep(args.exe, os.path.join(STUDIES_DIR, "damage_onset.yaml"),
                    os.path.join(out, "sweep"), args.jobs, args.quick)
    wall, measured = measured_wall_time(run)
    plate_run = run_sweep(args.exe, os.path.join(STUDIES_DIR, "damage_onset_d7136.yaml"),
                          os.path.join(out, "sweep_d7136"), args.jobs, args.quick)
    cases, plate_cases = case_results(run), case_results(plate_run)
    columns = ["layup", "criterion", "depth_mm", "force_N", "work_Nmm", "mode", "place", "node"]
    write_csv(os.path.join(out, "onsets.csv"), columns, onset_table(cases))
    write_csv(os.path.join(out, "onsets_d7136.csv"), columns, onset_table(plate_cases))
    for draw in (index_figure, apex_figure, force_figure):
        draw(cases, figures_dir)
    index_figure(plate_cases, figures_dir, "damage_d7136_index_depth.png")
    force_figure(plate_cases, figures_dir, "damage_d7136_onset_force.png")
    problems = checks(run, cases) + [f"D7136 plate: {p}" for p in checks(plate_run, plate_cases)]
    path = report(report_dir, args, run, cases, plate_run, plate_cases, problems, wall, measured)
    print(f"damage_onset: wrote {path}; sweep {wall:.1f} s", file=sys.stderr)
    if problems:
        print("damage_onset: CHECKS FAILED:\n  " + "\n  ".join(problems), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
