#!/usr/bin/python3
"""Where a D7136 plate bears on its support frame: shellindent against a CalculiX solid model.

  /usr/bin/python3 bench/calculix/d7136_frame.py --build build-test [--layup "[0/90]2S"]
      [--sizes 2.5,1.25] [--depth 0.1] [--clamps preset,none]

Issue 17 expected the plate to lift off the frame at its corners; shellindent's shell model
(docs/case-file.md, "fixture") keeps the corners down under the preset's clamps. This script
checks that against an independent model:

- shellindent: the quarter plate (150 x 100 mm, [0/90]2S, t = 3.8 mm) on the D7136 preset,
  linear kinematics, a 16 mm sphere pressed to `--depth`; the frame is a unilateral contact
  (Fischer-Burmeister rows solved by Newton with the shell).
- CalculiX: the same plate as a solid, one C3D8I element per ply through the thickness, on the
  *same plan grid* (shellindent's nodes), loaded by shellindent's own nodal contact forces on
  the top face. The frame is a set of u_z = 0 conditions on the bottom face's frame nodes, chosen
  by an active-set (Signorini) iteration around linear ccx solves: a node whose reaction pulls
  the plate down is released, a released node that sinks below the frame is held again, until
  neither happens. The clamp holds u_z = 0 on the column of nodes at shellindent's clamp node.

The problem is linear in the load once the contact set is fixed, so the comparison is of the
contact set and of the reactions per unit indenter force: which frame nodes bear, the clamp's
share, the frame's share, and the reaction in the plate's corner (beyond both cut-out edges).

Result (docs/theory/contact.md): both models bear at the corners under the preset's clamps and
lift them without clamps (`--clamps none`, the Kirchhoff corner effect).

Writes bench/calculix/results/d7136_frame.csv (one row per clamp choice and plan mesh) and
bench/calculix/results/d7136_frame_nodes_<clamps>_<size>.csv (the frame nodes: position, shell
and solid reaction and lift). Work directories (decks, ccx output): bench/calculix/work/.
"""
from __future__ import annotations

import argparse
import csv
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import ccxdat  # noqa: E402
import decks  # noqa: E402
from run_ccx import ensure_ccx  # noqa: E402

RESULTS = HERE / "results"
WORK = HERE / "work"

PLY_T = 0.475  # mm, the paper's ply (studies/damage_onset_d7136_plate.yaml)
WINDOW = (62.5, 37.5)  # half the D7136 cut-out, mm
CLAMP = (50.0, 43.75)  # the preset's clamp tip in the quarter x, y >= 0 (src/model/fixture_spec)

CASE = """material: paper-carbon-epoxy
laminate: {{layup: "{layup}", ply_thickness: {ply} mm, reference: mid}}
fixture: {{type: astm_d7136{clamps}}}
mesh: {{size_apex: {size} mm, size_edge: {size} mm, refine_radius: 6 mm, symmetry: quarter}}
kinematics: linear
indenter: {{shape: sphere, radius: 8 mm}}
path: {{depth_max: {depth} mm, step: {depth} mm}}
output: {{dir: out/, vtu_every: 0, at: [{depth} mm]}}
"""


def run_shellindent(build: Path, layup: str, size: float, depth: float, clamped: bool,
                    work: Path) -> dict:
    """Runs the quarter plate and returns its last state's plan grid and nodal fields."""
    import meshio  # python3-meshio, installed by scripts/setup.sh

    work.mkdir(parents=True, exist_ok=True)
    (work / "case.yaml").write_text(CASE.format(layup=layup, ply=PLY_T, size=size, depth=depth,
                                                 clamps="" if clamped else ", clamps: []"))
    shutil.rmtree(work / "out", ignore_errors=True)
    subprocess.run([str(build / "shellindent"), "run", "case.yaml"], cwd=work, check=True,
                   stdout=subprocess.DEVNULL)
    last = sorted((work / "out").glob("path_*.vtu"))[-1]
    m = meshio.read(last)
    scalar = lambda key: np.asarray(m.point_data[key]).reshape(-1)  # noqa: E731
    return dict(points=np.asarray(m.points), contact=scalar("contact_force"),
                frame_force=scalar("frame_force"), frame_gap=scalar("frame_gap"),
                w=np.asarray(m.point_data["displacement"])[:, 2])


