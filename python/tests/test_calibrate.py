"""shellindent.calibrate against `shellindent calibrate`: on a coarse quarter cap (Yang-Sun law,
elastic indenter, 3 mm of travel, about 0.15 s a run) with synthetic data made by the model
itself (E3 = 8 GPa, G13 = 4 GPa, 1 % Gaussian noise, seeded), the truth lies inside the 95 %
intervals and the optimum is the CLI's to the last digit; the indenter's E and nu, which enter
only as (1 - nu^2)/E, raise the identifiability warning; bad input raises InputError with the
CLI's text; a progress function returning False stops with the best point so far."""

import json
import os
import shutil
import unittest

import numpy as np

import shellindent as si
from cases import OUT, run_cli

# tests/app/test_calibrate_command.cpp's coarse cap.
COARSE_CAP = {
    "material": "paper-carbon-epoxy",
    "laminate": {"layup": "[0/0]2S", "ply_thickness": "0.475 mm"},
    "mesh": {"size_apex": "1.5 mm", "size_edge": "4 mm", "refine_radius": "8 mm",
             "symmetry": "quarter"},
    "indenter": {"shape": "sphere", "radius": "12.7 mm",
                 "material": {"type": "isotropic", "E": "200 GPa", "nu": 0.3}},
    "contact": {"local": "yang_sun"},
    "path": {"depth_max": "3 mm", "step": "0.1 mm"},
}
TRAVEL = 0.3 * np.arange(1, 11)


def model_forces(material, indenter_modulus="200 GPa"):
    """The model's forces at TRAVEL with the top-level material and the indenter's modulus
    changed: a natural path stopping exactly at each travel, as a calibration's evaluation runs
    it."""
    case = dict(COARSE_CAP, material=material)
    case["indenter"] = dict(COARSE_CAP["indenter"],
                            material={"type": "isotropic", "E": indenter_modulus, "nu": 0.3})
    case["path"] = {"method": "natural", "depth_max": "3 mm", "step": "0.1 mm",
                    "depths": [f"{t:.1f} mm" for t in TRAVEL]}
    result = si.run(case, threads=1)
    assert result.completed, result.reason
    depth, force = result["depth_mm"], result["force_N"]
    return np.array([force[np.argmin(abs(depth - t))] for t in TRAVEL])


def paper_material(**changes):
    """paper-carbon-epoxy's elastic constants (src/material/material_library.cpp) as an inline
    table, with `changes` set."""
    m = {"type": "orthotropic", "E1": "130 GPa", "E2": "10 GPa", "E3": "10 GPa",
         "G12": "6 GPa", "G13": "3 GPa", "G23": "6 GPa", "nu12": 0.3, "nu13": 0.5, "nu23": 0.3}
    m.update(changes)
    return m


def fresh(name):
    path = os.path.join(OUT, name)
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return path


