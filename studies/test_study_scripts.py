#!/usr/bin/python3
"""Unit tests of the study scripts' own logic (issue 13 items 19 and 21), run by ctest without
running any sweep: which sweep failures fail a study, where the reports go, that the report
cites only paths inside the repository, and that README.md and scripts/main.sh state the same
time for the main job.

Run: /usr/bin/python3 studies/test_study_scripts.py
"""
import argparse
import os
import re
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import paper_layups  # noqa: E402
import paper_report  # noqa: E402
import sandwich  # noqa: E402
from study_support import SOURCE_DIR  # noqa: E402


def run(exit_code, tail=("case failed",)):
    return {"exit_code": exit_code, "stderr_tail": list(tail), "study": "x.yaml", "what": "x",
            "wall_s": 1.0, "measured": "now", "cpu_s": 1.0}


def case(layup, status="completed", reason=""):
    return {"layup": layup, "status": status, "reason": reason, "fit_status": "converged",
            "C2": 1.5, "energy_J": None, "work_J": None}


class Checks(unittest.TestCase):
    """Item 19: a study returns non-zero when a sweep fails, unless its failure is expected."""

    def test_a_failed_variant_fails_the_study(self):
        runs = {"default": run(0), "linear": run(1)}
        results = {"default": [case("[0/0]2S")], "linear": [case("[0/0]2S", "failed", "x")]}
        problems = paper_layups.checks(runs, results, {})
        self.assertTrue(any("linear" in p for p in problems), problems)

    def test_the_expected_failure_of_bernstein4_passes(self):
        reason = "case.yaml: mesh.element = 'bernstein4': degenerate shell element: director"
        runs = {"default": run(0), "bernstein4": run(1)}
        results = {"default": [case("[0/0]2S")],
                   "bernstein4": [case("[0/0]2S", "failed", reason)]}
        self.assertEqual(paper_layups.checks(runs, results, {}), [])

    def test_bernstein4_failing_for_another_reason_fails_the_study(self):
        runs = {"default": run(0), "bernstein4": run(1)}
        results = {"default": [case("[0/0]2S")],
                   "bernstein4": [case("[0/0]2S", "failed", "step too small")]}
        self.assertTrue(paper_layups.checks(runs, results, {}))

    def test_bernstein4_running_through_is_a_finding(self):
        runs = {"default": run(0), "bernstein4": run(0)}
        results = {"default": [case("[0/0]2S")], "bernstein4": [case("[0/0]2S")]}
        self.assertTrue(paper_layups.checks(runs, results, {}))


class Stability(unittest.TestCase):
    """Issue 15 item 5: the paper study's stability summary of a path."""

    def test_a_run_without_stability_has_none(self):
        self.assertIsNone(paper_layups.stability_summary([{"depth_mm": 0.1}], [])["stability"])

    def test_unstable_points_and_the_first_change_are_counted(self):
        rows = [{"stable": 1, "lowest_eigenvalue": 3.0}, {"stable": 0, "lowest_eigenvalue": -1.0},
                {"stable": 1, "lowest_eigenvalue": 2.0}]
        events = [{"type": "signature_change", "depth_mm": 0.1},
                  {"type": "stability_change", "depth_mm": 0.5, "force_N": 10.0,
                   "criticality": "bifurcation"},
                  {"type": "stability_change", "depth_mm": 0.9, "force_N": 20.0,
                   "criticality": "limit_point"}]
        s = paper_layups.stability_summary(rows, events)
        self.assertEqual((s["stability_points"], s["unstable_points"]), (3, 1))
        self.assertEqual(s["lowest_eigenvalue_min"], -1.0)
        self.assertEqual(s["stability_change"],
                         {"depth_mm": 0.5, "force_N": 10.0, "criticality": "bifurcation"})


class Reports(unittest.TestCase):
    """Item 19: reports go to the output directory unless asked; they cite only repository
    paths."""

    def test_reports_go_to_the_output_directory_by_default(self):
        args = argparse.Namespace(report_dir=None, quick=False)
        for module in (paper_layups, sandwich):
            self.assertEqual(module.report_directory(args, "/tmp/out"), "/tmp/out/report")
        args.report_dir = "docs/"
        self.assertEqual(paper_layups.report_directory(args, "/tmp/out"),
                         os.path.abspath("docs"))

    def test_the_report_cites_no_path_outside_the_repository(self):
        args = argparse.Namespace(quick=False)
        timing = {"sweeps_wall_s": 1.0, "post_processing_wall_s": 1.0, "jobs": 2,
                  "load_average": (1.0, 1.0, 1.0)}
        text = "\n".join(paper_report.header(args, {"default": run(0)}, timing, 10.0))
        text += paper_report.LOCAL_PARAGRAPH + paper_report.magnitude_paragraph({})
        self.assertNotIn("../", text)
        self.assertNotIn(SOURCE_DIR, text)

    def test_no_study_source_cites_the_shared_directory(self):
        for name in ("paper_report.py", "paper_data.py", "paper_layups.py", "sandwich.py"):
            with open(os.path.join(SOURCE_DIR, "studies", name)) as f:
                self.assertNotIn("../shared", f.read(), name)


class MainJob(unittest.TestCase):
    """Item 21: README.md and scripts/main.sh state the same time for the main job."""

    def test_readme_and_main_sh_agree(self):
        def seconds(path):
            with open(os.path.join(SOURCE_DIR, path)) as f:
                found = re.findall(r"takes about (\d+) s", " ".join(f.read().split()))
            self.assertEqual(len(found), 1, path)
            return found[0]
        self.assertEqual(seconds("README.md"), seconds("scripts/main.sh"))


if __name__ == "__main__":
    unittest.main()
