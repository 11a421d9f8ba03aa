#include "core/decimal_number.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

namespace si {
namespace {

bool digit_at(std::string_view text, std::size_t i) {
  return i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]));
}

}  // namespace

std::optional<double> parse_decimal_prefix(std::string_view text, std::size_t& length) {
  length = 0;
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  const std::size_t mantissa = i;
  while (digit_at(text, i)) ++i;
  std::size_t digits = i - mantissa;
  if (i < text.size() && text[i] == '.') {
    const std::size_t fraction = ++i;
    while (digit_at(text, i)) ++i;
    digits += i - fraction;
  }
  if (digits == 0) return std::nullopt;
  // "0x..." is a hexadecimal float to strtod: refused, not read as 0 followed by a unit "x...".
  if (i < text.size() && (text[i] == 'x' || text[i] == 'X') && i == mantissa + 1 &&
      text[mantissa] == '0')
    return std::nullopt;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t e = i + 1;
    if (e < text.size() && (text[e] == '+' || text[e] == '-')) ++e;
    if (digit_at(text, e)) {
      while (digit_at(text, e)) ++e;
      i = e;
    }
  }
  const std::string number(text.substr(0, i));
  length = i;
  return std::strtod(number.c_str(), nullptr);
}

bool is_hexadecimal(std::string_view text) {
  if (!text.empty() && (text[0] == '+' || text[0] == '-')) text.remove_prefix(1);
  return text.size() > 1 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
}

std::optional<double> parse_decimal(std::string_view text) {
  std::size_t length = 0;
  const std::optional<double> v = parse_decimal_prefix(text, length);
  if (!v || length != text.size() || !std::isfinite(*v)) return std::nullopt;
  return v;
}

std::string format_decimal(double value, int digits) {
  std::ostringstream os;
  os.precision(digits);
  os << value;
  return os.str();
}

}  // namespace si
