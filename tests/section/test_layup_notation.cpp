#include "section/layup_notation.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace si {
namespace {

using Angles = std::vector<double>;

struct Example {
  const char* notation;
  Angles expected;
};

TEST(LayupNotation, ExpandsTheDocumentedExamples) {
  const std::vector<Example> examples{
      // The source paper's notation: repeat the group twice, then mirror.
      {"[45/-45]2S", {45, -45, 45, -45, -45, 45, -45, 45}},
      {"[0/90]2S", {0, 90, 0, 90, 90, 0, 90, 0}},
      {"[0_2/90_2]S", {0, 0, 90, 90, 90, 90, 0, 0}},
      {"[0/±45/90]s", {0, 45, -45, 90, 90, -45, 45, 0}},
      {"[0/+-45/90]S", {0, 45, -45, 90, 90, -45, 45, 0}},
      {"[0/-+45/90]S", {0, -45, 45, 90, 90, 45, -45, 0}},
      {"[0/∓45/90]S", {0, -45, 45, 90, 90, 45, -45, 0}},
      {"[0/90]", {0, 90}},
      {"[0/90]3", {0, 90, 0, 90, 0, 90}},
      {"[0/90]_3", {0, 90, 0, 90, 0, 90}},
      {"[0/90]T", {0, 90}},
      {"[(0/90)_2/45]S", {0, 90, 0, 90, 45, 45, 90, 0, 90, 0}},
      {"[0/(±45)2/90]S", {0, 45, -45, 45, -45, 90, 90, -45, 45, -45, 45, 0}},
      {"[((0/90)2/30)_2]", {0, 90, 0, 90, 30, 0, 90, 0, 90, 30}},
      {"[22.5/-67.5/+15]", {22.5, -67.5, 15}},
      {"[ 0 / 90 ] 2 S", {0, 90, 0, 90, 90, 0, 90, 0}},
      {"[.5/-0.25]", {0.5, -0.25}},
      {"[0/90_h]S", {0, 90, 0}},
      {"[45/-45/0_h]S", {45, -45, 0, -45, 45}},
      {"[360/-360]", {360, -360}},
      {"[30]", {30}},
  };
  for (const auto& ex : examples) EXPECT_EQ(parse_layup(ex.notation), ex.expected) << ex.notation;
}

// Source paper, Results: [theta/-theta]2S for theta = 0, 15, ..., 90, eight plies each.
TEST(LayupNotation, PaperThetaMinusThetaTwoSymmetric) {
  for (int theta = 0; theta <= 90; theta += 15) {
    const std::string text = "[" + std::to_string(theta) + "/-" + std::to_string(theta) + "]2S";
    const double t = theta;
    EXPECT_EQ(parse_layup(text), (Angles{t, -t, t, -t, -t, t, -t, t})) << text;
  }
  EXPECT_EQ(parse_layup("[0/90]2S").size(), 8u);
}

TEST(LayupNotation, FormatsCompactly) {
  EXPECT_EQ(format_layup({45, -45, 45, -45, -45, 45, -45, 45}), "[±45]2S");
  EXPECT_EQ(format_layup({0, 90, 0, 90, 90, 0, 90, 0}), "[0/90]2S");
  EXPECT_EQ(format_layup({0, 0, 90, 90, 90, 90, 0, 0}), "[0_2/90_2]S");
  EXPECT_EQ(format_layup({0, 90, 0, 90, 0, 90}), "[0/90]3");
  EXPECT_EQ(format_layup({0, 0, 0, 0}), "[0_4]");
  EXPECT_EQ(format_layup({0, 30, 60}), "[0/30/60]");
  EXPECT_EQ(format_layup({22.5}), "[22.5]");
  EXPECT_EQ(format_layup({45, -45, 0, -45, 45}), "[±45/0_h]S");
}

void expect_round_trip(const Angles& angles) {
  const std::string text = format_layup(angles);
  EXPECT_EQ(parse_layup(text), angles) << text;
}

TEST(LayupNotation, RoundTripsRandomLists) {
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> any_angle(-360.0, 360.0);
  std::uniform_int_distribution<int> common_angle(-6, 6);  // multiples of 15 deg: runs, ± pairs
  std::uniform_int_distribution<int> length(1, 24);
  for (int trial = 0; trial < 500; ++trial) {
    const int n = length(rng);
    Angles angles;
    for (int i = 0; i < n; ++i)
      angles.push_back(trial % 2 == 0 ? any_angle(rng) : 15.0 * common_angle(rng));
    expect_round_trip(angles);

    Angles symmetric = angles;  // even symmetric stack
    symmetric.insert(symmetric.end(), angles.rbegin(), angles.rend());
    expect_round_trip(symmetric);

    Angles odd = angles;  // odd symmetric stack with a mid-plane ply
    odd.insert(odd.end(), angles.rbegin() + 1, angles.rend());
    expect_round_trip(odd);

    Angles repeated;
    for (int k = 0; k < 3; ++k) repeated.insert(repeated.end(), angles.begin(), angles.end());
    expect_round_trip(repeated);
  }
}

TEST(LayupNotation, RoundTripsRunsAndAwkwardNumbers) {
  expect_round_trip({0, 0, 0, 90, 90, 45, 45, 45, 45});
  expect_round_trip({45, -45, -45, 45});
  expect_round_trip({45, 45, -45, -45});
  expect_round_trip({-0.0, 0.0});
  expect_round_trip({1e-7, 0.1, 1.0 / 3.0, -359.99999999999994, 360});
  expect_round_trip({100, 200, 300});
}

// Issue 13 item 4: the compact form of a long run or a large repetition must parse back. It
// printed "[0_2000]" for "[0_1000]2" and "[0_6380]S" for "[0_0290]22S", counts the parser
// refuses (above 1000); such counts are now written as nested groups.
TEST(LayupNotation, CompactFormOfLongRunsAndRepetitionsParsesBack) {
  for (const char* notation : {"[0_1000]2", "[0_0290]22S", "[0/90]1000", "[(0/90)1000]3",
                               "[0_999/45_1000]2S", "[(0_1000)100]", "[(±45)1000]S"}) {
    const Angles angles = parse_layup(notation);
    const std::string compact = format_layup(angles);
    try {
      EXPECT_EQ(parse_layup(compact), angles) << notation << " -> " << compact;
    } catch (const Error& e) {
      ADD_FAILURE() << notation << " -> " << compact << " refused: " << e.what();
    }
  }
  EXPECT_EQ(format_layup(parse_layup("[0_1000]2")), "[0_1000]S");
}

// Random long runs and repetitions around the count limit, up to the parser's 100,000 plies.
TEST(LayupNotation, RoundTripsLongRunsAndRepetitions) {
  std::mt19937 rng(13);
  std::uniform_int_distribution<int> run(1, 2500);
  std::uniform_int_distribution<int> angle(-2, 2);
  std::uniform_int_distribution<int> parts(1, 4);
  std::uniform_int_distribution<int> times(1, 30);
  for (int trial = 0; trial < 100; ++trial) {
    Angles base;
    for (int p = parts(rng); p > 0; --p) base.insert(base.end(), run(rng), 45.0 * angle(rng));
    Angles angles;
    for (int k = times(rng); k > 0 && angles.size() + base.size() <= 50000; --k)
      angles.insert(angles.end(), base.begin(), base.end());
    expect_round_trip(angles);
    Angles symmetric = angles;
    symmetric.insert(symmetric.end(), angles.rbegin(), angles.rend());
    expect_round_trip(symmetric);
  }
}

// Issue 13 item 1: nesting is bounded (the parser is recursive; 30,000 levels overflowed the
// stack of a Release build, 3,476 under AddressSanitizer).
TEST(LayupNotation, RefusesGroupsNestedTooDeep) {
  const auto nested = [](int levels) {
    return "[" + std::string(levels, '(') + "0" + std::string(levels, ')') + "]";
  };
  EXPECT_EQ(parse_layup(nested(64)), Angles{0});
  for (int levels : {65, 4000, 200000}) {
    try {
      parse_layup(nested(levels));
      ADD_FAILURE() << levels << " levels accepted";
    } catch (const Error& e) {
      EXPECT_NE(e.reason().find("groups nested deeper than 64 levels at character 66"),
                std::string::npos)
          << e.reason().substr(0, 300);
      EXPECT_LT(e.reason().size(), 200u);  // the string is quoted by its first 80 characters
    }
  }
}

TEST(LayupNotation, FormatRefusesWhatItCannotWrite) {
  EXPECT_THROW(format_layup({}), Error);
  EXPECT_THROW(format_layup({400}), Error);
  EXPECT_THROW(format_layup({std::nan("")}), Error);
}

struct Malformed {
  const char* notation;
  const char* expected_reason;  // the part of the message after the quoted string
};

TEST(LayupNotation, RejectsMalformedStringsWithPosition) {
  const std::vector<Malformed> cases{
      {"[45/-45", "missing ']' at character 8"},
      {"45/-45]", "a lay-up must start with '[' at character 1"},
      {"[]", "empty ply at character 2"},
      {"[45//0]", "empty ply at character 5"},
      {"[45/]", "empty ply at character 5"},
      {"[abc]", "expected an angle at character 2"},
      {"[45]2X", "unexpected 'X' after the lay-up at character 6"},
      {"[0_0]", "repetition count must be at least 1 at character 4"},
      {"[0_-1]", "expected a repetition count (a positive integer) at character 4"},
      {"[400]", "angle beyond +-360 deg at character 2"},
      {"[-360.5]", "angle beyond +-360 deg at character 2"},
      {"[(0/90]", "expected '/' or ')' at character 7"},
      {"[0/90)]", "expected '/' or ']' at character 6"},
      {"[0 90]", "expected '/' or ']' at character 4"},
      {"[±45_2]", "a count on a ± ply is ambiguous; write (±a)n at character 6"},
      {"[0/90_h]", "'_h' needs a symmetric lay-up ('S') at character 9"},
      {"[0_h/90]S",
       "'_h' (mid-plane ply) is allowed only on the last ply of the outer brackets "
       "at character 2"},
      {"[0/90_h]2S", "'_h' cannot be combined with a repetition count at character 9"},
      {"[0/90]S2", "unexpected '2' after the lay-up at character 8"},
      {"[0/90]T2", "unexpected '2' after the lay-up at character 8"},
      {"[0_5000]", "repetition count above 1000 at character 4"},
      {"", "a lay-up must start with '[' at character 1"},
      {"[((0_1000)1000)1000]", "more than 100000 plies at character 11"},
  };
  for (const auto& c : cases) {
    try {
      parse_layup(c.notation);
      ADD_FAILURE() << "accepted '" << c.notation << "'";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::kInput);
      EXPECT_EQ(e.reason(), "lay-up '" + std::string(c.notation) + "': " + c.expected_reason);
    }
  }
}

}  // namespace
}  // namespace si
