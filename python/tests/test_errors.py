"""A bad case raises shellindent.InputError whose text is the CLI's error message on the
equivalent file (the dict is written as YAML and read by the same reader), with the file, line,
key and value as attributes."""

import os
import unittest

import shellindent as si
from cases import QUICK_CAP, out_dir, run_cli

PREFIX = "shellindent: error: "


def with_changes(base, changes):
    case = {k: dict(v) if isinstance(v, dict) else v for k, v in base.items()}
    for section, values in changes.items():
        if isinstance(values, dict) and isinstance(case.get(section), dict):
            case[section].update(values)
        else:
            case[section] = values
    return case


class BadDictMatchesCli(unittest.TestCase):
    def check(self, name, case, key, value):
        path = os.path.join(out_dir("bad_cases"), name + ".yaml")
        with open(path, "w") as f:
            f.write(si.case_yaml(case))
        code, _, err = run_cli("run", path, "--out", os.path.join(out_dir("bad_cases"), name))
        self.assertEqual(code, 2, err)
        self.assertTrue(err.startswith(PREFIX), err)
        cli_message = err[len(PREFIX):].rstrip("\n")
        with self.assertRaises(si.InputError) as caught:
            si.run(si.read_case(case, label=path), threads=1)
        e = caught.exception
        self.assertEqual(str(e), cli_message)
        self.assertEqual(e.file, path)
        self.assertEqual(e.key, key)
        self.assertEqual(e.value, value)
        self.assertIsInstance(e.line, int)
        with open(path) as f:
            self.assertIn(key.split(".")[-1], f.read().splitlines()[e.line - 1])
        self.assertFalse(os.path.exists(os.path.join(out_dir("bad_cases"), name, "path.csv")))
        return e

    def test_negative_ply_thickness(self):
        e = self.check("negative_thickness",
                       with_changes(QUICK_CAP, {"laminate": {"ply_thickness": "-0.475 mm"}}),
                       "laminate.ply_thickness", "-0.475 mm")
        self.assertIsInstance(e, ValueError)  # InputError is a ValueError for generic handlers

    def test_wrong_unit(self):
        self.check("wrong_unit", with_changes(QUICK_CAP, {"indenter": {"radius": "12.7 N"}}),
                   "indenter.radius", "12.7 N")

    def test_unknown_key_with_did_you_mean(self):
        e = self.check("unknown_key", with_changes(QUICK_CAP, {"path": {"depth_mx": "3 mm"}}),
                       "path.depth_mx", "3 mm")
        self.assertIn("depth_max", str(e))

    def test_error_found_after_reading(self):
        # A quarter model of an angle ply is refused by the model's set-up, after the reader;
        # the CLI and the module both locate it in the case text.
        self.check("quarter_angle_ply",
                   with_changes(QUICK_CAP, {"laminate": {"layup": "[45/-45]2S"}}),
                   "mesh.symmetry", "quarter")

    def test_dict_label_defaults_to_dict(self):
        with self.assertRaises(si.InputError) as caught:
            si.read_case(with_changes(QUICK_CAP, {"laminate": {"ply_thickness": "-1 mm"}}))
        self.assertTrue(str(caught.exception).startswith("<dict>:"), str(caught.exception))

    def test_missing_file(self):
        with self.assertRaises(si.InputError) as caught:
            si.read_case("no/such/case.yaml")
        self.assertEqual(caught.exception.file, "no/such/case.yaml")

    def test_thread_counts_the_cli_refuses(self):
        # As `run --threads` (docs/hardening.md item 2): negative, or far above the machine.
        for threads in (-1, 100000, 1.5):
            with self.assertRaises(si.InputError) as caught:
                si.run(QUICK_CAP, threads=threads)
            self.assertEqual(caught.exception.key, "threads")

    def test_not_a_case(self):
        with self.assertRaises(TypeError):
            si.read_case(42)


class CaseText(unittest.TestCase):
    def test_dict_text_and_file_give_the_same_case(self):
        text = si.case_yaml(QUICK_CAP)
        path = os.path.join(out_dir("cases"), "quick.yaml")
        with open(path, "w") as f:
            f.write(text)
        for source in (QUICK_CAP, text, path):
            c = si.read_case(source)
            self.assertEqual(c.yaml, text)
            self.assertEqual(c.depth_max_mm, 3.0)

    def test_strings_that_yaml_would_misread_are_quoted(self):
        text = si.case_yaml({"laminate": {"layup": "[0/±45/90]s", "note": "yes"}})
        self.assertIn('layup: "[0/±45/90]s"', text)
        self.assertIn('note: "yes"', text)


if __name__ == "__main__":
    unittest.main()
