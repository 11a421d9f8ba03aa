// The one exception type of shellindent. It carries where a bad value came from (file, line,
// key, value) so that every message a user sees names them, and a kind that the CLI maps to
// its exit code: 2 for bad input, 1 for a numerical failure.
#pragma once

#include <stdexcept>
#include <string>

namespace si {

enum class ErrorKind { kInput, kNumerical, kInternal };

// Where a value came from. Empty fields are left out of the message; line is 1-based, 0 = unknown.
struct Where {
  std::string file;
  std::string key;    // dotted path in the case file, e.g. "laminate.ply_thickness"
  std::string value;  // the offending text as the user wrote it
  int line = 0;
};

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, std::string reason, Where where = {});

  ErrorKind kind() const noexcept { return kind_; }
  const std::string& reason() const noexcept { return reason_; }
  const Where& where() const noexcept { return where_; }

  // A copy in which the fields this error does not know yet are taken from `outer`. Used where
  // a low-level parser (units, lay-up notation) is called by the case-file reader.
  Error within(const Where& outer) const;

  // Process exit code for this kind: 2 input, 1 numerical, 3 internal.
  int exit_code() const noexcept;

 private:
  ErrorKind kind_;
  std::string reason_;
  Where where_;
};

// "case.yaml:4: laminate.ply_thickness = '-1 mm': <reason>"
std::string format_error(const std::string& reason, const Where& where);

[[noreturn]] void throw_input(std::string reason, Where where = {});
[[noreturn]] void throw_numerical(std::string reason, Where where = {});

}  // namespace si

// Always-on check of user input and of invariants a user can break: throws an input Error.
#define SI_REQUIRE(cond, reason)              \
  do {                                        \
    if (!(cond)) ::si::throw_input((reason)); \
  } while (false)

// Debug-only check of internal invariants (compiled out with NDEBUG).
#ifdef NDEBUG
#define SI_ASSERT(cond) ((void)0)
#else
#define SI_ASSERT(cond)                                                                   \
  do {                                                                                    \
    if (!(cond))                                                                          \
      throw ::si::Error(::si::ErrorKind::kInternal,                                       \
                        std::string("assertion failed: " #cond " at ") + __FILE__ + ":" + \
                            std::to_string(__LINE__));                                    \
  } while (false)
#endif
