"""Graded O-grid meshes for the CalculiX reference models (numpy only).

The plan of every model is a disk O-grid in flat coordinates (x, y), the same layout as
src/model/disk_o_grid: a central square [0, b]^2 per quadrant and a ring of two blocks per
quadrant that blends the square's sides into circles. Elements are quadratic: the grid is built
as a lattice of doubled indices (even = element corners, odd = mid-edge points), so that the
mid-edge nodes lie on the smooth mapping, not on straight chords.

Sizes follow a size function of the plan radius rho: the element size is h inside
`fine_radius`, then grows linearly with slope `growth` (per mm) up to `max_factor` h. The nodes
sit at equal steps of xi(rho) = integral d rho / g(rho); a level with twice the elements puts
every other node on the coarser level's nodes (nested refinement, for Richardson).

A plan mesh is mapped onto a surface (a sphere by geodesic polar coordinates, as the shell
mesh of src/model/spherical_cap_mesh does, or a plane) and extruded along the surface normal
into 20-node hexahedra (C3D20R), node order and face labels as in the CalculiX manual.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


def graded_positions(r0: float, r1: float, n_elem: int, fine_radius: float, growth: float,
                     max_factor: float) -> np.ndarray:
    """2 n_elem + 1 lattice positions (corners and mid points) from r0 to r1 at equal steps
    of xi(rho) = integral d rho / g(rho), g = 1 below fine_radius, 1 + growth (rho -
    fine_radius) above, capped at max_factor."""
    rho = np.linspace(r0, r1, 20001)
    g = np.clip(1.0 + growth * np.maximum(rho - fine_radius, 0.0), 1.0, max_factor)
    xi = np.concatenate([[0.0], np.cumsum(0.5 * (1 / g[1:] + 1 / g[:-1]) * np.diff(rho))])
    target = np.linspace(0.0, xi[-1], 2 * n_elem + 1)
    out = np.interp(target, xi, rho)
    out[0], out[-1] = r0, r1
    return out


def xi_length(r0: float, r1: float, fine_radius: float, growth: float, max_factor: float) -> float:
    """xi(r1) - xi(r0): about xi_length / h elements of size h fill [r0, r1]."""
    rho = np.linspace(r0, r1, 20001)
    g = np.clip(1.0 + growth * np.maximum(rho - fine_radius, 0.0), 1.0, max_factor)
    return float(np.sum(0.5 * (1 / g[1:] + 1 / g[:-1]) * np.diff(rho)))


@dataclass
class PlanSpec:
    """One quadrant of the O-grid, before copies.

    b: half side of the central square; n: elements along its side; ring: the ring's radial
    lattice positions (2 N + 1 values from b to the outer radius, mid points
    included); blend: the radius by which the square's sides have become circles."""
    b: float
    n: int
    ring: np.ndarray
    blend: float


@dataclass
class PlanMesh:
    """Quadratic quadrilaterals in the plane: points (P, 2) and quads (Q, 8) as point indices,
    corners counter-clockwise, then the mid points of sides 1-2, 2-3, 3-4, 4-1."""
    points: np.ndarray
    quads: np.ndarray
    quadrants: list = field(default_factory=list)


def _quadrant_lattices(spec: PlanSpec):
    """The three lattices of one quadrant (x >= 0, y >= 0): arrays (2 i + 1, 2 j + 1, 2)."""
    n, b = spec.n, spec.b
    t = np.linspace(0.0, 1.0, 2 * n + 1)
    square = np.stack(np.meshgrid(b * t, b * t, indexing="ij"), axis=-1)

    rho = spec.ring
    beta = np.clip((rho - b) / max(spec.blend - b, 1e-12), 0.0, 1.0)
    beta = beta * beta * (3 - 2 * beta)  # smoothstep: no kink in the grid lines
    side = np.stack([np.full_like(t, b), b * t], axis=-1)  # side x = b, from y = 0 up
    circle = np.stack([np.cos(t * np.pi / 4), np.sin(t * np.pi / 4)], axis=-1)
    ring_a = ((1 - beta)[None, :, None] * (rho / b)[None, :, None] * side[:, None, :]
              + (beta * rho)[None, :, None] * circle[:, None, :])
    ring_b = ring_a[..., ::-1]  # mirror about the diagonal: the block on the side y = b
    return [square, ring_a, ring_b]


def _rotate(lattice: np.ndarray, quarter_turns: int) -> np.ndarray:
    c, s = np.cos(quarter_turns * np.pi / 2), np.sin(quarter_turns * np.pi / 2)
    x, y = lattice[..., 0], lattice[..., 1]
    return np.stack([c * x - s * y, s * x + c * y], axis=-1)


def plan_mesh(spec: PlanSpec, quadrants: list[int]) -> PlanMesh:
    """The O-grid over the listed quadrants (0: x, y >= 0; 1: x <= 0, y >= 0; 2, 3 further
    counter-clockwise), coincident points merged."""
    lattices = []
    for q in quadrants:
        lattices += [_rotate(lat, q) for lat in _quadrant_lattices(spec)]
    return _merge(lattices, quadrants)


