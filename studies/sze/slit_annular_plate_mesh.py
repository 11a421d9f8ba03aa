#!/usr/bin/env python3
"""Writes the mesh of Sze, Liu & Lo (2004) sec. 3.3, the slit annular plate, as a Gmsh 2.2 file.

Sze et al. give the plate in consistent units (Ri = 6, Ro = 10, h = 0.03, E = 21e6, q = 0.8);
the mesh is written with those lengths read as mm (the case file sze_3-3_slit_annular_plate.yaml
scales E and q alike, which leaves the displacements unchanged). Radial x circumferential
quadrangles, numbered counter-clockwise about +z (the directors point to +z). The lips of the
slit are the radial lines at angle 0 (clamped) and 360 deg - 1e-6 rad (loaded): 6e-6 mm apart
at the inner edge, because shellindent refuses coincident nodes that are not merged (1e-6 rad is
1.3e-5 of an element's angle). Physical groups: curves `slit_fixed`, `slit_loaded`, points `A`
(inner corner of the loaded lip) and `B` (outer corner), surface `plate`.

Usage: /usr/bin/python3 studies/sze/slit_annular_plate_mesh.py N_RADIAL N_CIRC OUT.msh
(the committed files: 6 80 slit_annular_plate_6x80.msh, 10 80 slit_annular_plate_10x80.msh).
"""
import math
import sys

RI, RO = 6.0, 10.0
GAP_RAD = 1e-6


def write_mesh(n_radial, n_circ, path):
    def node(i, j):  # 1-based tag of radial station i, circumferential station j
        return 1 + i + (n_radial + 1) * j

    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", "5",
             '0 1 "A"', '0 2 "B"', '1 3 "slit_fixed"', '1 4 "slit_loaded"', '2 5 "plate"',
             "$EndPhysicalNames", "$Nodes", str((n_radial + 1) * (n_circ + 1))]
    for j in range(n_circ + 1):
        angle = (2 * math.pi - GAP_RAD) * j / n_circ
        for i in range(n_radial + 1):
            r = RI + (RO - RI) * i / n_radial
            lines.append(f"{node(i, j)} {r * math.cos(angle):.17g} {r * math.sin(angle):.17g} 0")
    lines.append("$EndNodes")
    elements = [(15, 1, [node(0, n_circ)]), (15, 2, [node(n_radial, n_circ)])]
    for i in range(n_radial):
        elements.append((1, 3, [node(i, 0), node(i + 1, 0)]))
        elements.append((1, 4, [node(i, n_circ), node(i + 1, n_circ)]))
    for j in range(n_circ):
        for i in range(n_radial):
            elements.append((3, 5, [node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]))
    lines += ["$Elements", str(len(elements))]
    for tag, (kind, group, nodes) in enumerate(elements, start=1):
        lines.append(f"{tag} {kind} 2 {group} {group} " + " ".join(map(str, nodes)))
    lines.append("$EndElements")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    write_mesh(int(sys.argv[1]), int(sys.argv[2]), sys.argv[3])
