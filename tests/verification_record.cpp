// JSON-lines recorder of verification checks (see verification_record.hpp).
#include "verification_record.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace si::test {
namespace {

// JSON string literal of `s` (RFC 8259: quote, backslash and control characters escaped).
std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
      out += buffer;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

// Round-trip representation; non-finite values become null (JSON has no NaN), which the report
// treats as a failed check.
std::string json_number(double x) {
  if (!std::isfinite(x)) return "null";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

const char* scale_kind_name(ErrorScale kind) {
  switch (kind) {
    case ErrorScale::kRelative:
      return "relative";
    case ErrorScale::kAbsolute:
      return "absolute";
    case ErrorScale::kCustom:
      return "custom";
  }
  return "unknown";
}

std::string current_test_name() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  if (info == nullptr) return "";
  return std::string(info->test_suite_name()) + "." + info->name();
}

}  // namespace

double verification_error(const VerificationCheck& c) {
  const double difference = c.measured - c.reference;
  switch (c.scale_kind) {
    case ErrorScale::kRelative:
      return difference / std::abs(c.reference);
    case ErrorScale::kAbsolute:
      return difference;
    case ErrorScale::kCustom:
      return difference / c.scale;
  }
  return difference;
}

void record_verification(const VerificationCheck& c) {
  const char* path = std::getenv("SHELLINDENT_VERIFICATION_RECORD");
  if (path == nullptr || *path == '\0') return;
  std::ostringstream line;
  line << "{\"table\": " << json_string(c.table) << ", \"check\": " << json_string(c.check)
       << ", \"reference\": " << json_number(c.reference)
       << ", \"measured\": " << json_number(c.measured)
       << ", \"error\": " << json_number(verification_error(c))
       << ", \"tolerance\": " << json_number(c.tolerance)
       << ", \"scale_kind\": " << json_string(scale_kind_name(c.scale_kind))
       << ", \"scale\": " << json_number(c.scale_kind == ErrorScale::kCustom ? c.scale : 1.0)
       << ", \"scale_name\": " << json_string(c.scale_name)
       << ", \"source\": " << json_string(c.source)
       << ", \"test\": " << json_string(current_test_name()) << "}\n";
  // One write of the whole line in append mode: records of consecutive tests never interleave.
  std::ofstream file(path, std::ios::app);
  file << line.str();
  EXPECT_TRUE(file.good()) << "cannot append to SHELLINDENT_VERIFICATION_RECORD=" << path;
}

void record_verification(const std::string& table, const std::string& check, double reference,
                         double measured, double tolerance, const std::string& source) {
  record_verification(
      {table, check, reference, measured, tolerance, source, ErrorScale::kRelative, 1.0, ""});
}

void record_verification_absolute(const std::string& table, const std::string& check,
                                  double reference, double measured, double tolerance,
                                  const std::string& source) {
  record_verification(
      {table, check, reference, measured, tolerance, source, ErrorScale::kAbsolute, 1.0, ""});
}

}  // namespace si::test
