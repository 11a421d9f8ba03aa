#!/usr/bin/env python3
"""Example 2: a sweep over lay-ups in Python, two cases at a time.

The paper's study: the cap with [theta/-theta]2S for several angles and [0/90]2S, each the same
shell and sphere. For each lay-up: the bending stiffness D11 of its section (VAM) and the force
at the end of the path. The runs go through a thread pool: the module releases the GIL while it
solves, so two threads keep two cores busy (one assembly thread each).

    PYTHONPATH=build/python /usr/bin/python3 examples/02_layup_sweep.py [--quick] [--out DIR]

Writes DIR/sweep.csv (lay-up, D11, force at depth_max, status); --quick: two lay-ups on a coarse
mesh to 1.5 mm (ctest: python_example_02_layup_sweep). Exit 1 if a case does not reach
depth_max or a force is not positive.
"""

import argparse
import csv
import os
import sys
from concurrent.futures import ThreadPoolExecutor

import shellindent as si

LAYUPS = ["[0/0]2S", "[15/-15]2S", "[30/-30]2S", "[45/-45]2S", "[60/-60]2S", "[75/-75]2S",
          "[90/-90]2S", "[0/90]2S"]
QUICK_LAYUPS = ["[0/0]2S", "[45/-45]2S"]


def case_for(layup, quick):
    """The cap of example 1 with the lay-up `layup`: a full model (angle plies are not
    specially orthotropic, so a quarter model would not be exact)."""
    mesh = ({"size_apex": "2 mm", "size_edge": "5 mm", "refine_radius": "10 mm"} if quick
            else {"size_apex": "0.5 mm", "size_edge": "2 mm", "refine_radius": "13 mm"})
    mesh["symmetry"] = "full"
    return {
        "material": "paper-carbon-epoxy",
        "laminate": {"layup": layup, "ply_thickness": "0.475 mm"},
        "shell": {"type": "spherical_cap", "base_radius": "25 mm", "radius": "80.9 mm",
                  "edge": "clamped"},
        "mesh": mesh,
        "indenter": {"shape": "sphere", "radius": "12.7 mm"},
        "path": {"method": "pseudo_arclength", "depth_max": "1.5 mm" if quick else "10 mm",
                 "step": "0.25 mm" if quick else "0.1 mm"},
    }


def one(layup, quick):
    # 1. Each case: read (errors name the lay-up), section, run with one assembly thread.
    case = si.read_case(case_for(layup, quick), label=layup)
    d11 = si.section(case)["vam"]["A_R"][3, 3]
    result = si.run(case, threads=1)
    return {"layup": layup, "D11_Nmm": d11, "force_N": result["force_N"][-1],
            "depth_mm": result["depth_mm"][-1], "status": result.status}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out", default="results/example_02_layup_sweep")
    parser.add_argument("-j", "--jobs", type=int, default=2, help="cases at once")
    args = parser.parse_args()
    layups = QUICK_LAYUPS if args.quick else LAYUPS

    # 2. Two at a time: the threads wait on the solver, not on each other (the GIL is free).
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        rows = list(pool.map(lambda l: one(l, args.quick), layups))

    # 3. The table, on screen and as CSV.
    print(f"{'lay-up':12} {'D11 N mm':>10} {'force N':>10} {'at mm':>6}  status")
    for r in rows:
        print(f"{r['layup']:12} {r['D11_Nmm']:10.1f} {r['force_N']:10.2f} {r['depth_mm']:6.2f}"
              f"  {r['status']}")
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "sweep.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print("wrote", os.path.join(args.out, "sweep.csv"))

    # 4. The checks: every case ran to depth_max; the force is positive.
    failed = [r["layup"] for r in rows if r["status"] not in ("completed", "reached_bound")]
    if failed or any(r["force_N"] <= 0 for r in rows):
        print("check failed:", failed or "a force is not positive")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