def _merge(lattices, quadrants) -> PlanMesh:
    """Quadratic quads of the lattices, coincident points merged, corners counter-clockwise."""
    pts, index_of = [], {}
    quads = []
    scale = 1e-7  # mm: points closer than this are the same point
    for lat in lattices:
        ids = np.empty(lat.shape[:2], dtype=np.int64)
        for i in range(lat.shape[0]):
            for j in range(lat.shape[1]):
                p = lat[i, j]
                key = (int(round(p[0] / scale)), int(round(p[1] / scale)))
                k = index_of.get(key)
                if k is None:
                    k = len(pts)
                    index_of[key] = k
                    pts.append(p)
                ids[i, j] = k
        for i in range(0, lat.shape[0] - 1, 2):
            for j in range(0, lat.shape[1] - 1, 2):
                quads.append([ids[i, j], ids[i + 2, j], ids[i + 2, j + 2], ids[i, j + 2],
                              ids[i + 1, j], ids[i + 2, j + 1], ids[i + 1, j + 2], ids[i, j + 1]])
    points = np.array(pts)
    quads = np.array(quads, dtype=np.int64)
    # counter-clockwise corners (signed area > 0); a mirrored block comes out clockwise
    c = points[quads[:, :4]]
    area = 0.5 * np.sum(c[:, :, 0] * np.roll(c[:, :, 1], -1, axis=1)
                        - np.roll(c[:, :, 0], -1, axis=1) * c[:, :, 1], axis=1)
    flip = area < 0
    quads[flip] = quads[flip][:, [0, 3, 2, 1, 7, 6, 5, 4]]
    return PlanMesh(points=points, quads=quads, quadrants=list(quadrants))


def annulus_mesh(ring: np.ndarray, n_circ: int, quadrants: list[int]) -> PlanMesh:
    """A polar grid between the radii ring[0] and ring[-1] (lattice positions, mid points
    included), n_circ elements per quadrant around."""
    t = np.linspace(0.0, np.pi / 2, 2 * n_circ + 1)
    quarter = np.stack([np.outer(np.cos(t), ring), np.outer(np.sin(t), ring)], axis=-1)
    return _merge([_rotate(quarter, q) for q in quadrants], quadrants)


# --------------------------------------------------------------------------------------------
# Surfaces: plan point -> (position, unit normal)

def sphere_map(radius: float, apex: np.ndarray, down: bool = False):
    """Geodesic polar map onto a sphere: the plan point at distance s from the origin goes to
    the point at arc length s from the apex, same azimuth. The normal points away from the
    centre. down=False: the apex is the top of the sphere (a cap); True: its bottom (an
    indenter seen from below)."""
    apex = np.asarray(apex, dtype=float)
    sign = -1.0 if down else 1.0
    centre = apex - sign * np.array([0.0, 0.0, radius])

    def f(p: np.ndarray):
        s = np.hypot(p[:, 0], p[:, 1])
        phi = s / radius
        with np.errstate(invalid="ignore", divide="ignore"):
            scale = np.where(s > 0, radius * np.sin(phi) / np.where(s > 0, s, 1), 0.0)
        x = np.stack([scale * p[:, 0], scale * p[:, 1], sign * radius * np.cos(phi)], axis=-1)
        return centre + x, x / radius
    return f


def plane_map(z0: float = 0.0):
    def f(p: np.ndarray):
        x = np.column_stack([p[:, 0], p[:, 1], np.full(len(p), z0)])
        nrm = np.zeros_like(x)
        nrm[:, 2] = 1.0
        return x, nrm
    return f


# --------------------------------------------------------------------------------------------
# Extrusion to 20-node hexahedra

# CalculiX / Abaqus C3D20 faces (manual, *SURFACE): corner nodes, 0-based
HEX_FACES = {1: [0, 1, 2, 3], 2: [4, 7, 6, 5], 3: [0, 4, 5, 1], 4: [1, 5, 6, 2],
             5: [2, 6, 7, 3], 6: [3, 7, 4, 0]}


@dataclass
class SolidMesh:
    nodes: np.ndarray          # (N, 3)
    elements: np.ndarray       # (E, 20), 0-based node indices
    elem_layer: np.ndarray     # (E,) layer index (0 = innermost, zeta lowest)
    elem_column: np.ndarray    # (E,) plan quad index
    node_plan: np.ndarray      # (N,) plan point index
    node_level: np.ndarray     # (N,) lattice level through the thickness (2 * layer boundary)
    levels: np.ndarray         # (2 L + 1,) zeta of every lattice level
    plan: PlanMesh
    column_normal: np.ndarray  # (Q, 3) unit normal at each plan quad's centre
    column_centre: np.ndarray  # (Q, 3) its position on the reference surface
    node_xy: np.ndarray = None    # (N, 2) plan coordinates of every node
    node_zeta: np.ndarray = None  # (N,) distance from the reference surface along the normal
    node_zone: np.ndarray = None  # (N,) zone index (combine)
    elem_zone: np.ndarray = None  # (E,)


