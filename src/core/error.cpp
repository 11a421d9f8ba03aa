#include "core/error.hpp"

#include <utility>

#include "core/value_excerpt.hpp"

namespace si {

std::string format_error(const std::string& reason, const Where& where) {
  std::string prefix;
  if (!where.file.empty()) {
    prefix += where.file;
    if (where.line > 0) prefix += ":" + std::to_string(where.line);
    prefix += ": ";
  }
  if (!where.key.empty()) {
    prefix += where.key;
    if (!where.value.empty()) prefix += " = '" + value_excerpt(where.value) + "'";
    prefix += ": ";
  } else if (!where.value.empty()) {
    prefix += "'" + value_excerpt(where.value) + "': ";
  }
  return prefix + reason;
}

Error::Error(ErrorKind kind, std::string reason, Where where)
    : std::runtime_error(format_error(reason, where)),
      kind_(kind),
      reason_(std::move(reason)),
      where_(std::move(where)) {}

Error Error::within(const Where& outer) const {
  Where merged = where_;
  if (merged.file.empty()) merged.file = outer.file;
  if (merged.key.empty()) merged.key = outer.key;
  if (merged.value.empty()) merged.value = outer.value;
  if (merged.line == 0) merged.line = outer.line;
  return Error(kind_, reason_, merged);
}

int Error::exit_code() const noexcept {
  switch (kind_) {
    case ErrorKind::kInput:
      return 2;
    case ErrorKind::kNumerical:
      return 1;
    case ErrorKind::kInternal:
      return 3;
  }
  return 3;
}

void throw_input(std::string reason, Where where) {
  throw Error(ErrorKind::kInput, std::move(reason), std::move(where));
}

void throw_numerical(std::string reason, Where where) {
  throw Error(ErrorKind::kNumerical, std::move(reason), std::move(where));
}

}  // namespace si
