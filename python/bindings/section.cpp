// Section properties of a case's laminate, as `shellindent section CASE --json` writes them.
#include "bindings.hpp"
#include "io/section_report.hpp"
#include "section/layup_notation.hpp"
#include "section/section_properties.hpp"

namespace si::py {

void bind_section(py::module_& m) {
  m.def(
      "section_json",
      [](const CaseHandle& c, int vam_order) {
        if (vam_order < 2 || vam_order > 8)
          throw_input("VAM element order must be between 2 and 8",
                      Where{"", "vam_order", std::to_string(vam_order), 0});
        const Laminate& lam = c.file.laminate;
        py::gil_scoped_release nogil;
        return section_to_json(
                   analyze_section(lam, describe_laminate(lam), VamOptions{vam_order, 1}))
            .dump();
      },
      py::arg("case"), py::arg("vam_order") = 4);
}

}  // namespace si::py
