#!/usr/bin/env python3
"""Example 3: calibrate the contact law T = C1 h^C2 on a computed path.

The paper condenses each force-depth curve into the two constants of a power law. Here: run the
cap of example 1, fit T = C1 h^C2 to its path twice - by least squares on T (NLopt and
Levenberg-Marquardt, fitting/) and by a straight line in log-log space - and compare. The two
estimate the same curve with different weights (absolute errors on T against relative ones), so
they need not agree to the last digit, but both must describe the path (R^2 close to 1) and give
an exponent a shell under a sphere can have (0.9 <= C2 <= 3: 1 for a point load on a linear
shell, more as the contact patch grows and the membrane stiffens).

    PYTHONPATH=build/python /usr/bin/python3 examples/03_power_law_fit.py [--quick] [--out DIR]

Writes DIR/fit.json (both fits) and DIR/path.csv; --quick: a coarse mesh to 3 mm (ctest:
python_example_03_power_law_fit). Exit 1 if a fit does not converge or the checks fail.
(`shellindent calibrate` fits the model's own parameters to a measured curve; this example only
fits a curve to computed points, as `shellindent fit` does.)
"""

import argparse
import json
import os
import sys

import numpy as np

import shellindent as si

CASE = {
    "material": "paper-carbon-epoxy",
    "laminate": {"layup": "[0/0]2S", "ply_thickness": "0.475 mm"},
    "mesh": {"symmetry": "quarter"},
    "path": {"depth_max": "10 mm", "step": "0.1 mm"},
}
QUICK = {"mesh": {"size_apex": "1.5 mm", "size_edge": "4 mm", "symmetry": "quarter"},
         "path": {"depth_max": "3 mm", "step": "0.25 mm"}}
C2_PHYSICAL_RANGE = (0.9, 3.0)


def describe(name, fit):
    print(f"{name}: {fit['status']} ({fit['method']})")
    for n, v, lo, hi in zip(fit["names"], fit["parameters"], fit["ci_lower"], fit["ci_upper"]):
        print(f"  {n} = {v:.6g}   95 % interval [{lo:.6g}, {hi:.6g}]")
    print(f"  R^2 = {fit['r_squared']:.6f}, RMSE = {fit['rmse']:.4g}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out", default="results/example_03_power_law_fit")
    args = parser.parse_args()
    case = dict(CASE, **QUICK) if args.quick else CASE  # the rest: the paper's cap (defaults)

    # 1. The path (the defaults of the case file are the paper's cap and sphere).
    result = si.run(case)
    if not result.completed:
        print("the run stopped:", result.reason)
        return 1
    result.write(args.out)

    # 2. The points past first touch: h = 0 carries no information on C1, C2 (and log 0).
    h, force = result["depth_mm"], result["force_N"]
    keep = h > 0
    h, force = h[keep], force[keep]

    # 3. Two fits of the same law.
    direct = si.fit(h, force, "power")
    loglog = si.fit(h, force, "power-log")
    describe("T = C1 h^C2, least squares on T", direct)
    describe("ln T = ln C1 + C2 ln h, least squares on ln T", loglog)

    # 4. The fitted curve against the path, at a few depths.
    c1, c2 = direct["parameters"]
    for d in np.linspace(h[0], h[-1], 4):
        print(f"  h = {d:6.3f} mm: path {np.interp(d, h, force):9.2f} N, "
              f"C1 h^C2 {c1 * d ** c2:9.2f} N")
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "fit.json"), "w") as f:
        json.dump({name: {k: (v.tolist() if isinstance(v, np.ndarray) else v)
                          for k, v in fit.items()}
                   for name, fit in (("power", direct), ("power-log", loglog))}, f, indent=2)

    # 5. The checks.
    problems = []
    for name, fit in (("power", direct), ("power-log", loglog)):
        exponent = fit["parameters"][1]
        if fit["status"] != "converged":
            problems.append(f"{name}: {fit['status']} ({fit['reason']})")
        if not C2_PHYSICAL_RANGE[0] <= exponent <= C2_PHYSICAL_RANGE[1]:
            problems.append(f"{name}: C2 = {exponent:.4g} outside {C2_PHYSICAL_RANGE}")
        if fit["r_squared"] < 0.99:
            problems.append(f"{name}: R^2 = {fit['r_squared']:.4f} < 0.99")
    for p in problems:
        print("check failed:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
