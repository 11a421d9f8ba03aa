"""CalculiX decks of the paper's cap (C3D20R solid, S8R shell) and of the Hertz block.

Conventions (docs/case-file.md, src/model/spherical_cap_mesh.hpp): z is the cap's axis, the
base circle of the *mid-surface* has plan radius 25 mm and lies in z = 0, the mid-surface is a
sphere of radius 80.9 mm, plies are listed bottom (inner face) first, ply angle 0 is the global
x axis projected on the surface, positive towards y about the outward normal. The indenter is a
rigid sphere touching the outer face at the apex at travel 0 and moving along -z.

Solid model: one C3D20R layer per ply, the top plies split (`top_split`), each element column
with its own *ORIENTATION per ply angle (axis 1 = fibre, 3 = the sphere's normal at the
column's centre). "Clamped" for a solid is the edge face fixed: every node on the ruled
surface through the mid-surface's base circle along the normals has u = 0. Quarter models have
u_x = 0 on x = 0 and u_y = 0 on y = 0. The half model (y >= 0) is the full model reduced by its
exact 180-degree symmetry about z (an angle ply maps onto itself: a fibre direction is a line):
u(-x, 0, z) = R_z(180) u(x, 0, z) as *EQUATIONs.

The indenter is one layer of C3D20R on the sphere, every node driven by *BOUNDARY (a rigid
translation); the contact force is the sum of their reactions. Contact is CalculiX's
face-to-face penalty contact (TYPE=SURFACE TO SURFACE), frictionless, linear
pressure-overclosure with slope `penalty` (MPa/mm), slave = the cap's outer face near the apex,
master = the indenter.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

import ogrid

# The material library's paper-carbon-epoxy (src/material, docs/case-file.md), MPa
PAPER_CARBON_EPOXY = dict(E1=130e3, E2=10e3, E3=10e3, nu12=0.3, nu13=0.5, nu23=0.3,
                          G12=6e3, G13=3e3, G23=6e3)

LAYUPS = {"[0]8": [0.0] * 8, "[0/90]2S": [0, 90, 0, 90, 90, 0, 90, 0],
          "[45/-45]2S": [45, -45, 45, -45, -45, 45, -45, 45]}


def layup_slug(layup: str) -> str:
    """The lay-up as it appears in file and run names: "[0/90]2S" -> "0-902S"."""
    return layup.strip("[]").replace("/", "-").replace("]", "")


@dataclass
class Mesh:
    """The refinement level and grading (all lengths mm). Level L has in-plane size h0 / 2^L
    within fine_radius of the axis, the top ply split in 2^L layers, the next in 2^(L-1), ..."""
    level: int = 0
    h0: float = 0.4
    b: float = 1.2              # half side of the O-grid's central square
    fine_radius: float = 3.0    # uniform size h up to this plan (arc) radius
    growth: float = 0.5         # then g = 1 + growth (rho - fine_radius) ...
    max_factor: float = 10.0    # ... up to max_factor h
    blend: float = 2.4          # the square's sides become circles by this radius
    top_split: int | None = None  # sublayers of the top ply (default 2^level)
    # Two zones tied together (*TIE) at tie_radius (None: one O-grid to the edge). The outer
    # zone is a polar grid, one layer per ply, refined by outer_level only (the far field's
    # own check); the inner zone carries the level's refinement.
    tie_radius: float | None = 4.0
    outer_circ: int = 12        # elements per quadrant around
    outer_h: float = 0.5        # radial size at tie_radius, growing like the inner grading
    outer_growth: float = 0.3
    outer_max: float = 5.0
    outer_level: int = 0
    # one element through the whole thickness (the expanded-shell form of a single-angle
    # lay-up: CalculiX expands S8R into exactly this C3D20R)
    single_layer: bool = False

    def outer_ring(self, r0: float, r1: float) -> np.ndarray:
        n0 = max(2, int(round(ogrid.xi_length(r0, r1, r0, self.outer_growth, self.outer_max)
                              / self.outer_h)))
        return ogrid.graded_positions(r0, r1, n0 * 2 ** self.outer_level, r0, self.outer_growth,
                                      self.outer_max)

    def outer_plan(self, r0: float, r1: float, quadrants) -> ogrid.PlanMesh:
        return ogrid.annulus_mesh(self.outer_ring(r0, r1), self.outer_circ * 2 ** self.outer_level,
                                  quadrants)

    @property
    def h(self) -> float:
        return self.h0 / 2 ** self.level

    @property
    def n(self) -> int:
        return int(round(self.b / self.h0)) * 2 ** self.level

    def ring(self, outer: float) -> np.ndarray:
        n0 = max(2, int(round(ogrid.xi_length(self.b, outer, self.fine_radius, self.growth,
                                              self.max_factor) / self.h0)))
        return ogrid.graded_positions(self.b, outer, n0 * 2 ** self.level, self.fine_radius,
                                      self.growth, self.max_factor)

    def plan(self, outer: float, quadrants) -> ogrid.PlanMesh:
        spec = ogrid.PlanSpec(b=self.b, n=self.n, ring=self.ring(outer), blend=self.blend)
        return ogrid.plan_mesh(spec, quadrants)

    def splits(self, nplies: int) -> list[int]:
        top = self.top_split if self.top_split is not None else 2 ** self.level
        out = []
        for k in range(nplies):  # k = 0: top ply
            out.append(max(1, top // 2 ** k))
        return out[::-1]  # bottom first


@dataclass
class Case:
    kind: str = "cap"            # cap | block
    layup: str = "[0]8"
    ply_t: float = 0.475
    sphere_radius: float = 80.9  # mid-surface
    base_radius: float = 25.0    # plan radius of the mid-surface's base circle
    symmetry: str = "quarter"    # quarter | half | full
    nlgeom: bool = False
    travel: float = 1.0
    points: list = field(default_factory=lambda: [0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5,
                                                  0.6, 0.7, 0.8, 0.9, 1.0])
    penalty: float = 1e7         # MPa/mm
    indenter_radius: float = 12.7
    indenter_extent: float = 5.0  # arc length of the meshed indenter patch from its pole
    slave_radius: float = 5.0    # plan radius of the slave face
    mesh: Mesh = field(default_factory=Mesh)
    # block (Hertz check)
    block_radius: float = 50.0
    block_depth: float = 50.0
    block_E: float = 10e3
    block_nu: float = 0.3
    # increments (fractions of the step)
    inc0: float = 0.02
    inc_max: float = 0.05
    solver: str = "SPOOLES"
    # A load with no local part instead of the indenter (kind 'cap'): a uniform pressure on the
    # whole outer face, scaled so that it carries the same force as `pressure` on the
    # mid-surface (the shell's load); the indenter is held fixed and has no contact. 0: the
    # indenter's travel is the load.
    pressure: float = 0.0        # MPa on the mid-surface
    # With pressure > 0 and patch_radius > 0 the face load is instead Hertz's pressure
    # p0 (1 - r^2/a^2)^0.5 on the plan disc r < a (a = patch_radius, mm), one value per face at
    # its centroid, p0 such that the whole cap carries `pressure` N (a force, not a pressure).
    patch_radius: float = 0.0

    @property
    def thickness(self) -> float:
        return self.ply_t * len(LAYUPS[self.layup])

    def quadrants(self):
        return {"quarter": [0], "half": [0, 1], "full": [0, 1, 2, 3]}[self.symmetry]


# --------------------------------------------------------------------------------------------

def _lines(values, per_line=16, fmt="{}"):
    out = []
    for i in range(0, len(values), per_line):
        out.append(", ".join(fmt.format(v) for v in values[i:i + per_line]))
    return "\n".join(out)


def _nset(name, ids):
    return f"*NSET, NSET={name}\n{_lines([int(i) + 1 for i in ids])}\n"


def _elset(name, ids):
    return f"*ELSET, ELSET={name}\n{_lines([int(i) + 1 for i in ids])}\n"


def _elements(etype, elset, elems, first_id):
    rows = []
    for k, e in enumerate(elems):
        ids = [first_id + k] + [int(i) + 1 for i in e]
        rows.append(", ".join(map(str, ids[:16])) + ",\n" + ", ".join(map(str, ids[16:])))
    return f"*ELEMENT, TYPE={etype}, ELSET={elset}\n" + "\n".join(rows) + "\n"


def _nodes(x, first_id=1):
    return "*NODE, NSET=NALL\n" + "\n".join(
        f"{first_id + i}, {p[0]:.12g}, {p[1]:.12g}, {p[2]:.12g}" for i, p in enumerate(x)) + "\n"


def _material(name, m):
    return (f"*MATERIAL, NAME={name}\n*ELASTIC, TYPE=ENGINEERING CONSTANTS\n"
            f"{m['E1']:g}, {m['E2']:g}, {m['E3']:g}, {m['nu12']:g}, {m['nu13']:g}, "
            f"{m['nu23']:g}, {m['G12']:g}, {m['G13']:g}\n{m['G23']:g}, 0.\n")


def ply_axes(normal: np.ndarray, angle_deg: float):
    """Fibre direction and the in-plane transverse direction of a ply: angle from the global
    x axis projected on the tangent plane, positive about the outward normal."""
    ex = np.array([1.0, 0.0, 0.0])
    t1 = ex - normal @ ex * normal
    t1 /= np.linalg.norm(t1)
    t2 = np.cross(normal, t1)
    a = math.radians(angle_deg)
    f = math.cos(a) * t1 + math.sin(a) * t2
    return f, np.cross(normal, f)


@dataclass
class Deck:
    text: str
    info: dict


def _time_points(case: Case):
    """The *TIME POINTS card of the printed travels; none when case.points is empty, and then
    every converged increment is printed. ccx 2.20 can meet a time point after a cut-back with
    an increment of size zero, find the matrix singular and stop (the peer benchmark's level 2
    at step time 1/2): printing every increment never meets that defect."""
    if not case.points:
        return ""
    pts = sorted({round(p / case.travel, 10) for p in case.points if 0 < p <= case.travel})
    return "*TIME POINTS, NAME=TP\n" + _lines(pts, 8, "{:.10g}") + "\n"


def _node_print(case: Case, nset: str, what: str, totals: bool = False) -> str:
    """One *NODE PRINT card: at the time points when there are any, else every increment."""
    opts = (", TOTALS=ONLY" if totals else "") + (", TIME POINTS=TP" if case.points else "")
    return f"*NODE PRINT, NSET={nset}{opts}\n{what}\n"


def _indenter(case: Case, top_apex_z: float, mesh: Mesh, first_node: int):
    """The meshed rigid indenter: (nodes, elements, master faces)."""
    ri = case.indenter_radius
    # uniform size h out to the patch's edge: the master faces match the slave's
    m = Mesh(level=mesh.level, h0=mesh.h0, b=mesh.b, fine_radius=1e9, growth=0.0,
             max_factor=1.0, blend=mesh.blend)
    plan = m.plan(case.indenter_extent, case.quadrants())
    surf = ogrid.sphere_map(ri, np.array([0.0, 0.0, top_apex_z]), down=True)
    # one layer, from 1 mm inside the sphere to its surface (levels along the outward normal)
    solid = ogrid.extrude(plan, surf, ogrid.layer_levels(np.array([-1.0, 0.0])))
    on_sphere = np.abs(np.linalg.norm(solid.nodes - np.array([0, 0, top_apex_z + ri]), axis=1)
                       - ri) < 1e-9
    faces = ogrid.faces_on(solid, on_sphere)
    return solid, faces


def _ply_levels(case: Case, splits: list[int]):
    """Lattice levels through the thickness and the ply of every layer."""
    t = case.thickness
    bounds, ply_of_layer = [-t / 2], []
    for k, s in enumerate(splits):
        for j in range(s):
            bounds.append(-t / 2 + case.ply_t * (k + (j + 1) / s))
            ply_of_layer.append(k)
    return ogrid.layer_levels(np.array(bounds)), ply_of_layer


def solid_deck(case: Case) -> Deck:
    """The C3D20R model of the cap (kind 'cap') or of the Hertz block (kind 'block')."""
    mesh = case.mesh
    quads = case.quadrants()
    parts = ["** generated by bench/calculix/decks.py: " + repr(case) + "\n",
             "*HEADING\nshellindent 3-D reference: " + case.kind + "\n"]
    tie = None
    if case.kind == "cap":
        R, c = case.sphere_radius, case.base_radius
        rise = R - math.sqrt(R * R - c * c)
        outer = R * math.asin(c / R)  # arc length apex -> edge of the mid-surface
        surf = ogrid.sphere_map(R, np.array([0.0, 0.0, rise]))
        angles = LAYUPS[case.layup]
        nply = len(angles)
        levels, ply_of_layer = _ply_levels(case, mesh.splits(nply))
        if mesh.single_layer:
            if len(set(angles)) != 1:
                raise ValueError("single_layer needs one ply angle")
            levels, ply_of_layer = ogrid.layer_levels(np.array([-case.thickness / 2,
                                                                 case.thickness / 2])), [0]
        if mesh.tie_radius:
            tie = mesh.tie_radius
            inner = ogrid.extrude(mesh.plan(tie, quads), surf, levels)
            levels_o, ply_o = _ply_levels(case, [1] * nply)
            outer_zone = ogrid.extrude(mesh.outer_plan(tie, outer, quads), surf, levels_o)
            solid = ogrid.combine([inner, outer_zone])
            layer_ply = [np.array(ply_of_layer), np.array(ply_o)]
        else:
            solid = ogrid.combine([ogrid.extrude(mesh.plan(outer, quads), surf, levels)])
            layer_ply = [np.array(ply_of_layer)]
        elem_ply = np.empty(len(solid.elements), np.int64)
        for z, lp in enumerate(layer_ply):
            m = solid.elem_zone == z
            elem_ply[m] = lp[solid.elem_layer[m]]
        top_apex_z = rise + case.thickness / 2
        top_zeta = case.thickness / 2
    else:
        outer = case.block_radius
        surf = ogrid.plane_map(0.0)
        # depth grading: the in-plane size function along the depth, fine at the top
        n0 = max(2, int(round(ogrid.xi_length(0.0, case.block_depth, mesh.fine_radius,
                                              mesh.growth, mesh.max_factor) / mesh.h0)))
        depth = ogrid.graded_positions(0.0, case.block_depth, n0 * 2 ** mesh.level,
                                       mesh.fine_radius, mesh.growth, mesh.max_factor)
        levels = -depth[::-1]
        solid = ogrid.combine([ogrid.extrude(mesh.plan(outer, quads), surf, levels)])
        elem_ply = np.zeros(len(solid.elements), np.int64)
        angles = [0.0]
        top_apex_z = 0.0
        top_zeta = 0.0

    x = solid.nodes
    nn = len(x)
    p_of = solid.node_xy
    s_of = np.hypot(p_of[:, 0], p_of[:, 1])
    is_top = np.abs(solid.node_zeta - top_zeta) < 1e-9
    # tie: the inner zone's nodes on the interface are the slaves (no SPC or equation of
    # their own: they follow the master faces, whose nodes carry the symmetry conditions)
    tied = np.zeros(nn, bool)
    if tie:
        tied = (solid.node_zone == 0) & (np.abs(s_of - tie) < 1e-6)

    ind, master = _indenter(case, top_apex_z, mesh, nn)
    ind_first_node = nn + 1
    ne_cap = len(solid.elements)

    parts.append(_nodes(x))
    parts.append(_nodes(ind.nodes, ind_first_node).replace("NSET=NALL", "NSET=NIND"))
    parts.append(_elements("C3D20R", "ECAP", solid.elements, 1))
    parts.append(_elements("C3D20R", "EIND", ind.elements + nn, ne_cap + 1))

    # sets
    axis = s_of < 1e-9
    apex_mid = np.nonzero(axis & (np.abs(solid.node_zeta) < 1e-12) if case.kind == "cap"
                          else axis & is_top)[0]
    apex_top = np.nonzero(axis & is_top)[0]
    parts.append(_nset("NAPEX", apex_mid) + _nset("NAPEXTOP", apex_top)
                 + _nset("NAXISLINE", np.nonzero(axis)[0]))
    if case.kind == "cap":
        fixed = np.nonzero(np.abs(s_of - outer) < 1e-6)[0]
    else:
        fixed = np.nonzero(np.abs(solid.node_zeta + case.block_depth) < 1e-9)[0]
    parts.append(_nset("NFIX", fixed))
    # top-surface lines for the contact radius: along x, y and the diagonal
    line = is_top & (s_of <= case.slave_radius + 1e-9) & (solid.node_zone == 0)
    on_x = line & (np.abs(p_of[:, 1]) < 1e-9)
    on_y = line & (np.abs(p_of[:, 0]) < 1e-9)
    on_d = line & (np.abs(p_of[:, 0] - p_of[:, 1]) < 1e-9)
    parts.append(_nset("NLINEX", np.nonzero(on_x)[0]) + _nset("NLINEY", np.nonzero(on_y)[0])
                 + _nset("NLINED", np.nonzero(on_d)[0]))
    bcs = ["*BOUNDARY\nNFIX, 1, 3\n"]
    equations = []
    fixed_mask = np.zeros(nn, bool)
    fixed_mask[fixed] = True
    if case.symmetry == "quarter":
        sx = np.nonzero((np.abs(p_of[:, 0]) < 1e-9) & ~tied)[0]
        sy = np.nonzero((np.abs(p_of[:, 1]) < 1e-9) & ~tied)[0]
        parts.append(_nset("NSYMX", sx) + _nset("NSYMY", sy))
        bcs.append("*BOUNDARY\nNSYMX, 1, 1\nNSYMY, 2, 2\n")
    elif case.symmetry == "half":
        parts.append(_nset("NAXIS", np.nonzero(axis)[0]))
        bcs.append("*BOUNDARY\nNAXIS, 1, 2\n")
        key = {}
        for i in np.nonzero((np.abs(p_of[:, 1]) < 1e-9) & ~tied & ~fixed_mask & ~axis)[0]:
            key[(solid.node_zone[i], round(p_of[i, 0] * 1e6), round(solid.node_zeta[i] * 1e9))] = i
        for (z, kx, kz), i in key.items():
            if kx < 0:
                continue
            j = key[(z, -kx, kz)]
            # dependent: the node at -x; u1(j) + u1(i) = 0, u2(j) + u2(i) = 0, u3(j) - u3(i) = 0
            equations.append(f"2\n{j + 1}, 1, 1., {i + 1}, 1, 1.\n"
                             f"2\n{j + 1}, 2, 1., {i + 1}, 2, 1.\n"
                             f"2\n{j + 1}, 3, 1., {i + 1}, 3, -1.\n")
    if equations:
        parts.append("*EQUATION\n" + "".join(equations))
    if tie:
        slave_tie = ogrid.faces_on(solid, tied, solid.elem_zone == 0)
        master_tie = ogrid.faces_on(solid, (solid.node_zone == 1) & (np.abs(s_of - tie) < 1e-6),
                                    solid.elem_zone == 1)
        parts.append("*SURFACE, NAME=STIES, TYPE=ELEMENT\n"
                     + "\n".join(f"{e + 1}, S{f}" for e, f in slave_tie) + "\n")
        parts.append("*SURFACE, NAME=STIEM, TYPE=ELEMENT\n"
                     + "\n".join(f"{e + 1}, S{f}" for e, f in master_tie) + "\n")
        parts.append("*TIE, NAME=T1, POSITION TOLERANCE=0.01, ADJUST=NO\nSTIES, STIEM\n")

    # materials and sections: one orientation per element column and ply angle
    if case.kind == "cap":
        parts.append(_material("PLY", PAPER_CARBON_EPOXY))
        uniq = sorted(set(angles))
        elem_ang = np.array([uniq.index(angles[p]) for p in range(len(angles))])[elem_ply]
        order = np.lexsort((elem_ang, solid.elem_column))
        keys = solid.elem_column[order] * len(uniq) + elem_ang[order]
        bounds = np.nonzero(np.diff(keys))[0] + 1
        for ids in np.split(order, bounds):
            col, ai = int(solid.elem_column[ids[0]]), int(elem_ang[ids[0]])
            f, g = ply_axes(solid.column_normal[col], uniq[ai])
            name = f"C{col}A{ai}"
            parts.append(f"*ORIENTATION, NAME=O{name}, SYSTEM=RECTANGULAR\n"
                         f"{f[0]:.12g}, {f[1]:.12g}, {f[2]:.12g}, "
                         f"{g[0]:.12g}, {g[1]:.12g}, {g[2]:.12g}\n")
            parts.append(_elset("E" + name, np.sort(ids)))
            parts.append(f"*SOLID SECTION, ELSET=E{name}, MATERIAL=PLY, ORIENTATION=O{name}\n")
    else:
        parts.append(f"*MATERIAL, NAME=ISO\n*ELASTIC\n{case.block_E:g}, {case.block_nu:g}\n"
                     "*SOLID SECTION, ELSET=ECAP, MATERIAL=ISO\n")
    parts.append("*MATERIAL, NAME=RIGID\n*ELASTIC\n1e7, 0.3\n"
                 "*SOLID SECTION, ELSET=EIND, MATERIAL=RIGID\n")

    if case.pressure > 0:
        return _pressure_deck(case, parts, bcs, solid, is_top, levels, tie, ne_cap)
    # contact: slave = the cap's outer face within slave_radius, master = the indenter
    slave_mask = is_top & (s_of <= case.slave_radius + 1e-9) & (solid.node_zone == 0)
    slave = ogrid.faces_on(solid, slave_mask, solid.elem_zone == 0)
    parts.append("*SURFACE, NAME=SSLAVE, TYPE=ELEMENT\n"
                 + "\n".join(f"{e + 1}, S{f}" for e, f in slave) + "\n")
    parts.append("*SURFACE, NAME=SMASTER, TYPE=ELEMENT\n"
                 + "\n".join(f"{e + 1 + ne_cap}, S{f}" for e, f in master) + "\n")
    parts.append("*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\nSSLAVE, SMASTER\n"
                 f"*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, "
                 f"PRESSURE-OVERCLOSURE=LINEAR\n{case.penalty:g}\n")
    parts += bcs
    parts.append(_time_points(case))
    parts.append(f"*STEP{', NLGEOM' if case.nlgeom else ''}, INC=10000\n"
                 f"*STATIC, SOLVER={case.solver}\n"
                 f"{case.inc0:g}, 1., 1e-6, {case.inc_max:g}\n"
                 f"*BOUNDARY\nNIND, 1, 2, 0.\nNIND, 3, 3, {-case.travel:.10g}\n"
                 + _node_print(case, "NAPEX", "U")
                 + _node_print(case, "NAPEXTOP", "U")
                 + _node_print(case, "NIND", "RF", totals=True)
                 + _node_print(case, "NFIX", "RF", totals=True)
                 + _node_print(case, "NLINEX", "U")
                 + _node_print(case, "NLINEY", "U")
                 + _node_print(case, "NLINED", "U")
                 + (_node_print(case, "NAXISLINE", "U")
                    if case.kind == "block" else "") +
                 "*END STEP\n")
    info = dict(kind=case.kind, layup=case.layup, symmetry=case.symmetry, travel=case.travel,
                penalty=case.penalty,
                nlgeom=case.nlgeom, level=mesh.level, h=mesh.h, nodes=nn,
                elements=ne_cap, layers=len(levels) // 2, dofs=3 * nn, tie_radius=tie,
                slave_faces=len(slave), master_faces=len(master),
                indenter_centre=[0.0, 0.0, top_apex_z + case.indenter_radius],
                indenter_radius=case.indenter_radius, top_apex_z=top_apex_z,
                line_nodes={k: [int(i) + 1 for i in np.nonzero(m)[0]]
                            for k, m in (("x", on_x), ("y", on_y), ("d", on_d))},
                line_ref={int(i) + 1: x[i].tolist() for i in np.nonzero(on_x | on_y | on_d)[0]},
                axis_ref={int(i) + 1: x[i].tolist() for i in np.nonzero(axis)[0]},
                factor={"quarter": 4, "half": 2, "full": 1}[case.symmetry])
    return Deck(text="".join(parts), info=info)


def _pressure_deck(case: Case, parts, bcs, solid, is_top, levels, tie, ne_cap) -> Deck:
    """The solid cap under a pressure on its outer face (Case.pressure), one linear increment.
    The outer face's area element is (1 + t/(2R))^2 times the mid-surface's on a sphere, so the
    face pressure is scaled by the inverse: the resultant equals the shell's mid-surface load."""
    if case.kind != "cap" or case.nlgeom:
        raise ValueError("the pressure load is for the linear cap")
    R = case.sphere_radius
    face_p = case.pressure * (R / (R + case.thickness / 2)) ** 2
    loaded = ogrid.faces_on(solid, is_top)
    values = [face_p] * len(loaded)
    if case.patch_radius > 0:
        loaded, values = _hertz_patch(case, solid, loaded)
    parts += bcs
    parts.append("*STEP, INC=10\n*STATIC, SOLVER=" + case.solver + "\n1., 1.\n"
                 "*BOUNDARY\nNIND, 1, 3, 0.\n*DLOAD\n"
                 + "\n".join(f"{e + 1}, P{f}, {v:.12g}" for (e, f), v in zip(loaded, values))
                 + "\n"
                 + "*NODE PRINT, NSET=NAPEX\nU\n*NODE PRINT, NSET=NAPEXTOP\nU\n"
                 "*NODE PRINT, NSET=NFIX, TOTALS=ONLY\nRF\n*END STEP\n")
    info = dict(kind="cap_pressure", layup=case.layup, symmetry=case.symmetry, travel=0.0,
                penalty=0.0, nlgeom=False, level=case.mesh.level, h=case.mesh.h,
                nodes=len(solid.nodes), elements=ne_cap, layers=len(levels) // 2,
                dofs=3 * len(solid.nodes), tie_radius=tie, pressure=case.pressure,
                face_pressure=face_p, patch_radius=case.patch_radius,
                loaded_faces=len(loaded),
                factor={"quarter": 4, "half": 2, "full": 1}[case.symmetry])
    return Deck(text="".join(parts), info=info)


