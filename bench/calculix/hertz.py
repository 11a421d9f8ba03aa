#!/usr/bin/python3
"""The Hertz sanity check of the 3-D reference's contact settings (issue 20, acceptance 1).

  /usr/bin/python3 bench/calculix/hertz.py [TAG ...]     (default: every hertz_* run)

A rigid sphere (R = 12.7 mm) on a thick isotropic block (E = 10 GPa, nu = 0.3; a quarter
cylinder of radius and depth 50 mm, bottom fixed) meshed with the cap's contact-zone grading
and the same face-to-face penalty contact. Two comparisons per printed travel d:

* force against Hertz at the travel: F = 4/3 E* R^0.5 d^1.5, E* = E / (1 - nu^2). The block is
  not a half-space: its fixed bottom at depth D adds roughly the Boussinesq displacement
  F (1 + nu) (3 - 2 nu) / (2 pi E D) to the travel (printed as `finite_block_pct`, the force
  error it causes, 1.5 times the relative travel).
* force against Hertz at the approach relative to an axis node at depth z0 (a few contact
  radii down): d - w(z0) = -integral_0^z0 eps_z dz with Hertz's stresses on the axis (Johnson,
  Contact Mechanics, 1985, eq. 3.45). The block's far boundary moves the near field almost
  rigidly, so this comparison is free of the block size.

Writes results/hertz.csv.
"""
from __future__ import annotations

import csv
import json
import math
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import ccxdat  # noqa: E402

E, NU, RI, DEPTH = 10e3, 0.3, 12.7, 50.0
ESTAR = E / (1 - NU ** 2)


def hertz_force(d):
    return 4 / 3 * ESTAR * math.sqrt(RI) * d ** 1.5


def relative_approach(force: float, z0: float) -> float:
    """Hertz: displacement of the surface point on the axis towards the body, relative to the
    axis point at depth z0 (> 0), under a total force `force` (mm)."""
    a = (3 * force * RI / (4 * ESTAR)) ** (1 / 3)
    p0 = 3 * force / (2 * math.pi * a * a)
    z = a * np.geomspace(1e-5, z0 / a, 4000)
    zeta = z / a
    sr = p0 * (-(1 + NU) * (1 - zeta * np.arctan(1 / zeta)) + 0.5 / (1 + zeta ** 2))
    sz = -p0 / (1 + zeta ** 2)
    eps = (sz - 2 * NU * sr) / E
    eps0 = (-p0 - 2 * NU * p0 * (-(1 + 2 * NU) / 2)) / E  # the limit at the surface
    z = np.concatenate([[0.0], z])
    eps = np.concatenate([[eps0], eps])
    return float(-np.sum(0.5 * (eps[1:] + eps[:-1]) * np.diff(z)))


def force_at_relative_approach(delta: float, z0: float) -> float:
    lo, hi = 1e-6, 1e7
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        if relative_approach(mid, z0) < delta:
            lo = mid
        else:
            hi = mid
    return math.sqrt(lo * hi)


def analyse(tag: str) -> list[dict]:
    work = HERE / "work" / tag
    info = json.loads((work / "info.json").read_text())
    dat = ccxdat.read_dat(str(work / "job.dat"))
    rows = []
    axis = dat[("u", "NAXISLINE")]
    ref = {int(k): v for k, v in info["axis_ref"].items()}
    for t in sorted(dat[("rf_total", "NIND")]):
        d = t * info["travel"]
        f = -dat[("rf_total", "NIND")][t][2] * info["factor"]
        u = axis[t]
        depth = np.array([-ref[int(n)][2] for n in u[:, 0]])
        w = -u[:, 3]
        a = math.sqrt(RI * d)
        row = dict(tag=tag, level=info["level"], h_mm=info["h"], penalty=info["penalty"],
                   travel_mm=d, force_N=f, hertz_N=hertz_force(d),
                   ratio=f / hertz_force(d), hertz_a_mm=a,
                   finite_block_pct=100 * 1.5 * f * (1 + NU) * (3 - 2 * NU)
                   / (2 * math.pi * E * DEPTH) / d)
        for mult in (5, 10):
            z0 = mult * a
            k = int(np.argmin(abs(depth - z0)))
            z0, wz = depth[k], w[k]
            delta = d - wz
            fh = force_at_relative_approach(delta, z0)
            row[f"z0_{mult}a_mm"] = z0
            row[f"ratio_rel_{mult}a"] = f / fh
        rows.append(row)
    return rows


def main(argv=None):
    tags = (argv if argv else sys.argv[1:]) or sorted(
        p.name for p in (HERE / "work").glob("hertz_*") if (p / "job.dat").exists())
    rows = []
    for tag in tags:
        rows += analyse(tag)
    if not rows:
        print("no Hertz runs found", file=sys.stderr)
        return 1
    out = HERE / "results" / "hertz.csv"
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    print(f"{'tag':24s} {'h':>5s} {'d_mm':>7s} {'F_FE':>9s} {'F_Hertz':>9s} {'ratio':>6s} "
          f"{'block%':>6s} {'rel@5a':>7s} {'rel@10a':>7s}")
    for r in rows:
        print(f"{r['tag']:24s} {r['h_mm']:5.2f} {r['travel_mm']:7.4f} {r['force_N']:9.2f} "
              f"{r['hertz_N']:9.2f} {r['ratio']:6.4f} {r['finite_block_pct']:6.2f} "
              f"{r['ratio_rel_5a']:7.4f} {r['ratio_rel_10a']:7.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
