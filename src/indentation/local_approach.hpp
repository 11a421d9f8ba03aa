// The local (through-thickness) approach of the indenter towards the shell's contact face, as
// the contact rows see it (contact/local_contact_law.hpp, docs/theory/local-indentation.md):
// candidate i's gap is taken at its face depth h - u_i(alpha), the face dented by a power law's
// Hertz profile (power_law_approach.hpp), and gains c_i lambda_i, a thin layer's compliance
// (thin_layer.hpp). Without a local law (the default here) neither.
#pragma once

#include "contact/hertz_dent.hpp"
#include "continuation/problem.hpp"

namespace si {

class LocalApproach {
 public:
  virtual ~LocalApproach() = default;
  // The dent of the face at mesh node `node` and its rate d/dalpha.
  virtual DentValue dent(int, const cont::Vector&) const { return {}; }
  // The approach at mesh node `node` carried by the multiplier `lambda` (N), mm.
  virtual double layer(int, double) const { return 0.0; }
  // The position of alpha in z (the dent's column in the contact rows), -1 without one.
  virtual int alpha_index() const { return -1; }
  // A power law's start is regular only at the kink of the NCP function: a gap within
  // roundoff of zero then takes the touch's derivatives (ContactRows::complementarity).
  virtual bool regularizes_touch() const { return false; }
};

}  // namespace si
