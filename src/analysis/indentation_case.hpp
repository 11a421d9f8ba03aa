// Everything an indentation run is built from: the shell model's spec (laminate, shell, mesh,
// kinematics), the indenter, the contact and the path. io/case_file.hpp reads a case file into
// it (CaseFile extends it with the output settings); the runs take nothing else.
#pragma once

#include <optional>
#include <vector>

#include "analysis/contact_spec.hpp"
#include "analysis/damage_spec.hpp"
#include "analysis/path_spec.hpp"
#include "contact/indenter_spec.hpp"
#include "model/shell_model.hpp"

namespace si {

struct IndentationCase : ShellModelSpec {
  IndenterSpec indenter;
  ContactSpec contact;
  PathSpec path;
  std::optional<DamageSpec> damage;  // the `damage:` section; none: no damage output at all
};

// The criteria whose failure indices the run monitors (the `damage:` section's; their columns are
// the run's).
std::vector<Criterion> monitored_criteria(const IndentationCase& c);

// The contact face offset of a case: the laminate's top face (contact.surface: outer) or its
// mid-surface (contact.surface: mid, the paper's choice), measured from the reference surface.
double contact_face_offset(const IndentationCase& c);
// The offset of the laminate's bottom face (x3 = -t/2, the face on a support frame) from the
// reference surface.
double back_face_offset(const IndentationCase& c);

}  // namespace si
