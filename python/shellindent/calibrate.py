"""Calibration of a case against a measured force-travel curve: shellindent.calibrate().

calibrate() calls the same C++ as `shellindent calibrate` (io/case_calibration): the parameters
are case-file keys with bounds ("material.E3": "4:20 GPa"), each evaluation a run of the case at
the measured travels, NLopt's search, then the Jacobian at the optimum, standard errors, 95 %
intervals, correlations and the identifiability warnings (docs/calibration.md). Bad input raises
InputError with the CLI's text; the report is the CLI's calibration.json, parsed.

The GIL is released during the runs. Ctrl-C (KeyboardInterrupt) or an exception of the progress
function stops the calibration with the best point so far (status "interrupted"); the exception
is raised again with that result as its attribute `result`.
"""

import json
import os

import numpy as np

from . import _core
from .case import parse_case, read_case
from .run import write_atomically


class CalibrationResult:
    """The outcome of calibrate(), read from the CLI's report (calibration.json).

    status       "converged", "budget_exhausted", "interrupted" or "failed"; converged: bool
    reason       why it ended so ("" when converged)
    names        the parameters' keys, in the order given
    parameters   dict key -> optimum (internal units: MPa, mm; `units` says which)
    start        dict key -> start value
    std_errors   dict key -> standard error (None without statistics)
    intervals    dict key -> (low, high), the 95 % t interval (None without statistics)
    correlation  p x p array in `names` order (NaN without statistics)
    warnings     the identifiability warnings' messages (empty: the data separate the parameters)
    curve        dict of arrays: travel_mm, measured_force_N, fitted_force_N, residual_N
    report       calibration.json as a dict (every statistic: covariance, confidence region,
                 singular values, NLopt's code, evaluation counts ...)
    table        the table `shellindent calibrate` prints
    case         the calibrated case (a Case), or None when no optimum was found
    """

    def __init__(self, raw):
        self.report = json.loads(raw["calibration_json"])
        self.table = raw["table"]
        self.notes = raw["notes"]
        self._files = {"calibration.json": raw["calibration_json"],
                       "calibration_curve.csv": raw["calibration_curve_csv"]}
        yaml = raw["calibrated_case_yaml"]
        self.case = None
        if yaml is not None:
            self._files["calibrated_case.yaml"] = yaml
            self.case = parse_case(yaml, "calibrated_case.yaml")
        r = self.report
        self.status = r["status"]
        self.reason = r["reason"]
        self.converged = self.status == "converged"
        params = r["parameters"]
        self.names = [p["key"] for p in params]
        self.units = {p["key"]: p["unit"] for p in params}
        self.parameters = {p["key"]: p["value"] for p in params}
        self.start = {p["key"]: p["start"] for p in params}
        self.std_errors = {p["key"]: p["std_error"] for p in params}
        self.intervals = {p["key"]: (None if p["ci_low"] is None else (p["ci_low"], p["ci_high"]))
                          for p in params}
        self.correlation = _matrix(r["correlation"], len(params))
        self.warnings = [w["message"] for w in r["identifiability"]["warnings"]]
        self.curve = _curve(raw["calibration_curve_csv"])

    def __repr__(self):
        values = ", ".join(f"{k} = {v:.6g} {self.units[k]}" if v is not None else f"{k} = None"
                           for k, v in self.parameters.items())
        return f"<shellindent.CalibrationResult {self.status}: {values}>"

    def files(self):
        """The files `shellindent calibrate` writes: {file name: text}."""
        return dict(self._files)

    def write(self, directory):
        """Writes calibration.json, calibration_curve.csv and calibrated_case.yaml into
        `directory` (made if missing) as `shellindent calibrate --out` does; returns the paths."""
        return [write_atomically(directory, name, text) for name, text in self._files.items()]


def _matrix(rows, n):
    if not rows:
        return np.full((n, n), np.nan)
    return np.array([[np.nan if v is None else v for v in row] for row in rows], dtype=float)


def _curve(csv):
    lines = [line.split(",") for line in csv.strip().splitlines()]
    header, rows = lines[0], lines[1:]
    return {name: np.array([float(row[j]) if row[j] else np.nan for row in rows])
            for j, name in enumerate(header)}


def _param_texts(params):
    """{"material.E3": "4:20 GPa" | ("4 GPa", "20 GPa"[, start])} or ["material.E3=4:20GPa"]
    -> the CLI's --param texts."""
    if isinstance(params, str):
        return [params]
    if isinstance(params, dict):
        texts = []
        for key, bounds in params.items():
            if isinstance(bounds, (tuple, list)):
                bounds = ":".join(str(b) for b in bounds)
            texts.append(f"{key}={bounds}")
        return texts
    return [str(p) for p in params]


def calibrate(case, data, params, x=None, y=None, algorithm="bobyqa", max_evaluations=100,
              xtol=1e-4, threads=1, jobs=1, warm_start=True, progress=None):
    """Calibrates numbers of `case` (a Case, dict, file path or YAML text) so that its force at
    the measured travels matches `data`, as `shellindent calibrate` does; returns a
    CalibrationResult.

    data: a CSV file (units in the header, as --data; x, y choose its columns as --x, --y), or
          a pair (travel_mm, force_N) of sequences in mm and N.
    params: {key: "LO:HI[:START]"} or {key: (LO, HI[, START])} with units ("4 GPa", or numbers
          in the unit written to their right: "4:20 GPa"), or a list of "KEY=LO:HI[:START]".
    algorithm, max_evaluations, xtol, threads, jobs, warm_start: as the CLI's --algorithm,
          --max-evaluations, --xtol, --threads, -j, --no-warm-start.
    progress: called after every evaluation with a dict (evaluation, phase, parameters, ok,
          sse, best_sse, seconds, failure, and line: the CLI's progress line); False stops.
    Bad input raises InputError with the CLI's message before anything runs.
    """
    c = read_case(case)
    if progress is not None and not callable(progress):
        raise TypeError("progress must be callable")
    texts = _param_texts(params)
    settings = (algorithm, int(max_evaluations), float(xtol), int(threads), int(jobs),
                bool(warm_start), progress)
    if isinstance(data, (str, os.PathLike)):
        raw, stopped_by = _core.calibrate_file(c, os.fspath(data), x or "", y or "", texts,
                                               *settings)
    else:
        travel, force = data
        raw, stopped_by = _core.calibrate_arrays(
            c, "<data>", [float(v) for v in np.asarray(travel, dtype=float).ravel()],
            [float(v) for v in np.asarray(force, dtype=float).ravel()], texts, *settings)
    result = CalibrationResult(raw)
    if stopped_by is not None:
        stopped_by.result = result
        raise stopped_by
    return result
