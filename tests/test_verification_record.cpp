// The verification recorder (verification_record.hpp): one JSON line per check when
// SHELLINDENT_VERIFICATION_RECORD is set.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "verification_record.hpp"

namespace si::test {
namespace {

constexpr const char* kVariable = "SHELLINDENT_VERIFICATION_RECORD";

// Points the recorder at `path` for the lifetime of the object and restores the previous value
// (the study runs this binary with the variable set).
class RecordTarget {
 public:
  explicit RecordTarget(const std::optional<std::string>& path) {
    if (const char* old = std::getenv(kVariable)) previous_ = old;
    if (path) {
      setenv(kVariable, path->c_str(), 1);
    } else {
      unsetenv(kVariable);
    }
  }
  ~RecordTarget() {
    if (previous_) {
      setenv(kVariable, previous_->c_str(), 1);
    } else {
      unsetenv(kVariable);
    }
  }
  RecordTarget(const RecordTarget&) = delete;
  RecordTarget& operator=(const RecordTarget&) = delete;

 private:
  std::optional<std::string> previous_;
};

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::filesystem::path scratch_file(const std::string& name) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("shellindent_" + name + "_" + std::to_string(::getpid()) + ".jsonl");
  std::filesystem::remove(path);
  return path;
}

TEST(VerificationRecord, AppendsOneJsonLinePerCheckWithTheTestName) {
  const auto path = scratch_file("record");
  {
    const RecordTarget target(path.string());
    record_verification("t1", "a \"quoted\" check", 2.0, 2.01, 0.01, "closed form");
    record_verification_absolute("t1", "second", 1.0, 0.5, 0.25, "exact");
  }
  const std::string text = read_all(path);
  std::filesystem::remove(path);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 2);
  EXPECT_NE(text.find("\"check\": \"a \\\"quoted\\\" check\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"scale_kind\": \"absolute\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"error\": -0.5,"), std::string::npos) << text;
  EXPECT_NE(text.find("\"test\": \"VerificationRecord.AppendsOneJsonLinePerCheckWithTheTestName\""),
            std::string::npos)
      << text;
}

TEST(VerificationRecord, ErrorIsRelativeAbsoluteOrInUnitsOfTheGivenScale) {
  EXPECT_DOUBLE_EQ(
      verification_error({"t", "c", -4.0, -5.0, 0, "s", ErrorScale::kRelative, 1.0, ""}), -0.25);
  EXPECT_DOUBLE_EQ(verification_error({"t", "c", 4.0, 5.0, 0, "s", ErrorScale::kAbsolute, 1.0, ""}),
                   1.0);
  EXPECT_DOUBLE_EQ(verification_error({"t", "c", 4.0, 5.0, 0, "s", ErrorScale::kCustom, 10.0, "L"}),
                   0.1);
}

}  // namespace
}  // namespace si::test
