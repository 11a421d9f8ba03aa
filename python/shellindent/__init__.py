"""shellindent: static indentation of laminated composite shells by rigid indenters, from Python.

    import shellindent as si
    case = si.read_case({"material": "paper-carbon-epoxy",
                         "laminate": {"layup": "[0/90]2S", "ply_thickness": "0.475 mm"},
                         "mesh": {"symmetry": "full"}, "path": {"depth_max": "2 mm"}})
    result = si.run(case, progress=lambda p: print(p["depth_mm"], p["force_N"]))
    result["force_N"], result["depth_mm"]            # NumPy arrays, one value per point
    si.fit(result["depth_mm"][1:], result["force_N"][1:], "power")   # T = C1 h^C2
    si.section(case)["vam"]["A_R"]                    # 6x6 stiffness, Yu order
    si.calibrate(case, "test.csv", {"material.E3": "4:20 GPa"})   # fit case numbers to a curve

The module calls the same C++ as the `shellindent` command line: the same case-file reader (so
the same error messages, raised as InputError), the same path runs, the same result columns.
User's guide: docs/python.md.
"""

from ._core import version as __version__
from .calibrate import CalibrationResult, calibrate
from .case import Case, case_yaml, default_case, parse_case, read_case
from .errors import Error, InputError, InternalError, NumericalError
from .fit import MODELS as FIT_MODELS
from .fit import fit
from .run import Result, column_units, run
from .section import section
from .sweep import SweepResult, sweep

__all__ = [
    "CalibrationResult", "Case", "Error", "FIT_MODELS", "InputError", "InternalError",
    "NumericalError", "Result", "SweepResult", "calibrate", "case_yaml", "column_units",
    "default_case", "fit", "parse_case", "read_case", "run", "section", "sweep",
]
