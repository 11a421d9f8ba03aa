#!/usr/bin/env python3
"""Example 1: one indentation run from Python.

The source paper's clamped carbon/epoxy cap ([0/0]2S, base radius 25 mm, R = 80.9 mm, 3.8 mm
thick) pressed by a rigid 12.7 mm sphere, built as a dict with unit strings, run with a progress
line per converged point, and checked: the indenter's work must equal the strain energy stored
in the shell (frictionless, elastic: nothing is dissipated; paper-notes item 8).

    PYTHONPATH=build/python /usr/bin/python3 examples/01_run.py [--quick] [--out DIR]

Writes DIR/path.csv, path.json and events.json (as `shellindent run` does); --quick runs a coarse
mesh to 3 mm (ctest: python_example_01_run). Exit 1 if the check fails.
"""

import argparse
import sys

import shellindent as si

# 1. The case. Every quantity carries its unit; keys left out take the paper's defaults
#    (docs/case-file.md). The quarter model is exact for a specially orthotropic lay-up.
CASE = {
    "material": "paper-carbon-epoxy",
    "laminate": {"layup": "[0/0]2S", "ply_thickness": "0.475 mm"},
    "shell": {"type": "spherical_cap", "base_radius": "25 mm", "radius": "80.9 mm",
              "edge": "clamped"},
    "mesh": {"size_apex": "0.5 mm", "size_edge": "2 mm", "refine_radius": "13 mm",
             "symmetry": "quarter"},
    "indenter": {"shape": "sphere", "radius": "12.7 mm"},
    "path": {"method": "pseudo_arclength", "depth_max": "10 mm", "step": "0.1 mm"},
}
QUICK = {"mesh": {"size_apex": "1.5 mm", "size_edge": "4 mm"},
         "path": {"depth_max": "3 mm", "step": "0.25 mm"}}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="coarse mesh, 0-3 mm")
    parser.add_argument("--out", default="results/example_01_run")
    args = parser.parse_args()
    case = {k: dict(v) if isinstance(v, dict) else v for k, v in CASE.items()}
    if args.quick:
        for section, values in QUICK.items():
            case[section].update(values)

    # 2. Read it: the same reader as the CLI, so a typo raises InputError with file, line, key.
    case = si.read_case(case, label="example_01")

    # 3. Run it. The progress function sees each converged point by column name; returning
    #    False (or Ctrl-C) would stop the run, keeping what converged.
    def progress(p):
        print(f"  depth {p['depth_mm']:7.4f} mm  force {p['force_N']:10.2f} N  "
              f"contact nodes {p['contact_nodes']:.0f}", file=sys.stderr)

    result = si.run(case, progress=progress)
    print(f"{result.status}: {len(result)} points by {result.method}")

    # 4. The path is a dict of NumPy arrays named as path.csv's columns, units in the name.
    h, force = result["depth_mm"], result["force_N"]
    print(f"force at {h[-1]:.2f} mm: {force[-1]:.1f} N; maximum {force.max():.1f} N")
    for e in result.events:
        if e["type"] == "signature_change":  # the Jacobian's inertia: listed in events.json only
            continue
        print(f"event: {e['type']} {e['monitor']} at depth {e['depth_mm']:.3f} mm, "
              f"force {e['force_N']:.1f} N")
    for path in result.write(args.out):
        print("wrote", path)

    # 5. The check: work done by the indenter (trapezoidal integral of T dh) against the strain
    #    energy; the trapezoidal rule's error on this path is a few per cent at most.
    work, energy = result["work_Nmm"][-1], result["energy_Nmm"][-1]
    print(f"indenter work {work:.2f} N mm, strain energy {energy:.2f} N mm")
    if not result.completed or abs(work - energy) > 0.05 * work:
        print("check failed: the run did not complete or work and energy differ by > 5 %")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
