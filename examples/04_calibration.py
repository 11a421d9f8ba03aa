#!/usr/bin/env python3
"""Example 4: calibrate two elastic constants of a case against a measured force-travel curve.

An indentation test gives the force against the indenter's travel. Two constants of the
laminate are poorly known: E3, the through-thickness modulus (it sets the local dent under the
indenter, Yang-Sun's law), and G13, the transverse shear modulus (it sets how the shell bends
under a concentrated load). Here the "measured" curve is made by the model itself with
E3 = 8 GPa and G13 = 4 GPa plus 1 % noise, so we know the answer; shellindent.calibrate() then
starts from the handbook's 10 and 3 GPa, runs the case again and again (NLopt's BOBYQA), and
reports the optimum with standard errors, 95 % intervals, the correlation of the two and any
warning that the data cannot separate them. The check: the truth lies in both intervals.

    PYTHONPATH=build/python /usr/bin/python3 examples/04_calibration.py [--quick] [--out DIR]

Writes DIR/measured.csv and what `shellindent calibrate` writes (calibration.json,
calibration_curve.csv, calibrated_case.yaml). Full: the paper's cap on its default mesh (about
40 runs, 70 s of CPU on 2 cores, docs/calibration.md); --quick: a coarse quarter mesh (ctest:
python_example_04_calibration: 44 runs, 4 s of CPU). Exit 1 if the calibration does not converge or the
truth is outside an interval. The same from the shell:
    shellindent calibrate DIR/case.yaml --data DIR/measured.csv --param material.E3=4:20GPa \\
        --param material.G13=1:8GPa -j 2
"""

import argparse
import os
import sys

import numpy as np

import shellindent as si

# The paper's carbon/epoxy written out, so that E3 and G13 can be changed (GPa).
HANDBOOK = {"type": "orthotropic", "E1": "130 GPa", "E2": "10 GPa", "E3": "10 GPa",
            "G12": "6 GPa", "G13": "3 GPa", "G23": "6 GPa", "nu12": 0.3, "nu13": 0.5,
            "nu23": 0.3}
TRUTH = {"material.E3": 8000.0, "material.G13": 4000.0}  # MPa
CASE = {
    "material": HANDBOOK,
    "laminate": {"layup": "[0/0]2S", "ply_thickness": "0.475 mm"},
    "mesh": {"symmetry": "quarter"},  # the paper's cap: 0.5 mm at the apex
    "indenter": {"shape": "sphere", "radius": "12.7 mm",
                 "material": {"type": "isotropic", "E": "200 GPa", "nu": 0.3}},
    "contact": {"local": "yang_sun"},  # the local dent in series with the shell
    "path": {"depth_max": "3 mm", "step": "0.1 mm"},
}
QUICK_MESH = {"size_apex": "1.5 mm", "size_edge": "4 mm", "refine_radius": "8 mm",
              "symmetry": "quarter"}
TRAVEL = 0.3 * np.arange(1, 11)  # mm: where the "test" recorded the force


def measured_curve(case, seed=1):
    """The "test": the case with the true E3 and G13, its force at TRAVEL (a natural path that
    stops at each travel), plus Gaussian noise of 1 % of the largest force."""
    material = dict(HANDBOOK, E3=f"{TRUTH['material.E3']} MPa",
                    G13=f"{TRUTH['material.G13']} MPa")
    truth = dict(case, material=material,
                 path={"method": "natural", "depth_max": "3 mm", "step": "0.1 mm",
                       "depths": [f"{t:.1f} mm" for t in TRAVEL]})
    result = si.run(truth, threads=1)
    if not result.completed:
        sys.exit(f"the run that makes the measured curve stopped: {result.reason}")
    depth, force = result["depth_mm"], result["force_N"]
    clean = np.array([force[np.argmin(abs(depth - t))] for t in TRAVEL])
    noise = np.random.default_rng(seed).standard_normal(len(clean))
    return clean + 0.01 * clean[-1] * noise


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out", default="results/example_04_calibration")
    args = parser.parse_args()
    case = dict(CASE, mesh=QUICK_MESH) if args.quick else CASE
    os.makedirs(args.out, exist_ok=True)

    # 1. The measured curve, written as a test machine's CSV would be (units in the header).
    force = measured_curve(case)
    data = os.path.join(args.out, "measured.csv")
    with open(data, "w") as f:
        f.write("travel_mm,force_N\n")
        f.writelines(f"{t:.3f},{y:.6f}\n" for t, y in zip(TRAVEL, force))
    case_file = os.path.join(args.out, "case.yaml")  # the case as a file: the report names it
    with open(case_file, "w") as f:
        f.write(si.case_yaml(case))
    print(f"measured: {len(TRAVEL)} points, {force[0]:.0f} N at {TRAVEL[0]:.1f} mm to "
          f"{force[-1]:.0f} N at {TRAVEL[-1]:.1f} mm")

    # 2. The calibration: the case's E3 and G13 within bounds, from the handbook's values.
    #    Each line: one run of the case (warm-started from the nearest earlier one).
    result = si.calibrate(case_file, data, {"material.E3": "4:20 GPa", "material.G13": "1:8 GPa"},
                          jobs=2, progress=lambda p: print(p["line"]))

    # 3. The answer, with its uncertainty.
    print()
    print(result.table)
    ok = result.converged
    for key, truth in TRUTH.items():
        low, high = result.intervals[key]
        inside = low <= truth <= high
        ok = ok and inside
        print(f"{key}: {result.parameters[key]:.0f} MPa, 95 % interval [{low:.0f}, {high:.0f}] "
              f"MPa; the truth, {truth:.0f} MPa, is {'inside' if inside else 'OUTSIDE'}")
    print(f"correlation of the two estimates: {result.correlation[0, 1]:+.2f} "
          "(negative: a stiffer E3 and a softer G13 give nearly the same curve)")
    for w in result.warnings:
        print("warning:", w)
    result.write(args.out)
    print(f"wrote {args.out}/calibration.json, calibration_curve.csv, calibrated_case.yaml")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
