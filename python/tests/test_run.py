"""The module's path runs against the CLI's: the same arrays as path.csv, same file bytes."""

import os
import threading
import time
import unittest

import numpy as np

import shellindent as si
from cases import QUICK_CAP, out_dir, read_csv_columns, run_cli


class PaperCapEqualsCli(unittest.TestCase):
    """The built-in default (the source paper's cap, [0/0]2S, 0-10 mm) through the module and
    through `shellindent run`, one thread each. With a checkpoint file, as the CLI keeps one, it
    is the same computation: path.csv byte for byte. Without, the solver's caches are not
    dropped every 10 points and the path differs in its last bits. Each point's depth is its
    predictor's (the fixed-depth corrector on steep steps, docs/theory/continuation.md 3), which
    carries the tangent's Krylov accuracy, so those bits move the points along the same branch:
    equal to path.csv within rtol 1e-7 (measured: 3.8e-8 at most, in `step`, the arclength of the
    step along the predictor's direction, 2026-11-30; 7e-12 with Keller's corrector alone)."""

    @classmethod
    def setUpClass(cls):
        cls.cli_dir = out_dir("paper_cap_cli")
        code, _, err = run_cli("run", "--out", cls.cli_dir, "--threads", "1")
        if code != 0:
            raise AssertionError("shellindent run failed:\n" + err)
        cls.values, _ = read_csv_columns(os.path.join(cls.cli_dir, "path.csv"))
        checkpoint = os.path.join(out_dir("paper_cap_module"), "checkpoint.json")
        cls.same = si.run(threads=1, checkpoint=checkpoint)
        cls.plain = si.run(threads=1)

    def test_with_a_checkpoint_the_files_are_the_cli_files(self):
        written = out_dir("paper_cap_module")
        self.same.write(written)
        for name in ("path.csv", "events.json"):
            with open(os.path.join(self.cli_dir, name)) as a, \
                    open(os.path.join(written, name)) as b:
                self.assertEqual(a.read(), b.read(), name)
        for name, expected in self.values.items():
            np.testing.assert_allclose(self.same[name], expected, rtol=5e-12, atol=1e-300,
                                       err_msg=name)

    def test_arrays_equal_path_csv(self):
        self.assertEqual(list(self.values), list(self.plain.path))
        self.assertTrue(self.plain.completed, self.plain.reason)
        self.assertEqual(len(self.plain), len(self.values["depth_mm"]))
        self.assertEqual(self.plain["depth_mm"][-1], 10.0)
        for name, expected in self.values.items():
            if name in ("min_gap_mm", "min_multiplier_N", "max_complementarity_Nmm"):
                # Residuals of the converged equations, round-off sized: no relative digits to
                # compare, the absolute difference far below the solver's tolerance.
                np.testing.assert_allclose(self.plain[name], expected, rtol=0, atol=1e-9,
                                           err_msg=name)
                continue
            np.testing.assert_allclose(self.plain[name], expected, rtol=1e-7, atol=1e-300,
                                       err_msg=name)

    def test_units_are_the_column_table(self):
        self.assertEqual(self.plain.units["force_N"], "N")
        self.assertEqual(self.plain.units["depth_mm"], "mm")
        # column_units() is the whole table; a run without damage or stability output writes
        # its leading columns, in the same order (the optional ones come last).
        table = list(si.column_units())
        self.assertEqual(table[:len(self.plain.path)], list(self.plain.path))
        self.assertIn("hashin_index", table)
        self.assertNotIn("hashin_index", self.plain.path)

    def test_events_lie_on_the_path(self):
        self.assertTrue(self.plain.events, "no event located")
        for e in self.plain.events:
            self.assertGreaterEqual(e["depth_mm"], 0.0)
            self.assertLessEqual(e["depth_mm"], 10.0)


class CompanionMesh(unittest.TestCase):
    """mesh.error_estimate: companion through the module: the same force_error_estimate column
    as the CLI's path.csv (the companion's path is the same computation)."""

    def test_force_error_as_the_cli(self):
        case = dict(QUICK_CAP)
        case["mesh"] = dict(QUICK_CAP["mesh"], error_estimate="companion")
        case["path"] = dict(QUICK_CAP["path"], depth_max="0.6 mm")
        r = si.run(case, threads=1)
        self.assertTrue(r.completed, r.reason)
        estimate = r["force_error_estimate"]
        self.assertTrue(np.isnan(estimate[0]))  # depth 0: no force
        self.assertTrue(np.all(estimate[1:] > 0), estimate)
        case_file = os.path.join(out_dir("companion_cli"), "case.yaml")
        with open(case_file, "w") as f:
            f.write(si.case_yaml(case))
        code, _, err = run_cli("run", case_file, "--out", out_dir("companion_cli"),
                               "--threads", "1")
        self.assertEqual(code, 0, err)
        values, _ = read_csv_columns(os.path.join(out_dir("companion_cli"), "path.csv"))
        # The CLI drops its solver caches at its checkpoints, the module without one does not:
        # the points' depths move along the branch by the tangent's Krylov accuracy (the
        # fixed-depth corrector, test PaperCapEqualsCli), measured 2.3e-9 here.
        np.testing.assert_allclose(estimate[1:], values["force_error_estimate"][1:], rtol=1e-8)


class Progress(unittest.TestCase):
    def test_progress_sees_every_point_in_order(self):
        seen = []
        r = si.run(QUICK_CAP, progress=lambda p: seen.append((p["index"], p["depth_mm"])),
                   threads=1)
        self.assertTrue(r.completed, r.reason)
        self.assertEqual([i for i, _ in seen], list(range(len(seen))))
        # The start point is a point of the path too; every point is reported once.
        self.assertEqual(len(seen), len(r))
        np.testing.assert_array_equal([d for _, d in seen], r["depth_mm"])

    def test_returning_false_stops_keeping_the_points(self):
        full = si.run(QUICK_CAP, threads=1)
        calls = []

        def stop_at_third(p):
            calls.append(p["index"])
            return len(calls) < 3

        r = si.run(QUICK_CAP, progress=stop_at_third, threads=1)
        self.assertEqual(r.status, "stopped_by_callback")
        self.assertFalse(r.completed)
        self.assertEqual(len(r), 3)
        for name in r.path:
            np.testing.assert_array_equal(r[name], full[name][:3], err_msg=name)

    def test_the_gil_is_released_during_the_solve(self):
        # Another Python thread runs while the path is solved: with the GIL held by the solve,
        # this loop would stand still for the whole run.
        # The paper's mesh on the quick path: a few seconds of solving.
        case = dict(QUICK_CAP, mesh=dict(QUICK_CAP["mesh"], size_apex="0.5 mm",
                                         size_edge="2 mm"))
        done = []
        t = threading.Thread(target=lambda: done.append(si.run(case, threads=1)))
        ticks = 0
        start = time.monotonic()
        t.start()
        while t.is_alive():
            ticks += 1
            time.sleep(0.001)
        elapsed = time.monotonic() - start
        self.assertTrue(done[0].completed)
        # Held, the loop would get the GIL about once per point (when the callback takes it):
        # a few ticks per point. Released, a tick per millisecond or so.
        points = len(done[0])
        self.assertGreater(ticks, 5 * points + 20, f"{ticks} ticks in {elapsed:.2f} s")


if __name__ == "__main__":
    unittest.main()
