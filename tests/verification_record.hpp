// Records the outcome of a verification check for the generated report (docs/verification.md,
// written by studies/verification.py). A test computes its value, asserts it as before, and in
// addition calls record_verification(...) with the same numbers: when the environment variable
// SHELLINDENT_VERIFICATION_RECORD names a file, one JSON object per check is appended to it (one
// line each); otherwise nothing happens. The record never replaces an EXPECT.
//
// Error convention: error = (measured - reference) / scale, compared as |error| <= tolerance, with
// scale = |reference| for a relative check (the default), 1 for an absolute one, or a quantity
// the reference states its tolerance in (e.g. "1 % of L", "in units of Pmax").
#pragma once

#include <string>

namespace si::test {

enum class ErrorScale { kRelative, kAbsolute, kCustom };

struct VerificationCheck {
  std::string table;     // table id in docs/verification.md (verification:begin <id>)
  std::string check;     // what is compared: quantity, case, mesh
  double reference = 0;  // the published value, closed form or other method's value
  double measured = 0;   // ours
  double tolerance = 0;  // allowed |error|, in the units of `scale`
  std::string source;    // where the reference comes from
  ErrorScale scale_kind = ErrorScale::kRelative;
  double scale = 1;        // used with ErrorScale::kCustom only
  std::string scale_name;  // what `scale` is ("L", "Pmax"), for the report
};

// Appends `c` (and the running test's name) to $SHELLINDENT_VERIFICATION_RECORD if it is set.
void record_verification(const VerificationCheck& c);

// Relative check: |measured / reference - 1| <= tolerance.
void record_verification(const std::string& table, const std::string& check, double reference,
                         double measured, double tolerance, const std::string& source);

// Absolute check: |measured - reference| <= tolerance.
void record_verification_absolute(const std::string& table, const std::string& check,
                                  double reference, double measured, double tolerance,
                                  const std::string& source);

// The error of `c` as defined above (what the report prints and compares with the tolerance).
double verification_error(const VerificationCheck& c);

}  // namespace si::test
