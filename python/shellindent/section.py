"""Section properties of a laminate, as `shellindent section CASE --json` writes them.

Only the case's material and laminate matter: section({"material": "paper-carbon-epoxy",
"laminate": {"layup": "[45/-45]2S", "ply_thickness": "0.475 mm"}}) takes the other sections'
defaults. Matrices come back as NumPy
arrays, in Yu's order: strains [e11, 2e12, e22, k11, k12+k21, k22], shear [2g13, 2g23]; units in
the result's "units" entry (A N/mm, B N, D N*mm, G N/mm).
"""

import json

import numpy as np

from . import _core
from .case import read_case


def _arrays(value):
    if isinstance(value, dict):
        return {k: _arrays(v) for k, v in value.items()}
    if isinstance(value, list) and value and all(isinstance(v, (int, float)) for v in value):
        return np.array(value, dtype=float)
    if (isinstance(value, list) and value and all(isinstance(v, list) for v in value)
            and all(isinstance(x, (int, float)) for v in value for x in v)):
        return np.array(value, dtype=float)
    if isinstance(value, list):
        return [_arrays(v) for v in value]
    return value


def section(case, vam_order=4):
    """The section properties of the laminate of `case` (Case, dict, path or YAML text).

    Returns a dict: label, plies_bottom_to_top, thickness_mm, clt {A, B, D}, shear {vam,
    fsdt_k5_6, equilibrium}, vam {A_R (6x6), G (2x2), Fbar_top, Fbar_bottom, c_L, fit}, units.
    """
    return _arrays(json.loads(_core.section_json(read_case(case), vam_order)))