def _hertz_patch(case: Case, solid, loaded):
    """The outer faces inside the plan disc r < patch_radius and Hertz's pressure at each face's
    centroid, scaled so that the whole cap carries case.pressure N: a local load with the
    contact's own shape and no contact (pressure_check.py --patch)."""
    a = case.patch_radius
    faces, shape, area = [], [], []
    for e, f in loaded:
        # the outer face's own coordinates: node_xy is the reference surface's plan point, and the
        # outer face lies (1 + t/(2R)) further out
        c = solid.nodes[solid.elements[e, ogrid.HEX_FACES[f]]]
        r2 = float(np.sum(c[:, :2].mean(axis=0) ** 2)) / a ** 2
        if r2 >= 1.0:
            continue
        faces.append((e, f))
        shape.append((1.0 - r2) ** 0.5)
        area.append(0.5 * float(np.linalg.norm(np.cross(c[2] - c[0], c[3] - c[1]))))
    factor = {"quarter": 4, "half": 2, "full": 1}[case.symmetry]
    p0 = case.pressure / (factor * float(np.dot(shape, area)))
    return faces, [p0 * v for v in shape]


# --------------------------------------------------------------------------------------------
# S8R shell model (issue 19's peer benchmark)

def shell_deck(case: Case) -> Deck:
    """The cap as S8R shells on the mid-surface (CalculiX expands them into one C3D20R layer
    through the thickness), clamped edge (translations and rotations of the edge nodes), the
    same indenter and contact as the solid model on the shell's outer (POS) face.

    Full model only. Symmetry planes cannot be imposed on S8R nodes in CalculiX 2.20: measured
    on this cap under a uniform pressure (linear, level 1), u_x = 0 on the x = 0 nodes gives an
    apex deflection 47 % above the full model's (the SPC reaches the expanded mid node only),
    and adding zero rotations 5, 6 (mean-rotation MPCs) 15 % below it. The quarter model of the
    same elements is the expanded form written out (solid_deck with Mesh.single_layer)."""
    if case.symmetry != "full":
        raise ValueError("S8R models: full only (see shell_deck); the quarter model is the "
                         "expanded form, solid_deck with Mesh(single_layer=True)")
    mesh = case.mesh
    quads = case.quadrants()
    R, c = case.sphere_radius, case.base_radius
    rise = R - math.sqrt(R * R - c * c)
    outer = R * math.asin(c / R)
    plan = mesh.plan(outer, quads)
    pos, nrm = ogrid.sphere_map(R, np.array([0.0, 0.0, rise]))(plan.points)
    used = np.unique(plan.quads)
    nid = -np.ones(len(plan.points), np.int64)
    nid[used] = np.arange(len(used))
    x = pos[used]
    p_of = plan.points[used]
    s_of = np.hypot(p_of[:, 0], p_of[:, 1])
    elems = nid[plan.quads]
    t = case.thickness
    top_apex_z = rise + t / 2
    nn, ne = len(x), len(elems)
    ind, master = _indenter(case, top_apex_z, mesh, nn)
    parts = ["** generated by bench/calculix/decks.py (shell): " + repr(case) + "\n",
             "*HEADING\nshellindent peer: S8R cap\n", _nodes(x),
             _nodes(ind.nodes, nn + 1).replace("NSET=NALL", "NSET=NIND")]
    rows = []
    for k, e in enumerate(elems):
        rows.append(f"{k + 1}, " + ", ".join(str(int(i) + 1) for i in e))
    parts.append("*ELEMENT, TYPE=S8R, ELSET=ECAP\n" + "\n".join(rows) + "\n")
    parts.append(_elements("C3D20R", "EIND", ind.elements + nn, ne + 1))
    apex = np.nonzero(s_of < 1e-9)[0]
    fixed = np.nonzero(np.abs(s_of - outer) < 1e-6)[0]
    parts.append(_nset("NAPEX", apex) + _nset("NAPEXTOP", apex) + _nset("NFIX", fixed))
    bcs = ["*BOUNDARY\nNFIX, 1, 6\n"]
    line = s_of <= case.slave_radius + 1e-9
    on_x = line & (np.abs(p_of[:, 1]) < 1e-9)
    on_y = line & (np.abs(p_of[:, 0]) < 1e-9)
    on_d = line & (np.abs(p_of[:, 0] - p_of[:, 1]) < 1e-9)
    parts.append(_nset("NLINEX", np.nonzero(on_x)[0]) + _nset("NLINEY", np.nonzero(on_y)[0])
                 + _nset("NLINED", np.nonzero(on_d)[0]))
    parts.append(_material("PLY", PAPER_CARBON_EPOXY))
    angles = LAYUPS[case.layup]
    uniq = sorted(set(angles))
    cpos, cnrm = ogrid.sphere_map(R, np.array([0.0, 0.0, rise]))(
        plan.points[plan.quads[:, :4]].mean(axis=1))
    for k in range(ne):
        for a in uniq:
            f, g = ply_axes(cnrm[k], a)
            parts.append(f"*ORIENTATION, NAME=O{k}A{uniq.index(a)}, SYSTEM=RECTANGULAR\n"
                         f"{f[0]:.12g}, {f[1]:.12g}, {f[2]:.12g}, "
                         f"{g[0]:.12g}, {g[1]:.12g}, {g[2]:.12g}\n")
        parts.append(f"*ELSET, ELSET=S{k}\n{k + 1}\n")
        if len(uniq) == 1:
            parts.append(f"*SHELL SECTION, ELSET=S{k}, MATERIAL=PLY, ORIENTATION=O{k}A0\n{t:g}\n")
        else:
            parts.append(f"*SHELL SECTION, ELSET=S{k}, COMPOSITE\n" + "".join(
                f"{case.ply_t:g}, , PLY, O{k}A{uniq.index(a)}\n" for a in angles))
    parts.append("*MATERIAL, NAME=RIGID\n*ELASTIC\n1e7, 0.3\n"
                 "*SOLID SECTION, ELSET=EIND, MATERIAL=RIGID\n")
    slave = np.nonzero(np.all(line[elems[:, :4]], axis=1))[0]
    parts.append("*SURFACE, NAME=SSLAVE, TYPE=ELEMENT\n"
                 + "\n".join(f"{e + 1}, S2" for e in slave) + "\n")
    parts.append("*SURFACE, NAME=SMASTER, TYPE=ELEMENT\n"
                 + "\n".join(f"{e + 1 + ne}, S{f}" for e, f in master) + "\n")
    parts.append("*CONTACT PAIR, INTERACTION=SI, TYPE=SURFACE TO SURFACE\nSSLAVE, SMASTER\n"
                 f"*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, "
                 f"PRESSURE-OVERCLOSURE=LINEAR\n{case.penalty:g}\n")
    parts += bcs
    parts.append(_time_points(case))
    parts.append(f"*STEP{', NLGEOM' if case.nlgeom else ''}, INC=10000\n"
                 f"*STATIC, SOLVER={case.solver}\n"
                 f"{case.inc0:g}, 1., 1e-6, {case.inc_max:g}\n"
                 f"*BOUNDARY\nNIND, 1, 2, 0.\nNIND, 3, 3, {-case.travel:.10g}\n"
                 + _node_print(case, "NAPEX", "U")
                 + _node_print(case, "NIND", "RF", totals=True)
                 + _node_print(case, "NFIX", "RF", totals=True)
                 + "*END STEP\n")
    info = dict(kind="shell", layup=case.layup, symmetry=case.symmetry, travel=case.travel,
                penalty=case.penalty, nlgeom=case.nlgeom, level=mesh.level, h=mesh.h,
                nodes=nn, elements=ne, layers=1, dofs=3 * 3 * nn, slave_faces=len(slave),
                master_faces=len(master),
                indenter_centre=[0.0, 0.0, top_apex_z + case.indenter_radius],
                indenter_radius=case.indenter_radius, top_apex_z=top_apex_z,
                line_nodes={}, line_ref={},
                factor={"quarter": 4, "half": 2, "full": 1}[case.symmetry])
    return Deck(text="".join(parts), info=info)
