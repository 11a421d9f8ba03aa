"""Running a case: the depth path as NumPy arrays keyed by path.csv's column names.

run() calls the same C++ as `shellindent run` (analysis/indentation_run) without writing files;
Result.write() writes path.csv, path.json, events.json and path_grid.csv as the CLI does. The GIL is released
during the solve, so other Python threads go on while a path runs.

Stopping a run: the progress function is called with each converged point (a dict of the point's
values by column name, plus "index"); returning False stops the run (status
"stopped_by_callback"). An exception raised by it, and Ctrl-C (KeyboardInterrupt, checked at each
point), stop the run at that point too: the exception is raised again with the partial result,
every converged point in it, as its attribute `result`.
"""

import json
import os
import tempfile
import warnings

import numpy as np

from . import _core
from .case import default_case, read_case
from .errors import InputError

# As `shellindent run --threads` (io/thread_count.hpp): more than 4 per hardware thread is
# never faster and crashed libgomp at 100000.
THREADS_PER_CORE = 4


class Result:
    """The outcome of run(): the path, how it ended, its events.

    path       dict column name -> 1-D float array, one value per converged point, in path.csv's
               order; the names carry their units ("depth_mm", "force_N", "k11_per_mm")
    units      dict column name -> unit ("mm", "N", "1/mm", "-")
    status     "completed", "reached_bound", "max_steps", "step_too_small",
               "stopped_by_callback", "start_failed" or "failed" (path.json's status)
    completed  True when the path reached its end
    reason     why it stopped early ("" when completed)
    method     "pseudo_arclength", "natural", "active_set" or "linear fast path"
    events     located events (force extrema, critical force, limit points ...), as events.json
    warnings   the model's warnings (also issued as Python warnings)
    """

    def __init__(self, raw):
        self.path = dict(raw["path"])
        self.units = dict(raw["units"])
        self.status = raw["status"]
        self.completed = bool(raw["completed"])
        self.reason = raw["reason"]
        self.method = raw["method"]
        self.events = json.loads(raw["events_json"])
        self.warnings = list(raw["warnings"])
        self._files = {"path.csv": raw["path_csv"], "path.json": raw["path_json"],
                       "events.json": raw["events_json"]}
        if raw["path_grid_csv"] is not None:
            self._files["path_grid.csv"] = raw["path_grid_csv"]

    def __getitem__(self, column):
        return self.path[column]

    def __len__(self):
        return len(next(iter(self.path.values()))) if self.path else 0

    def __repr__(self):
        return (f"<shellindent.Result {self.status}, {len(self)} points, "
                f"{self.method}>")

    def files(self):
        """The result files as `shellindent run` writes them: {file name: text}."""
        return dict(self._files)

    def write(self, directory):
        """Writes path.csv, path.json, events.json and (pseudo-arclength runs) path_grid.csv into
        `directory` (made if missing), each atomically (a temporary file renamed into place), as
        `shellindent run` writes them (docs/results.md); returns the paths written."""
        return [write_atomically(directory, name, text) for name, text in self._files.items()]


def run(case=None, progress=None, threads=0, checkpoint=None):
    """Runs the depth path of `case` (a Case, dict, file path or YAML text; None: the built-in
    default, the source paper's cap) and returns a Result.

    progress: called with each converged point (dict by column name); False stops the run.
    threads: assembly threads (0: OpenMP's default), as `shellindent run --threads`.
    checkpoint: a file for the continuation's checkpoints (continuation methods), written every
    10 points as the CLI's DIR/checkpoint.json: `shellindent run CASE --out DIR --resume`
    continues it when it is DIR/checkpoint.json and CASE the same case text. The solver's caches
    are dropped at each checkpoint, so the path equals the CLI's bit for bit (without: in the
    last bits, about 1e-11 relative).
    A bad case raises InputError before anything runs. A path that stops early (no convergence,
    stopped) is not an exception: see Result.status and Result.reason.
    """
    c = default_case() if case is None else read_case(case)
    _check_threads(threads)
    if progress is not None and not callable(progress):
        raise TypeError("progress must be callable")
    raw, stopped_by = _core.run_case(c, progress, threads,
                                     "" if checkpoint is None else os.fspath(checkpoint))
    result = Result(raw)
    for w in result.warnings:
        warnings.warn(w, RuntimeWarning, stacklevel=2)
    if stopped_by is not None:
        stopped_by.result = result
        raise stopped_by
    return result


def write_atomically(directory, name, text):
    """Writes `text` to directory/name through a temporary file renamed into place (the
    directory is made if missing); returns the path."""
    os.makedirs(directory, exist_ok=True)
    target = os.path.join(directory, name)
    fd, tmp = tempfile.mkstemp(dir=directory, prefix="." + name)
    with os.fdopen(fd, "w") as f:
        f.write(text)
    os.replace(tmp, target)
    return target


def _check_threads(threads):
    hardware = max(1, os.cpu_count() or 1)
    limit = THREADS_PER_CORE * hardware
    if isinstance(threads, bool) or not isinstance(threads, int) or not 0 <= threads <= limit:
        raise InputError(f"threads = '{threads}': expected 0 (OpenMP's default) to {limit} "
                         f"threads ({THREADS_PER_CORE} per hardware thread; this machine has "
                         f"{hardware})", key="threads", value=str(threads),
                         reason=f"expected 0 to {limit} threads")


def column_units():
    """path.csv's column names and their units, in order (docs/results.md)."""
    return dict(_core.column_units())


