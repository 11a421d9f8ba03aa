// The registry of the indentation problem's contact parts (contact_term.hpp): which terms a
// problem's options ask for, built and wired to each other. Adding a part (a support frame, a
// friction law) is its own file and a few lines here.
#pragma once

#include <memory>
#include <vector>

#include "indentation/contact_rows.hpp"
#include "indentation/indentation_options.hpp"
#include "indentation/support_frame.hpp"

namespace si {

struct ContactParts {
  ContactRows* indenter = nullptr;  // the rows of the indenter's contact (one of `terms`)
  SupportFrame* frame = nullptr;    // the support frame's rows, if the model rests on one
  std::vector<std::unique_ptr<ContactTerm>> terms;  // in the order of their unknowns in z
};

// The support frame's rows if the model has frame nodes (ShellModel::frame_nodes; first in z, so
// that the indenter's candidates, which grow, stay at the end of the Krylov solver's rows), the
// indenter's contact rows (nodal or weighted gaps) and its local law (a power law's alpha or a
// thin layer), with the reachable nodes as the first candidates.
ContactParts make_contact_parts(const IndentationOptions& options,
                                const ContactRowsSetting& setting);

}  // namespace si
