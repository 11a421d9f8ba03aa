#include "model/msh_scanner.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

namespace si {
namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

}  // namespace

MshScanner::MshScanner(const std::string& path) : path_(path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_input("cannot open the Gmsh mesh file (does it exist?)", {path, "", "", 0});
  std::ostringstream text;
  text << in.rdbuf();
  data_ = text.str();
}

std::string MshScanner::position() const {
  return binary_seen_ ? "byte " + std::to_string(pos_) : "line " + std::to_string(line_);
}

void MshScanner::fail(const std::string& reason, const std::string& value) const {
  throw_input(binary_seen_ ? reason + " (at byte " + std::to_string(pos_) + ")" : reason,
              {path_, "", value, line()});
}

void MshScanner::skip_space() {
  while (pos_ < data_.size() && is_space(data_[pos_])) {
    if (data_[pos_] == '\n') ++line_;
    ++pos_;
  }
}

bool MshScanner::at_end() {
  skip_space();
  return pos_ >= data_.size();
}

std::string_view MshScanner::token(const char* what) {
  if (at_end()) fail(std::string("the file ends early: expected ") + what + " (truncated file?)");
  const std::size_t begin = pos_;
  while (pos_ < data_.size() && !is_space(data_[pos_])) ++pos_;
  return std::string_view(data_).substr(begin, pos_ - begin);
}

long long MshScanner::integer(const char* what) {
  const std::string_view t = token(what);
  long long value = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec != std::errc() || end != t.data() + t.size())
    fail(std::string("expected an integer (") + what + ")", std::string(t));
  return value;
}

double MshScanner::real(const char* what) {
  const std::string_view t = token(what);
  double value = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec != std::errc() || end != t.data() + t.size())
    fail(std::string("expected a number (") + what + ")", std::string(t));
  return value;
}

void MshScanner::expect(std::string_view wanted) {
  const std::string_view t = token(std::string(wanted).c_str());
  if (t != wanted) fail("expected " + std::string(wanted), std::string(t));
}

std::string MshScanner::rest_of_line(const char* what) {
  if (at_end()) fail(std::string("the file ends early: expected ") + what + " (truncated file?)");
  const std::size_t end = std::min(data_.find('\n', pos_), data_.size());
  std::string t = data_.substr(pos_, end - pos_);
  pos_ = end;
  const std::size_t last = t.find_last_not_of(" \t\r");
  return t.substr(0, last + 1);
}

void MshScanner::skip_line_break() {
  while (pos_ < data_.size() && (data_[pos_] == ' ' || data_[pos_] == '\r')) ++pos_;
  if (pos_ >= data_.size() || data_[pos_] != '\n') fail("expected the end of the line");
  ++pos_;
  ++line_;
}

void MshScanner::skip_past(std::string_view marker) {
  const std::size_t at = data_.find(marker, pos_);
  if (at == std::string::npos)
    fail("the file ends before " + std::string(marker) + " (truncated file?)");
  line_ += static_cast<int>(std::count(data_.begin() + static_cast<std::ptrdiff_t>(pos_),
                                       data_.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
  pos_ = at + marker.size();
}

std::size_t MshScanner::check_count(long long n, const char* what, std::size_t bytes_each) const {
  if (n < 0) fail(std::string("expected a count (") + what + ")", std::to_string(n));
  const std::size_t need = std::max<std::size_t>(bytes_each, 1);
  if (static_cast<unsigned long long>(n) > remaining() / need)
    fail(std::string(what) + " " + std::to_string(n) + " cannot fit in the " +
             std::to_string(remaining()) + " bytes left in the file (corrupt or truncated file?)",
         std::to_string(n));
  return static_cast<std::size_t>(n);
}

std::size_t MshScanner::count(const char* what, std::size_t bytes_each) {
  return check_count(integer(what), what, bytes_each);
}

std::size_t MshScanner::binary_count(const char* what, std::size_t bytes_each) {
  const unsigned long long n = binary_size(what);
  if (n > remaining())
    fail(std::string("implausible ") + what + " (corrupt file?)", std::to_string(n));
  return check_count(static_cast<long long>(n), what, bytes_each);
}

unsigned long long MshScanner::binary_size(const char* what) {
  if (size_bytes_ == 4) return binary<unsigned int>(what);
  return binary<unsigned long long>(what);
}

void MshScanner::require_bytes(std::size_t n, const char* what) const {
  if (remaining() < n)
    fail(std::string("the file ends early: expected ") + what + " (truncated file?)");
}

}  // namespace si
