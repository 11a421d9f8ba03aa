// Reading a case: the same reader as `shellindent run` (io/case_file), so the errors are the same.
#include <fstream>
#include <sstream>

#include "bindings.hpp"
#include "io/default_case.hpp"

namespace si::py {
namespace {

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

void bind_case(py::module_& m) {
  py::class_<CaseHandle>(m, "Case", "A case read and validated by the case-file reader")
      .def_property_readonly("label", [](const CaseHandle& c) { return c.file.file; })
      .def_property_readonly("yaml", [](const CaseHandle& c) { return c.text; })
      .def_property_readonly("depth_max_mm",
                             [](const CaseHandle& c) { return c.file.path.depth_max; });
  m.def(
      "read_case",
      [](const std::string& path) {
        CaseFile file = read_case_file(path);  // first: its errors for a missing file
        return CaseHandle{std::move(file), file_text(path)};
      },
      py::arg("path"));
  m.def(
      "parse_case",
      [](const std::string& text, const std::string& label) {
        return CaseHandle{parse_case_file(text, label), text};
      },
      py::arg("text"), py::arg("label"));
  m.def("default_case", [] {
    const std::string text = default_case_yaml();
    return CaseHandle{parse_case_file(text, kDefaultCaseLabel), text};
  });
}

}  // namespace si::py
