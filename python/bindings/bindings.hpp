// The compiled part of the Python module shellindent (shellindent._core). Thin on purpose: each
// function calls the C++ the CLI calls (io/ reads the case, analysis/ runs it, io/ formats the
// results) and converts between C++ and Python values; the Python package (../shellindent/)
// adds the conveniences. docs/python.md is the user's guide.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "io/case_file.hpp"

namespace si::py {

namespace py = pybind11;

// A case as read, with the text it was read from: errors found after reading (mesh, model,
// indenter placement) are located in that text as the CLI locates them (io/case_key_location).
struct CaseHandle {
  CaseFile file;
  std::string text;
};

// si::Error -> shellindent.errors.InputError / NumericalError / InternalError.
void bind_errors(py::module_& m);
// Case, read_case, parse_case, default_case.
void bind_case(py::module_& m);
// run_case: the path of a case with a progress callback; the GIL released during the solve.
void bind_run(py::module_& m);
// section: the section properties of a case's laminate (CLT ABD, VAM A_R, shear stiffness).
void bind_section(py::module_& m);
// read_study, Study, case_state, source_fingerprint: parameter studies for the Python sweep.
void bind_study(py::module_& m);
// fit_curve: the curve fits of fitting/ (power law, Hertz, power law with offset).
void bind_fit(py::module_& m);
// calibrate_file, calibrate_arrays: a case calibrated against a measured force-travel curve.
void bind_calibrate(py::module_& m);

}  // namespace si::py
