"""Cases and helpers shared by the module's tests (run by ctest: python_module_tests)."""

import csv
import os
import subprocess

import numpy as np

EXE = os.environ.get("SHELLINDENT_EXE", "shellindent")
OUT = os.environ.get("SHELLINDENT_TEST_DIR", "python_test_output")

# The paper's cap on a coarse quarter mesh to 3 mm in 30 steps: a second or so.
QUICK_CAP = {
    "material": "paper-carbon-epoxy",
    "laminate": {"layup": "[0/0]2S", "ply_thickness": "0.475 mm", "reference": "mid"},
    "shell": {"type": "spherical_cap", "base_radius": "25 mm", "radius": "80.9 mm",
              "edge": "clamped"},
    "mesh": {"element": "mitc4", "size_apex": "1.5 mm", "size_edge": "4 mm",
             "refine_radius": "13 mm", "symmetry": "quarter"},
    "kinematics": "nonlinear",
    "indenter": {"shape": "sphere", "radius": "12.7 mm"},
    "contact": {"surface": "outer", "solver": "kinsol"},
    "path": {"method": "pseudo_arclength", "depth_max": "3 mm", "step": "0.1 mm",
             "step_max": "0.1 mm"},
    "output": {"vtu_every": 0},
}


def out_dir(name):
    path = os.path.join(OUT, name)
    os.makedirs(path, exist_ok=True)
    return path


def run_cli(*args):
    """The CLI's exit code, stdout and stderr."""
    p = subprocess.run([EXE, *args], capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


def read_csv_columns(path):
    """path.csv as {column: float array} and its text values {column: [str]}."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    text = {name: [r[i] for r in body] for i, name in enumerate(header)}
    values = {name: np.array([float(v) for v in col]) for name, col in text.items()}
    return values, text
