#include "core/value_excerpt.hpp"

namespace si {
namespace {

bool continuation_byte(char c) {
  return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

// Byte offset of the first byte after `chars` characters of `text` (text.size() if shorter).
std::size_t byte_offset(std::string_view text, std::size_t chars) {
  std::size_t seen = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (continuation_byte(text[i])) continue;
    if (seen == chars) return i;
    ++seen;
  }
  return text.size();
}

}  // namespace

std::string value_excerpt(std::string_view text) {
  if (byte_offset(text, kExcerptChars) == text.size()) return std::string(text);
  return std::string(text.substr(0, byte_offset(text, kExcerptChars - 3))) + "...";
}

}  // namespace si
