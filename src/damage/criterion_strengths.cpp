#include "damage/criterion_strengths.hpp"

#include <limits>
#include <string>

#include "core/error.hpp"

namespace si {
namespace {

using K = StrengthKey;

double& entry(Strengths& s, StrengthKey key) {
  switch (key) {
    case K::kXT:
      return s.X_T;
    case K::kXC:
      return s.X_C;
    case K::kYT:
      return s.Y_T;
    case K::kYC:
      return s.Y_C;
    case K::kZT:
      return s.Z_T;
    case K::kZC:
      return s.Z_C;
    case K::kS12:
      return s.S_12;
    case K::kS13:
      return s.S_13;
    case K::kS23:
      return s.S_23;
  }
  return s.X_T;  // unreachable: every key is handled above
}

}  // namespace

std::vector<StrengthKey> required_strengths(Criterion criterion) {
  switch (criterion) {
    case Criterion::kMaxStress:
    case Criterion::kTsaiWu:
      return {K::kXT, K::kXC, K::kYT, K::kYC, K::kZT, K::kZC, K::kS12, K::kS13, K::kS23};
    case Criterion::kHashin:
      return {K::kXT, K::kXC, K::kYT, K::kYC, K::kS12, K::kS23};
    case Criterion::kQuadraticDelamination:
      return {K::kZT, K::kS13, K::kS23};
  }
  return {};
}

Strengths strengths_for(Criterion criterion, const Material& material) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Strengths out{nan, nan, nan, nan, nan, nan, nan, nan, nan};
  for (StrengthKey key : required_strengths(criterion)) {
    const std::optional<double> value = material.strengths().get(key);
    if (!value)
      throw_input("material '" + material.name() + "' has no " + key_name(key) + ", which the " +
                      criterion_name(criterion) + " criterion needs",
                  Where{"", key_name(key), material.name(), 0});
    entry(out, key) = *value;
  }
  return out;
}

const char* criterion_name(Criterion criterion) {
  switch (criterion) {
    case Criterion::kMaxStress:
      return "maximum stress";
    case Criterion::kTsaiWu:
      return "Tsai-Wu";
    case Criterion::kHashin:
      return "Hashin";
    case Criterion::kQuadraticDelamination:
      return "quadratic delamination";
  }
  return "?";
}

}  // namespace si
