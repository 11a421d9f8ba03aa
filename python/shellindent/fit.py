"""Curve fits of the fitting library (docs/fitting.md): the contact law T = C1 h^C2 and its kin.

fit(x, y, model="power") -> dict with status ("converged", "stalled", "failed"), reason, method,
names, parameters, std_errors, ci_lower, ci_upper (95 %), covariance, r_squared, rmse,
residuals and fitted, as `shellindent fit` reports them. Models:
  power         y = C1 x^C2 (least squares in y)
  power-log     ln y = ln C1 + C2 ln x (points with x, y > 0 only)
  hertz         y = C x^1.5
  power-offset  y = C1 x^C2 + C0
"""

import numpy as np

from . import _core

MODELS = tuple(_core.fit_models)


def fit(x, y, model="power"):
    """Fits `model` to the points (x, y); bad input raises InputError."""
    x = np.asarray(x, dtype=float).ravel()
    y = np.asarray(y, dtype=float).ravel()
    return dict(_core.fit_curve(model, x, y))
