#include "section/layup_notation.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "core/value_excerpt.hpp"

namespace si {
namespace {

constexpr double kMaxAngleDeg = 360.0;
constexpr long kMaxCount = 1000;      // a larger repetition count is a typo, not a laminate
constexpr size_t kMaxPlies = 100000;  // guards against "[0_999]999" exhausting memory
// Nested groups are parsed recursively: a bound on their depth keeps a hostile string such as
// "[((((...0...))))]" from overflowing the stack (30,000 levels did in a Release build, 3,476
// under AddressSanitizer). No laminate needs more than a few levels.
constexpr int kMaxNesting = 64;

constexpr std::string_view kPlusMinus = "\xC2\xB1";      // ±
constexpr std::string_view kMinusPlus = "\xE2\x88\x93";  // ∓

void append(std::vector<double>& to, const std::vector<double>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

std::vector<double> repeated(const std::vector<double>& angles, long count) {
  std::vector<double> out;
  out.reserve(angles.size() * static_cast<size_t>(count));
  for (long k = 0; k < count; ++k) append(out, angles);
  return out;
}

// Recursive-descent parser over the UTF-8 text; positions in messages count characters, not
// bytes, so that "±" counts as one.
class LayupParser {
 public:
  explicit LayupParser(std::string_view text) : text_(text) {}

  std::vector<double> parse() {
    skip_spaces();
    if (!accept("[")) fail("a lay-up must start with '['");
    std::vector<double> angles = parse_sequence(0);
    skip_spaces();
    if (!accept("]")) fail(at_end() ? "missing ']'" : "expected '/' or ']'");
    angles = parse_suffix(angles);
    skip_spaces();
    if (!at_end()) fail("unexpected '" + current_char() + "' after the lay-up");
    return angles;
  }

 private:
  struct Item {
    std::vector<double> angles;
    bool mid_plane = false;  // "_h": the unrepeated mid-plane ply of a symmetric stack
  };

  std::vector<double> parse_sequence(int depth) {
    std::vector<double> angles;
    while (true) {
      const size_t item_start = pos_;
      Item item = parse_item(depth);
      append(angles, item.angles);
      check_size(angles.size());
      skip_spaces();
      const bool more = peek("/");
      if (item.mid_plane) {
        if (depth > 0 || more) {
          pos_ = item_start;
          fail("'_h' (mid-plane ply) is allowed only on the last ply of the outer brackets");
        }
        mid_plane_ply_ = true;
      }
      if (!more) return angles;
      accept("/");
    }
  }

  Item parse_item(int depth) {
    skip_spaces();
    if (peek("/") || peek("]") || peek(")") || at_end()) fail("empty ply");
    if (peek("(") && depth >= kMaxNesting)
      fail("groups nested deeper than " + std::to_string(kMaxNesting) + " levels");
    if (accept("(")) {
      std::vector<double> group = parse_sequence(depth + 1);
      skip_spaces();
      if (!accept(")")) fail(at_end() ? "missing ')'" : "expected '/' or ')'");
      const bool underscore = accept("_");
      if (underscore || is_digit()) group = repeat_checked(group);
      return {group, false};
    }
    return parse_ply();
  }

  Item parse_ply() {
    const size_t start = pos_;
    bool pair = false;
    bool minus_first = false;
    double sign = 1.0;
    if (accept(kPlusMinus) || accept("+-")) {
      pair = true;
    } else if (accept(kMinusPlus) || accept("-+")) {
      pair = minus_first = true;
    } else if (accept("-")) {
      sign = -1.0;
    } else {
      accept("+");
    }
    const double magnitude = parse_number();
    if (std::abs(magnitude) > kMaxAngleDeg) {
      pos_ = start;
      fail("angle beyond +-360 deg");
    }
    const double angle = sign * magnitude;
    Item item;
    item.angles = pair ? (minus_first ? std::vector<double>{-angle, angle}
                                      : std::vector<double>{angle, -angle})
                       : std::vector<double>{angle};
    if (!accept("_")) return item;
    if (accept("h")) {
      if (pair) fail("a ± pair cannot be the mid-plane ply");
      item.mid_plane = true;
      return item;
    }
    if (pair) fail("a count on a ± ply is ambiguous; write (±a)n");
    item.angles = repeat_checked(item.angles);
    return item;
  }

  // Digits with an optional fraction and exponent, e.g. 45, 22.5, .5, 1e-05.
  double parse_number() {
    const size_t start = pos_;
    size_t end = pos_;
    auto digit_at = [&](size_t i) {
      return i < text_.size() && std::isdigit(static_cast<unsigned char>(text_[i]));
    };
    while (digit_at(end)) ++end;
    if (end < text_.size() && text_[end] == '.') ++end;
    while (digit_at(end)) ++end;
    const bool has_digit = digit_at(start) || (end > start + 1 && digit_at(start + 1));
    if (!has_digit) fail("expected an angle");
    if (end < text_.size() && (text_[end] == 'e' || text_[end] == 'E')) {
      size_t exp = end + 1;
      if (exp < text_.size() && (text_[exp] == '+' || text_[exp] == '-')) ++exp;
      if (digit_at(exp)) {
        while (digit_at(exp)) ++exp;
        end = exp;
      }
    }
    const std::string number(text_.substr(start, end - start));
    pos_ = end;
    return std::strtod(number.c_str(), nullptr);
  }

  long parse_count() {
    const size_t start = pos_;
    if (!is_digit()) fail("expected a repetition count (a positive integer)");
    long count = 0;
    while (is_digit()) {
      count = count * 10 + (text_[pos_] - '0');
      if (count > kMaxCount) {
        pos_ = start;
        fail("repetition count above " + std::to_string(kMaxCount));
      }
      ++pos_;
    }
    if (count < 1) {
      pos_ = start;
      fail("repetition count must be at least 1");
    }
    return count;
  }

  std::vector<double> parse_suffix(std::vector<double> angles) {
    skip_spaces();
    if (accept("T")) {
      if (mid_plane_ply_) fail("'_h' needs a symmetric lay-up ('S')");
      return angles;
    }
    const size_t count_pos = pos_;
    const bool underscore = accept("_");
    const bool has_count = underscore || is_digit();
    if (has_count) angles = repeat_checked(angles);
    skip_spaces();
    if (accept("S") || accept("s")) {
      if (mid_plane_ply_ && has_count) {
        pos_ = count_pos;
        fail("'_h' cannot be combined with a repetition count");
      }
      // The mid-plane ply is the last one written and is not mirrored.
      const size_t mirrored = angles.size() - (mid_plane_ply_ ? 1 : 0);
      for (size_t k = mirrored; k-- > 0;) angles.push_back(angles[k]);
      check_size(angles.size());
    } else if (mid_plane_ply_) {
      fail("'_h' needs a symmetric lay-up ('S')");
    }
    return angles;
  }

  // Reads a count and repeats `angles`, refusing (before allocating) a result that is too long.
  std::vector<double> repeat_checked(const std::vector<double>& angles) {
    const size_t start = pos_;
    const long count = parse_count();
    if (angles.size() * static_cast<size_t>(count) > kMaxPlies) {
      pos_ = start;
      check_size(angles.size() * static_cast<size_t>(count));
    }
    return repeated(angles, count);
  }

  void check_size(size_t n) const {
    if (n > kMaxPlies) fail("more than " + std::to_string(kMaxPlies) + " plies");
  }

  void skip_spaces() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool at_end() const { return pos_ >= text_.size(); }
  bool is_digit() const {
    return !at_end() && std::isdigit(static_cast<unsigned char>(text_[pos_]));
  }
  bool peek(std::string_view token) const { return text_.substr(pos_, token.size()) == token; }
  bool accept(std::string_view token) {
    if (!peek(token)) return false;
    pos_ += token.size();
    return true;
  }

  // The whole UTF-8 character at the current position, for messages.
  std::string current_char() const {
    size_t end = pos_ + 1;
    while (end < text_.size() && (static_cast<unsigned char>(text_[end]) & 0xC0) == 0x80) ++end;
    return std::string(text_.substr(pos_, end - pos_));
  }

  // 1-based character (not byte) position of pos_.
  size_t character_position() const {
    size_t chars = 0;
    for (size_t i = 0; i < pos_ && i < text_.size(); ++i)
      if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) ++chars;
    return chars + 1;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw_input("lay-up '" + value_excerpt(text_) + "': " + what + " at character " +
                std::to_string(character_position()));
  }

  std::string_view text_;
  size_t pos_ = 0;
  bool mid_plane_ply_ = false;
};

// Shortest decimal text that reads back to exactly `angle` (at least 3 significant digits so
// that 100 prints as "100", not "1e+02").
std::string format_angle(double angle) {
  char buffer[32];
  for (int digits = 3; digits <= 17; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, angle);
    if (std::strtod(buffer, nullptr) == angle) break;
  }
  return buffer;
}

// `group` (a sequence the parser reads) written `count` times with repetition counts the parser
// accepts (<= kMaxCount): "(g)n", and above kMaxCount nested, "((g)1000)2/(g)500" for 2500.
std::string repeated_group(const std::string& group, size_t count) {
  const auto limit = static_cast<size_t>(kMaxCount);
  if (count == 1) return group;
  if (count <= limit) return "(" + group + ")" + std::to_string(count);
  const std::string whole =
      repeated_group("(" + group + ")" + std::to_string(limit), count / limit);
  return count % limit == 0 ? whole : whole + "/" + repeated_group(group, count % limit);
}

// A run of `count` plies at one angle: "a", "a_n", or for n > kMaxCount "(a_1000)2/a_500".
std::string run_token(const std::string& angle, size_t count) {
  const auto limit = static_cast<size_t>(kMaxCount);
  if (count == 1) return angle;
  if (count <= limit) return angle + "_" + std::to_string(count);
  const std::string whole = repeated_group(angle + "_" + std::to_string(limit), count / limit);
  return count % limit == 0 ? whole : whole + "/" + run_token(angle, count % limit);
}

// Plies joined by '/', with runs of equal angles as "a_n" and a,-a pairs (a > 0) as "±a".
std::string format_plies(const std::vector<double>& angles) {
  std::string out;
  for (size_t i = 0; i < angles.size();) {
    size_t run = 1;
    while (i + run < angles.size() && angles[i + run] == angles[i]) ++run;
    std::string token;
    if (run > 1) {
      token = run_token(format_angle(angles[i]), run);
    } else if (angles[i] > 0 && i + 1 < angles.size() && angles[i + 1] == -angles[i] &&
               (i + 2 >= angles.size() || angles[i + 2] != angles[i + 1])) {
      token = std::string(kPlusMinus) + format_angle(angles[i]);
      run = 2;
    } else {
      token = format_angle(angles[i]);
    }
    out += (out.empty() ? "" : "/") + token;
    i += run;
  }
  return out;
}

// "[base]k" with the smallest period of two or more plies, or "[plies]" when that is shorter
// (a single repeated angle reads better as a run, "[0_4]", than as "[0]4").
std::string format_with_repetition(const std::vector<double>& angles, const std::string& suffix) {
  std::string best = "[" + format_plies(angles) + "]" + suffix;
  const size_t n = angles.size();
  for (size_t period = 2; period < n; ++period) {
    if (n % period != 0) continue;
    bool periodic = true;
    for (size_t i = period; i < n && periodic; ++i) periodic = angles[i] == angles[i - period];
    if (!periodic) continue;
    const std::vector<double> base(angles.begin(), angles.begin() + period);
    // A count the parser refuses (above kMaxCount) is written as nested groups instead.
    const size_t count = n / period;
    const std::string candidate =
        count <= static_cast<size_t>(kMaxCount)
            ? "[" + format_plies(base) + "]" + std::to_string(count) + suffix
            : "[" + repeated_group(format_plies(base), count) + "]" + suffix;
    if (candidate.size() < best.size()) best = candidate;
    break;
  }
  return best;
}

bool is_palindrome(const std::vector<double>& a) {
  for (size_t i = 0, j = a.size(); i < j--; ++i)
    if (a[i] != a[j]) return false;
  return true;
}

}  // namespace

