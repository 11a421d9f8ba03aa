// A value as quoted in a message: the user's text, cut to its first kExcerptChars characters.
// An error quotes what the user wrote, and a hostile or mistaken value can be megabytes long
// (a whole file pasted into one key): echoing all of it took 17 s for 100 MB and buried the
// message itself.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace si {

constexpr std::size_t kExcerptChars = 80;

// `text` itself when it has at most kExcerptChars characters (UTF-8 code points); otherwise its
// first kExcerptChars - 3 characters, cut at a character boundary, followed by "...".
std::string value_excerpt(std::string_view text);

}  // namespace si
