// Numbers as users write them in case files, CSV files and options: plain decimals only,
// [+-] digits [. digits] [e [+-] digits] ("0.475", "-45", "1e-3", ".5").
//
// std::strtod also reads "nan", "inf", "infinity" and hexadecimal floats ("0x1p6" = 64). Those
// are refused here on purpose: a NaN or an infinity compares false with every bound, so it slips
// through range checks ("--range nan:5" would keep no point or every point, E = inf passes
// "> 0"); and a hexadecimal float in an engineering input is far more likely a slip (or a
// fuzzer) than a deliberate value, which the user then cannot recognise in our messages (they
// print decimals). Refusing costs nothing: every value can be written in decimal.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace si {

// Reads a decimal number at the start of `text`; on success returns its value (finite, or an
// overflow to +-inf, which callers refuse as out of range) and sets `length` to the characters
// used. Returns std::nullopt (length 0) when `text` does not start with a decimal number, or
// starts with a hexadecimal one ("0x...").
std::optional<double> parse_decimal_prefix(std::string_view text, std::size_t& length);

// True when `text` starts like a hexadecimal number ("0x1p6", "-0X10"): for the message.
bool is_hexadecimal(std::string_view text);

// The whole of `text` as a finite decimal number, std::nullopt otherwise (no surrounding spaces).
std::optional<double> parse_decimal(std::string_view text);

// `value` with `digits` significant digits in the shortest of fixed and scientific notation
// (as a stream writes it: "0.7", "1e-08"): numbers in messages that the reader above reads back.
std::string format_decimal(double value, int digits = 10);

}  // namespace si
