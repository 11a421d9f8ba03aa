#!/usr/bin/python3
"""Reads a VTU file with meshio (an independent reader: python3-meshio) and prints its points,
quads and arrays as JSON on stdout, for tests/io/test_vtu_readback.cpp.

Usage: /usr/bin/python3 tests/io/vtu_to_json.py FILE.vtu
"""
import json
import sys

import meshio


def main(path):
    mesh = meshio.read(path, file_format="vtu")
    quads = [block.data.tolist() for block in mesh.cells if block.type == "quad"]
    out = {
        "points": mesh.points.tolist(),
        "quads": [q for block in quads for q in block],
        "other_cells": sum(len(b.data) for b in mesh.cells if b.type != "quad"),
        "point_data": {k: v.reshape(len(v), -1).tolist() for k, v in mesh.point_data.items()},
        "cell_data": {k: [r for block in v for r in block.reshape(len(block), -1).tolist()]
                      for k, v in mesh.cell_data.items()},
    }
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main(sys.argv[1])