std::vector<double> parse_layup(std::string_view notation) {
  return LayupParser(notation).parse();
}

std::string format_layup(const std::vector<double>& angles_deg) {
  if (angles_deg.empty()) throw_input("cannot format an empty lay-up");
  for (double a : angles_deg) {
    if (!std::isfinite(a) || std::abs(a) > kMaxAngleDeg)
      throw_input("cannot format a ply angle of " + format_angle(a) + " deg (|angle| <= 360)");
  }
  std::string best = format_with_repetition(angles_deg, "");
  const size_t n = angles_deg.size();
  if (n < 2 || !is_palindrome(angles_deg)) return best;

  const std::vector<double> half(angles_deg.begin(), angles_deg.begin() + n / 2);
  std::string symmetric = n % 2 == 0 ? format_with_repetition(half, "S")
                                     : "[" + (half.empty() ? "" : format_plies(half) + "/") +
                                           format_angle(angles_deg[n / 2]) + "_h]S";
  if (symmetric.size() <= best.size()) best = symmetric;
  return best;
}

std::string describe_laminate(const Laminate& laminate) {
  const auto& plies = laminate.plies;
  const bool uniform = !plies.empty() && std::all_of(plies.begin(), plies.end(), [&](const Ply& p) {
    return p.material.name() == plies.front().material.name() &&
           p.thickness == plies.front().thickness;
  });
  if (!uniform) return "ply list (" + std::to_string(plies.size()) + " plies)";
  std::vector<double> angles;
  for (const auto& p : plies) angles.push_back(p.angle_deg);
  return format_layup(angles);
}

}  // namespace si