def extrude(plan: PlanMesh, surface, zeta: np.ndarray) -> SolidMesh:
    """Hexahedra between the lattice levels zeta (2 L + 1 values: layer boundaries at even
    indices, mid-layer points at odd), along the surface normal. Element nodes 1-4 lie on the
    lower zeta, so with counter-clockwise plan corners and a normal that keeps the plan's
    orientation the Jacobian is positive (checked, and fixed by swapping the faces where not)."""
    zeta = np.asarray(zeta, dtype=float)
    nlev = len(zeta)
    nl = (nlev - 1) // 2
    pos, nrm = surface(plan.points)
    used = np.zeros((len(plan.points), nlev), dtype=bool)
    q = plan.quads
    elems_lattice = []
    for layer in range(nl):
        lo, mid, hi = 2 * layer, 2 * layer + 1, 2 * layer + 2
        for quad in q:
            c, m = quad[:4], quad[4:]
            lat = ([(p, lo) for p in c] + [(p, hi) for p in c] + [(p, lo) for p in m]
                   + [(p, hi) for p in m] + [(p, mid) for p in c])
            elems_lattice.append(lat)
            for p, lv in lat:
                used[p, lv] = True
    node_id = -np.ones((len(plan.points), nlev), dtype=np.int64)
    pp, ll = np.nonzero(used)
    node_id[pp, ll] = np.arange(len(pp))
    nodes = pos[pp] + zeta[ll][:, None] * nrm[pp]
    el = np.array([[node_id[p, lv] for p, lv in lat] for lat in elems_lattice], dtype=np.int64)
    layer_of = np.repeat(np.arange(nl), len(q))
    column_of = np.tile(np.arange(len(q)), nl)

    # Jacobian sign at the centre from the corner nodes
    x = nodes[el[:, :8]]
    d1 = (x[:, 1] + x[:, 2] + x[:, 5] + x[:, 6]) - (x[:, 0] + x[:, 3] + x[:, 4] + x[:, 7])
    d2 = (x[:, 2] + x[:, 3] + x[:, 6] + x[:, 7]) - (x[:, 0] + x[:, 1] + x[:, 4] + x[:, 5])
    d3 = x[:, 4:8].sum(axis=1) - x[:, 0:4].sum(axis=1)
    det = np.einsum("ij,ij->i", np.cross(d1, d2), d3)
    swap = det < 0
    perm = [4, 5, 6, 7, 0, 1, 2, 3, 12, 13, 14, 15, 8, 9, 10, 11, 16, 17, 18, 19]
    el[swap] = el[swap][:, perm]

    centres_plan = plan.points[q[:, :4]].mean(axis=1)
    cpos, cnrm = surface(centres_plan)
    return SolidMesh(nodes=nodes, elements=el, elem_layer=layer_of, elem_column=column_of,
                     node_plan=pp, node_level=ll, levels=zeta, plan=plan,
                     column_normal=cnrm, column_centre=cpos, node_xy=plan.points[pp],
                     node_zeta=zeta[ll], node_zone=np.zeros(len(pp), np.int64),
                     elem_zone=np.zeros(len(el), np.int64))


def combine(zones: list[SolidMesh]) -> SolidMesh:
    """Zones side by side (nodes not merged: they are tied), columns and layers renumbered
    globally (elem_layer keeps each zone's own layer index)."""
    node_off = np.cumsum([0] + [len(z.nodes) for z in zones])
    col_off = np.cumsum([0] + [len(z.plan.quads) for z in zones])
    cat = np.concatenate
    return SolidMesh(
        nodes=cat([z.nodes for z in zones]),
        elements=cat([z.elements + o for z, o in zip(zones, node_off)]),
        elem_layer=cat([z.elem_layer for z in zones]),
        elem_column=cat([z.elem_column + o for z, o in zip(zones, col_off)]),
        node_plan=cat([z.node_plan for z in zones]), node_level=cat([z.node_level for z in zones]),
        levels=None, plan=None,
        column_normal=cat([z.column_normal for z in zones]),
        column_centre=cat([z.column_centre for z in zones]),
        node_xy=cat([z.node_xy for z in zones]), node_zeta=cat([z.node_zeta for z in zones]),
        node_zone=cat([np.full(len(z.nodes), k) for k, z in enumerate(zones)]),
        elem_zone=cat([np.full(len(z.elements), k) for k, z in enumerate(zones)]))


def faces_on(mesh: SolidMesh, node_mask: np.ndarray, elem_mask: np.ndarray | None = None):
    """(element index, face label) of every hexahedron face whose four corners are all in
    node_mask."""
    out = []
    em = np.ones(len(mesh.elements), bool) if elem_mask is None else elem_mask
    for label, corners in HEX_FACES.items():
        hit = np.all(node_mask[mesh.elements[:, corners]], axis=1) & em
        out += [(int(e), label) for e in np.nonzero(hit)[0]]
    out.sort()
    return out


def layer_levels(boundaries: np.ndarray) -> np.ndarray:
    """Lattice levels (mid points included) from layer boundaries."""
    b = np.asarray(boundaries, dtype=float)
    out = np.empty(2 * len(b) - 1)
    out[0::2] = b
    out[1::2] = 0.5 * (b[1:] + b[:-1])
    return out