class Calibrate(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = fresh("calibrate")
        cls.case_file = os.path.join(cls.dir, "case.yaml")
        with open(cls.case_file, "w") as f:
            f.write(si.case_yaml(COARSE_CAP))
        clean = model_forces(paper_material(E3="8 GPa", G13="4 GPa"))
        rng = np.random.default_rng(1)
        cls.force = clean + 0.01 * clean[-1] * rng.standard_normal(len(clean))
        cls.data_file = os.path.join(cls.dir, "measured.csv")
        with open(cls.data_file, "w") as f:
            f.write("travel_mm,force_N\n")
            f.writelines(f"{t!r},{y!r}\n" for t, y in zip(TRAVEL, cls.force))

    def test_recovers_e3_and_g13_as_the_cli_does(self):
        lines = []
        r = si.calibrate(self.case_file, (TRAVEL, self.force),
                         {"material.E3": "4:20GPa", "material.G13": ("1GPa", "8GPa")},
                         progress=lambda p: lines.append(p["line"]))
        self.assertEqual(r.status, "converged", r.table)
        self.assertEqual(r.names, ["material.E3", "material.G13"])
        for key, truth in (("material.E3", 8000.0), ("material.G13", 4000.0)):
            low, high = r.intervals[key]
            print(f"[calibrate] {key}: true {truth}, estimate {r.parameters[key]:.1f}, "
                  f"95 % interval [{low:.1f}, {high:.1f}] {r.units[key]}")
            self.assertLessEqual(low, truth)
            self.assertGreaterEqual(high, truth)
        self.assertEqual(r.warnings, [])
        self.assertEqual(r.correlation.shape, (2, 2))
        self.assertAlmostEqual(r.correlation[0, 1], r.correlation[1, 0])
        self.assertTrue(-1 < r.correlation[0, 1] < 0)  # E3 and G13 trade against each other
        self.assertTrue(lines[0].startswith("calibrate: 1 search   material.E3 = "), lines[0])
        np.testing.assert_allclose(r.curve["measured_force_N"], self.force, rtol=1e-11)
        self.assertIsNotNone(r.case)

        # The CLI on the same numbers (a file with 17 digits): the same optimum, bit for bit.
        out = os.path.join(self.dir, "cli")
        code, _, err = run_cli("calibrate", self.case_file, "--data", self.data_file,
                               "--param", "material.E3=4:20GPa", "--param",
                               "material.G13=1GPa:8GPa", "--out", out)
        self.assertEqual(code, 0, err)
        with open(os.path.join(out, "calibration.json")) as f:
            cli = json.load(f)
        for p in cli["parameters"]:
            self.assertEqual(p["value"], r.parameters[p["key"]])
            self.assertEqual((p["ci_low"], p["ci_high"]), r.intervals[p["key"]])
        self.assertEqual(cli["evaluations"], r.report["evaluations"])
        with open(os.path.join(out, "calibrated_case.yaml")) as f:
            self.assertEqual(f.read(), r.files()["calibrated_case.yaml"])

        # The same through the CSV file, written as the CLI writes.
        r2 = si.calibrate(self.case_file, self.data_file,
                          ["material.E3=4:20GPa", "material.G13=1GPa:8GPa"])
        self.assertEqual(r2.parameters, r.parameters)
        written = os.path.join(self.dir, "module")
        r2.write(written)
        with open(os.path.join(out, "calibration_curve.csv")) as a, \
                open(os.path.join(written, "calibration_curve.csv")) as b:
            self.assertEqual(a.read(), b.read())

    def test_indenter_modulus_and_poisson_ratio_are_not_separable(self):
        force = model_forces(paper_material(), indenter_modulus="150 GPa")
        r = si.calibrate(COARSE_CAP, (TRAVEL, force),
                         {"indenter.material.E": "100:400GPa:200GPa",
                          "indenter.material.nu": (0.05, 0.45, 0.3)},
                         max_evaluations=16)
        self.assertTrue(r.warnings, r.table)
        named = [w["parameters"] for w in r.report["identifiability"]["warnings"]]
        self.assertIn(["indenter.material.E", "indenter.material.nu"], named)

    def test_bad_input_raises_the_clis_error(self):
        code, _, err = run_cli("calibrate", self.case_file, "--data", self.data_file,
                               "--param", "materal.E3=4:20GPa", "--out",
                               os.path.join(self.dir, "bad"))
        self.assertEqual(code, 2)
        with self.assertRaises(si.InputError) as e:
            si.calibrate(self.case_file, self.data_file, {"materal.E3": "4:20GPa"})
        self.assertEqual("shellindent: error: " + str(e.exception), err.strip())
        self.assertEqual(e.exception.key, "--param")

        with self.assertRaises(si.InputError) as e:
            si.calibrate(COARSE_CAP, ([0.5, 1.0, 0.8, 2.0], [5, 10, 16, 22]),
                         {"material.E3": "4:20GPa"})
        self.assertIn("<data>:4: travel_mm = '0.8': the travel must increase strictly", str(e.exception))
        with self.assertRaises(si.InputError) as e:
            si.calibrate(COARSE_CAP, ([0.5, 1.0, 1.5], [5, 10, 16]),
                         {"material.E3": "4:20GPa", "material.G13": "1:8GPa"})
        self.assertIn("needs at least 4", str(e.exception))
        with self.assertRaises(si.InputError) as e:
            si.calibrate(COARSE_CAP, (TRAVEL, self.force), {"material.E3": "0:20GPa"})
        self.assertIn("this bound gives an invalid case", str(e.exception))

    def test_progress_returning_false_stops_with_the_best_point(self):
        r = si.calibrate(COARSE_CAP, (TRAVEL, self.force), {"material.E3": "4:20GPa"},
                         progress=lambda p: p["evaluation"] < 3)
        self.assertEqual(r.status, "interrupted")
        self.assertEqual(r.report["evaluations"]["search"], 3)
        self.assertIsNotNone(r.parameters["material.E3"])


if __name__ == "__main__":
    unittest.main()
