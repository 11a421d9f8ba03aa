"""Reads CalculiX's .dat output (*NODE PRINT blocks) and turns a run into the reference
quantities: travel, contact force, apex mid-surface deflection, contact radius."""
from __future__ import annotations

import re

import numpy as np

_HEADER = re.compile(r"^\s*(displacements|total force|forces)\s*\(([^)]*)\)\s*for set\s+(\S+)"
                     r"\s+and time\s+(\S+)")


def read_dat(path: str) -> dict:
    """{(kind, set): {time: array}}: kind 'u' (rows: node, ux, uy, uz) or 'rf_total' (3,)."""
    out: dict = {}
    kind = None
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        m = _HEADER.match(lines[i])
        if not m:
            i += 1
            continue
        what, _, name, t = m.groups()
        t = float(t)
        kind = {"displacements": "u", "total force": "rf_total", "forces": "rf"}[what]
        i += 1
        rows = []
        while i < len(lines) and not lines[i].strip():
            i += 1
        while i < len(lines) and lines[i].strip() and not _HEADER.match(lines[i]):
            rows.append([float(v) for v in lines[i].split()])
            i += 1
        arr = np.array(rows)
        if kind == "rf_total":
            arr = arr.reshape(-1)[:3]
        out.setdefault((kind, name), {})[t] = arr
    return out


def contact_radius(line_u: np.ndarray, ref: dict, centre: np.ndarray, radius: float) -> float:
    """Plan distance from the axis of the outermost point of the outer face inside the
    indenter, along one line of top-surface nodes (deformed positions; linear interpolation
    of the overclosure between the last node in and the first node out)."""
    nodes = line_u[:, 0].astype(int)
    x = np.array([ref[n] for n in nodes]) + line_u[:, 1:4]
    r = np.hypot(x[:, 0], x[:, 1])
    order = np.argsort(r)
    r, x = r[order], x[order]
    over = radius - np.linalg.norm(x - centre, axis=1)
    inside = np.nonzero(over > 0)[0]
    if len(inside) == 0:
        return 0.0
    k = inside.max()
    if k + 1 >= len(r):
        return float(r[k])
    return float(r[k] + (r[k + 1] - r[k]) * over[k] / (over[k] - over[k + 1]))


def results(dat: dict, info: dict) -> list[dict]:
    """One row per printed time: travel, force, apex deflections, contact radii."""
    rows = []
    force = dat[("rf_total", "NIND")]
    ref = {int(k): np.array(v) for k, v in info["line_ref"].items()}
    for t in sorted(force):
        travel = t * info["travel"]
        centre = np.array(info["indenter_centre"]) - np.array([0.0, 0.0, travel])
        row = dict(travel_mm=travel, force_N=-force[t][2] * info["factor"])
        row["apex_mid_w_mm"] = -dat[("u", "NAPEX")][t][0, 3]
        top = dat.get(("u", "NAPEXTOP"), {}).get(t)
        row["apex_top_w_mm"] = -top[0, 3] if top is not None else float("nan")
        row["approach_mm"] = travel - row["apex_mid_w_mm"]
        row["reaction_N"] = dat[("rf_total", "NFIX")][t][2] * info["factor"] \
            if ("rf_total", "NFIX") in dat else float("nan")
        for key, name in (("x", "NLINEX"), ("y", "NLINEY"), ("d", "NLINED")):
            u = dat.get(("u", name), {}).get(t)
            row[f"a_{key}_mm"] = (contact_radius(u, ref, centre, info["indenter_radius"])
                                  if u is not None and len(u) else float("nan"))
        rows.append(row)
    return rows