class SolidPlate:
    """The plate as C3D8I on the shell's plan grid, one element per ply through the thickness."""

    def __init__(self, xs: np.ndarray, ys: np.ndarray, angles: list[float]):
        self.xs, self.ys = xs, ys
        self.angles = angles
        t = PLY_T * len(angles)
        self.zs = np.linspace(-t / 2, t / 2, len(angles) + 1)
        nx, ny, nz = len(xs), len(ys), len(self.zs)
        self.shape = (nz, ny, nx)
        X = np.stack(np.meshgrid(self.zs, ys, xs, indexing="ij"), axis=-1)[..., ::-1]
        self.nodes = X.reshape(-1, 3)

    def node(self, k: int, j: int, i: int) -> int:
        nz, ny, nx = self.shape
        return (k * ny + j) * nx + i

    def elements(self) -> list[tuple[int, list[int]]]:
        """(layer, 8 node indices) in C3D8I order: bottom face counter-clockwise, then top."""
        nz, ny, nx = self.shape
        out = []
        for k in range(nz - 1):
            for j in range(ny - 1):
                for i in range(nx - 1):
                    b = [self.node(k, j, i), self.node(k, j, i + 1), self.node(k, j + 1, i + 1),
                         self.node(k, j + 1, i)]
                    out.append((k, b + [n + ny * nx for n in b]))
        return out

    def deck(self, loads: dict[int, float], held: set[int], clamp: list[int]) -> str:
        parts = [decks._nodes(self.nodes)]
        elems = self.elements()
        for layer, angle in enumerate(self.angles):
            ids = [e for e, (k, _) in enumerate(elems) if k == layer]
            parts.append(f"*ELEMENT, TYPE=C3D8I, ELSET=L{layer}\n" + "\n".join(
                ", ".join(str(v) for v in [e + 1] + [n + 1 for n in elems[e][1]]) for e in ids)
                + "\n")
            a = np.radians(angle)
            parts.append(f"*ORIENTATION, NAME=O{layer}, SYSTEM=RECTANGULAR\n"
                         f"{np.cos(a):.15g}, {np.sin(a):.15g}, 0, {-np.sin(a):.15g}, "
                         f"{np.cos(a):.15g}, 0\n")
            parts.append(f"*SOLID SECTION, ELSET=L{layer}, MATERIAL=PLY, ORIENTATION=O{layer}\n")
        parts.append(decks._material("PLY", decks.PAPER_CARBON_EPOXY))
        x, y = self.nodes[:, 0], self.nodes[:, 1]
        parts.append(decks._nset("NSX", np.nonzero(np.abs(x) < 1e-9)[0]))
        parts.append(decks._nset("NSY", np.nonzero(np.abs(y) < 1e-9)[0]))
        parts.append(decks._nset("NCLAMP", clamp) if clamp else "")
        parts.append(decks._nset("NHELD", sorted(held)) if held else "")
        parts.append(decks._nset("NBOTTOM", self.bottom_frame_nodes()))
        parts.append("*BOUNDARY\nNSX, 1, 1\nNSY, 2, 2\n" + ("NCLAMP, 3, 3\n" if clamp else "")
                     + ("NHELD, 3, 3\n" if held else ""))
        parts.append("*STEP\n*STATIC\n*CLOAD\n" + "".join(
            f"{n + 1}, 3, {f:.15g}\n" for n, f in loads.items()))
        parts.append("*NODE PRINT, NSET=NBOTTOM\nU\n*NODE PRINT, NSET=NBOTTOM\nRF\n"
                     + ("*NODE PRINT, NSET=NCLAMP, TOTALS=ONLY\nRF\n" if clamp else "")
                     + "*END STEP\n")
        return "".join(parts)

    def bottom_frame_nodes(self) -> list[int]:
        nz, ny, nx = self.shape
        out = []
        for j, y in enumerate(self.ys):
            for i, x in enumerate(self.xs):
                if x >= WINDOW[0] - 1e-9 or y >= WINDOW[1] - 1e-9:
                    out.append(self.node(0, j, i))
        return out


def solve_signorini(plate: SolidPlate, loads: dict[int, float], clamp: list[int], work: Path,
                    max_rounds: int = 40) -> dict:
    """Active-set iteration of linear ccx solves; returns the bottom frame nodes' reactions
    (upward positive) and deflections, the clamp's reaction and the number of rounds."""
    ccx = ensure_ccx()
    work.mkdir(parents=True, exist_ok=True)
    frame = plate.bottom_frame_nodes()
    held = set(frame)  # start from the plate held on the whole frame
    for rounds in range(1, max_rounds + 1):
        (work / "job.inp").write_text(plate.deck(loads, held, clamp))
        with open(work / "ccx.log", "w") as log:
            subprocess.run(["nice", "-n", "5", ccx, "-i", "job"], cwd=work, stdout=log,
                           stderr=subprocess.STDOUT, check=True,
                           env={"OMP_NUM_THREADS": "1", "PATH": "/usr/bin:/bin"})
        dat = ccxdat.read_dat(str(work / "job.dat"))
        u = next(iter(dat[("u", "NBOTTOM")].values()))
        rf = next(iter(dat[("rf", "NBOTTOM")].values()))
        w = dict(zip(u[:, 0].astype(int) - 1, u[:, 3]))
        r = dict(zip(rf[:, 0].astype(int) - 1, rf[:, 3]))
        clamp_rf = next(iter(dat[("rf_total", "NCLAMP")].values()))[2] if clamp else 0.0
        pulls = {n for n in held if r[n] < 0}
        sinks = {n for n in frame if n not in held and w[n] < 0}
        if not pulls and not sinks:
            return dict(reaction=r, w=w, clamp=clamp_rf, rounds=rounds, held=held)
        held = (held - pulls) | sinks
    raise RuntimeError(f"active set not settled in {max_rounds} rounds ({work})")


