// Reading the text and binary parts of a Gmsh MSH file (gmsh_reader.hpp) out of one in-memory
// copy of the file, with the position every error message needs: the 1-based line in text
// parts, the byte offset in binary parts (where a line number means nothing).
//
// Counts read from the file are bounded by the bytes that are left (count()): a corrupt or
// hostile count can never make the reader allocate more than the file could describe.
#pragma once

#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace si {

class MshScanner {
 public:
  // Reads the whole file; an input error if it cannot be opened.
  explicit MshScanner(const std::string& path);

  const std::string& path() const { return path_; }

  // Position for messages: "line 12" in text, "byte 4711" once binary data has been read.
  std::string position() const;
  // The 1-based line (0 after binary data: lines no longer mean anything).
  int line() const { return binary_seen_ ? 0 : line_; }
  // The line (text) or byte offset (binary) of the cursor, to name an element later.
  long long location() const { return binary_seen_ ? static_cast<long long>(pos_) : line_; }
  bool binary_seen() const { return binary_seen_; }

  [[noreturn]] void fail(const std::string& reason, const std::string& value = "") const;

  // ---- text
  bool at_end();  // after skipping white space
  std::string_view token(const char* what);
  long long integer(const char* what);
  double real(const char* what);
  void expect(std::string_view wanted);
  // The rest of the current line, trimmed (names in quotes may hold spaces).
  std::string rest_of_line(const char* what);
  // Skips past the next line break (after the last text token before binary data).
  void skip_line_break();
  // Moves to just after `marker` (sections the reader does not use); fails if it never comes.
  void skip_past(std::string_view marker);

  // A count read as text (count) or as a binary size_t (binary_count), refused if negative or
  // if `bytes_each` bytes per item would not fit in the rest of the file.
  std::size_t count(const char* what, std::size_t bytes_each);
  std::size_t binary_count(const char* what, std::size_t bytes_each);
  std::size_t check_count(long long n, const char* what, std::size_t bytes_each) const;

  // ---- binary (native byte order; gmsh_reader checks it)
  template <class T>
  T binary(const char* what) {
    binary_seen_ = true;
    require_bytes(sizeof(T), what);
    T value;
    std::memcpy(&value, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }
  // A Gmsh "size_t" of the file's data size (4 or 8 bytes).
  unsigned long long binary_size(const char* what);
  void set_size_bytes(int bytes) { size_bytes_ = bytes; }
  void require_bytes(std::size_t n, const char* what) const;
  std::size_t remaining() const { return data_.size() - pos_; }

 private:
  void skip_space();

  std::string path_;
  std::string data_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int size_bytes_ = 8;
  bool binary_seen_ = false;
};

}  // namespace si
