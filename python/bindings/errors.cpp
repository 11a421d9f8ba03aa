// An si::Error becomes the Python exception of its kind (shellindent/errors.py) with the CLI's
// message as its text and the file, line, key, value and reason as attributes.
#include "core/error.hpp"

#include "bindings.hpp"

namespace si::py {
namespace {

const char* exception_class(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::kInput:
      return "InputError";
    case ErrorKind::kNumerical:
      return "NumericalError";
    case ErrorKind::kInternal:
      break;
  }
  return "InternalError";
}

py::object or_none(const std::string& s) {
  return s.empty() ? py::object(py::none()) : py::object(py::str(s));
}

}  // namespace

void bind_errors(py::module_&) {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Error& e) {
      const Where& w = e.where();
      const py::object cls =
          py::module_::import("shellindent.errors").attr(exception_class(e.kind()));
      const py::object exc =
          cls(e.what(), py::arg("file") = or_none(w.file),
              py::arg("line") = w.line > 0 ? py::object(py::int_(w.line)) : py::none(),
              py::arg("key") = or_none(w.key), py::arg("value") = or_none(w.value),
              py::arg("reason") = e.reason());
      PyErr_SetObject(cls.ptr(), exc.ptr());
    }
  });
}

}  // namespace si::py
