#include "bindings.hpp"
#include "core/blas_threads.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "shellindent's compiled core; use the package shellindent (docs/python.md)";
  m.attr("version") = SHELLINDENT_VERSION;
  // As the CLI's main: BLAS threads would compete with the assembly's OpenMP threads.
  si::limit_blas_threads();
  si::py::bind_errors(m);
  si::py::bind_case(m);
  si::py::bind_run(m);
  si::py::bind_section(m);
  si::py::bind_fit(m);
  si::py::bind_study(m);
  si::py::bind_calibrate(m);
}
