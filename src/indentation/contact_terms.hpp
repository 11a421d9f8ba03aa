// The registry of the indentation problem's contact parts (contact_term.hpp): which terms a
// problem's options ask for, built and wired to each other. Adding a part (a support frame, a
// friction law) is its own file and a few lines here.
#pragma once

#include <memory>
#include <vector>

#include "indentation/contact_rows.hpp"
#include "indentation/indentation_options.hpp"

namespace si {

struct ContactParts {
  ContactRows* indenter = nullptr;  // the rows of the indenter's contact (one of `terms`)
  std::vector<std::unique_ptr<ContactTerm>> terms;  // in the order of their unknowns in z
};

// The indenter's contact rows (nodal or weighted gaps) and its local law (a power law's alpha or
// a thin layer), with the reachable nodes as the first candidates.
ContactParts make_contact_parts(const IndentationOptions& options,
                                const ContactRowsSetting& setting);

}  // namespace si
