// Study files (io/study_file.hpp): setting dotted keys in the base YAML, product and zip
// expansion, the quick keys, and bad keys refused with the study file and key named.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "io/study_file.hpp"
#include "test_paths.hpp"

namespace si {
namespace {

const std::string kStudies = std::string(SHELLINDENT_SOURCE_DIR) + "/studies";

StudyFile study(const std::string& body) {
  return parse_study_file("base: paper_cap.yaml\n" + body, "s.yaml", kStudies);
}

// The message of the input error thrown by `f`, or "" if none.
template <class F>
std::string input_error(F f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    return e.what();
  }
  return "";
}

TEST(StudyFile, SetDottedKeyReplacesNestedValuesAndCreatesMissingMaps) {
  YAML::Node root = YAML::Load("mesh: {size_apex: 0.5 mm}\nkinematics: nonlinear\n");
  set_dotted_key(root, "mesh.size_apex", YAML::Load("2 mm"), Where{});
  set_dotted_key(root, "load.force", YAML::Load("10 N"), Where{});
  EXPECT_EQ(root["mesh"]["size_apex"].as<std::string>(), "2 mm");
  EXPECT_EQ(root["load"]["force"].as<std::string>(), "10 N");
  EXPECT_EQ(root["kinematics"].as<std::string>(), "nonlinear");
}

TEST(StudyFile, SetDottedKeyThroughAScalarIsAnInputError) {
  YAML::Node root = YAML::Load("kinematics: nonlinear\n");
  const std::string m = input_error([&] {
    set_dotted_key(root, "kinematics.order", YAML::Load("2"),
                   Where{"s.yaml", "vary.kinematics", "", 0});
  });
  EXPECT_NE(m.find("s.yaml"), std::string::npos) << m;
  EXPECT_NE(m.find("not a map"), std::string::npos) << m;
}

TEST(StudyFile, ProductTakesTheFirstKeySlowestAndEachCaseIsReadByTheCaseFileReader) {
  const auto cases = expand_study(study("vary:\n  laminate.layup: [\"[0/0]2S\", \"[0/90]2S\"]\n"
                                        "  indenter.radius: [5 mm, 12.7 mm, 20 mm]\n"),
                                  false);
  ASSERT_EQ(cases.size(), 6u);
  EXPECT_EQ(cases[0].values[0].second, "[0/0]2S");
  EXPECT_EQ(cases[2].values[1].second, "20 mm");
  EXPECT_EQ(cases[3].values[0].second, "[0/90]2S");
  EXPECT_DOUBLE_EQ(cases[1].case_file.indenter.radius, 12.7);
  EXPECT_DOUBLE_EQ(cases[5].case_file.indenter.radius, 20.0);
  EXPECT_EQ(cases[4].case_file.laminate.plies[1].angle_deg, 90.0);
  EXPECT_EQ(cases[4].slug, "005_0_90_2S_12.7_mm");
  EXPECT_EQ(cases[4].label, "s.yaml case 5 (laminate.layup = [0/90]2S, indenter.radius = 12.7 mm)");
  EXPECT_DOUBLE_EQ(cases[0].case_file.mesh.size_apex, 0.5);  // from the base
}

TEST(StudyFile, ZipPairsTheListsAndRefusesUnequalLengths) {
  const auto cases = expand_study(study("combine: zip\nvary:\n  indenter.radius: [5 mm, 10 mm]\n"
                                        "  path.depth_max: [1 mm, 2 mm]\n"),
                                  false);
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_DOUBLE_EQ(cases[1].case_file.indenter.radius, 10.0);
  EXPECT_DOUBLE_EQ(cases[1].case_file.path.depth_max, 2.0);
  const std::string m = input_error([] {
    expand_study(study("combine: zip\nvary:\n  indenter.radius: [5 mm, 10 mm]\n"
                       "  path.depth_max: [1 mm]\n"),
                 false);
  });
  EXPECT_NE(m.find("vary.path.depth_max"), std::string::npos) << m;
}

TEST(StudyFile, QuickKeysOverrideTheVariedOnesOnlyWhenAsked) {
  const StudyFile s = study(
      "vary:\n  mesh.size_apex: [1 mm]\nquick: {mesh.size_apex: 2 mm, path.depth_max: 1 mm}\n");
  EXPECT_DOUBLE_EQ(expand_study(s, false)[0].case_file.mesh.size_apex, 1.0);
  EXPECT_DOUBLE_EQ(expand_study(s, true)[0].case_file.mesh.size_apex, 2.0);
  EXPECT_DOUBLE_EQ(expand_study(s, true)[0].case_file.path.depth_max, 1.0);
  EXPECT_EQ(expand_study(s, true)[0].values[0].second, "2 mm");  // the value that was run
}

TEST(StudyFile, UnknownDottedKeyNamesTheStudyAndTheKey) {
  const std::string m =
      input_error([] { expand_study(study("vary:\n  laminate.layupp: [\"[0/0]2S\"]\n"), false); });
  EXPECT_NE(m.find("s.yaml case 1"), std::string::npos) << m;
  EXPECT_NE(m.find("laminate.layupp"), std::string::npos) << m;
}

TEST(StudyFile, BadValueNamesTheCase) {
  const std::string m =
      input_error([] { expand_study(study("vary:\n  indenter.radius: [5 mm, -1 mm]\n"), false); });
  EXPECT_NE(m.find("s.yaml case 2 (indenter.radius = -1 mm)"), std::string::npos) << m;
}

TEST(StudyFile, BadStudyKeysAreRefused) {
  EXPECT_NE(input_error([] { study("vary: {}\n"); }).find("nothing to vary"), std::string::npos);
  EXPECT_NE(input_error([] { study("vary: {mesh.size_apex: 1 mm}\n"); }).find("list"),
            std::string::npos);
  EXPECT_NE(input_error([] {
              study("vary: {mesh.size_apex: [1 mm]}\ncombine: cross\n");
            }).find("combine"),
            std::string::npos);
  EXPECT_NE(input_error([] {
              study("vary: {mesh.size_apex: [1 mm]}\nfit: {model: cubic}\n");
            }).find("fit.model"),
            std::string::npos);
  EXPECT_NE(input_error([] {
              parse_study_file("base: nowhere.yaml\nvary: {a: [1]}\n", "s.yaml", kStudies);
            }).find("base case file"),
            std::string::npos);
}

}  // namespace
}  // namespace si