def compare(build: Path, layup: str, size: float, depth: float, clamped: bool) -> dict:
    tag = "d7136_frame_{}_{}_{:g}".format(decks.layup_slug(layup),
                                          "clamps" if clamped else "noclamps", size)
    shell = run_shellindent(build, layup, size, depth, clamped, WORK / tag / "shellindent")
    p = shell["points"]
    xs = np.unique(np.round(p[:, 0], 9))
    ys = np.unique(np.round(p[:, 1], 9))
    if len(xs) * len(ys) != len(p):
        raise RuntimeError("the shell mesh is not a tensor grid; the solid needs one")
    plate = SolidPlate(xs, ys, decks.LAYUPS[layup])
    nz, ny, nx = plate.shape

    def index(q):  # plan position -> (j, i) on the grid
        return int(np.argmin(np.abs(ys - q[1]))), int(np.argmin(np.abs(xs - q[0])))

    top = {}
    for q, f in zip(p, shell["contact"]):
        if f != 0.0:
            j, i = index(q)
            top[plate.node(nz - 1, j, i)] = -f  # the indenter pushes down
    force = -sum(top.values())
    cj, ci = min((index(q) for q in p), key=lambda ji: np.hypot(xs[ji[1]] - CLAMP[0],
                                                                 ys[ji[0]] - CLAMP[1]))
    clamp = [plate.node(k, cj, ci) for k in range(nz)] if clamped else []
    solid = solve_signorini(plate, top, clamp, WORK / tag / "ccx")

    rows = []
    for q, mu, g in zip(p, shell["frame_force"], shell["frame_gap"]):
        j, i = index(q)
        n = plate.node(0, j, i)
        if n not in solid["reaction"]:
            continue
        rows.append(dict(x_mm=xs[i], y_mm=ys[j], shell_reaction_N=mu,
                         solid_reaction_N=solid["reaction"][n] if n in solid["held"] else 0.0,
                         shell_gap_mm=g, solid_lift_mm=max(solid["w"][n], 0.0)))
    return dict(tag=tag, rows=rows, force=force, solid=solid, shell=shell, plate=plate)


def summary(c: dict, size: float, layup: str, clamped: bool) -> dict:
    rows, force = c["rows"], c["force"]
    sh = np.array([r["shell_reaction_N"] for r in rows])
    so = np.array([r["solid_reaction_N"] for r in rows])
    x = np.array([r["x_mm"] for r in rows])
    y = np.array([r["y_mm"] for r in rows])
    corner = (x > WINDOW[0] + 1e-9) & (y > WINDOW[1] + 1e-9)
    far = int(np.argmax(x + y))  # the plate's corner (75, 50)
    tol = 1e-6 * max(sh.max(), so.max())
    bear_sh, bear_so = sh > tol, so > tol
    return dict(layup=layup, clamps="preset" if clamped else "none", size_mm=size, nodes=len(c["shell"]["points"]),
                force_N=force,
                shell_frame_share=sh.sum() / force, solid_frame_share=so.sum() / force,
                shell_clamp_share=1 - sh.sum() / force,
                solid_clamp_share=c["solid"]["clamp"] / force,
                shell_corner_share=sh[corner].sum() / force,
                solid_corner_share=so[corner].sum() / force,
                shell_corner_lift_mm=rows[far]["shell_gap_mm"],
                solid_corner_lift_mm=rows[far]["solid_lift_mm"],
                frame_nodes=len(rows), shell_bearing=int(bear_sh.sum()),
                solid_bearing=int(bear_so.sum()), bearing_agree=int((bear_sh == bear_so).sum()),
                signorini_rounds=c["solid"]["rounds"])


def write_csv(path: Path, rows: list[dict]):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


def main(argv=None):
    a = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    a.add_argument("--build", default="build", help="build directory holding shellindent")
    a.add_argument("--layup", choices=list(decks.LAYUPS), default="[0/90]2S")
    a.add_argument("--sizes", default="2.5,1.25", help="plan element sizes, mm")
    a.add_argument("--depth", type=float, default=0.1, help="indenter travel, mm")
    a.add_argument("--clamps", default="preset,none",
                   help="the preset's four clamps, none (the plate only rests on the frame), or both")
    args = a.parse_args(argv)
    out = []
    for clamps in args.clamps.split(","):
        for size in (float(s) for s in args.sizes.split(",")):
            clamped = clamps == "preset"
            c = compare(Path(args.build).resolve(), args.layup, size, args.depth, clamped)
            write_csv(RESULTS / f"d7136_frame_nodes_{clamps}_{size:g}.csv", c["rows"])
            out.append(summary(c, size, args.layup, clamped))
        print(", ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}"
                        for k, v in out[-1].items()), flush=True)
    write_csv(RESULTS / "d7136_frame.csv", out)


if __name__ == "__main__":
    main()
