"""Ctrl-C (KeyboardInterrupt) and exceptions of the progress function stop a run cleanly: the
exception reaches the caller with the converged points in its `result`, which are the first
points of the uninterrupted path."""

import os
import signal
import threading
import unittest

import numpy as np

import shellindent as si
from cases import QUICK_CAP


class Interrupts(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.full = si.run(QUICK_CAP, threads=1)
        assert cls.full.completed, cls.full.reason

    def assert_prefix_of_full_path(self, partial):
        self.assertGreater(len(partial), 0)
        self.assertLess(len(partial), len(self.full))
        self.assertEqual(partial.status, "stopped_by_callback")
        for name in partial.path:
            np.testing.assert_array_equal(partial[name], self.full[name][:len(partial)],
                                          err_msg=name)

    def test_keyboard_interrupt_from_the_progress_function(self):
        calls = []

        def progress(p):
            calls.append(p["index"])
            if len(calls) == 4:
                raise KeyboardInterrupt

        with self.assertRaises(KeyboardInterrupt) as caught:
            si.run(QUICK_CAP, progress=progress, threads=1)
        partial = caught.exception.result
        self.assertEqual(len(partial), 4)  # the point the function saw converged: it is kept
        self.assert_prefix_of_full_path(partial)

    def test_sigint_during_the_solve(self):
        # A real Ctrl-C: SIGINT from another thread while the main thread solves without the
        # GIL; Python's handler only flags it, and the run checks the flag at the next point.
        calls = []

        def progress(p):
            calls.append(p["index"])
            if len(calls) == 2:
                threading.Thread(target=os.kill, args=(os.getpid(), signal.SIGINT)).start()

        with self.assertRaises(KeyboardInterrupt) as caught:
            si.run(QUICK_CAP, progress=progress, threads=1)
        partial = caught.exception.result
        # Raised at the check before the next progress call, or inside it: the point that
        # was converged when the interrupt was seen is kept either way.
        self.assertIn(len(partial), (len(calls), len(calls) + 1))
        self.assert_prefix_of_full_path(partial)

    def test_other_exceptions_carry_the_points_too(self):
        def progress(p):
            if p["index"] == 2:
                raise ValueError("enough")

        with self.assertRaises(ValueError) as caught:
            si.run(QUICK_CAP, progress=progress, threads=1)
        self.assertEqual(str(caught.exception), "enough")
        self.assertEqual(len(caught.exception.result), 3)
        self.assert_prefix_of_full_path(caught.exception.result)


if __name__ == "__main__":
    unittest.main()
