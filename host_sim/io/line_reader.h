// Line-by-line tokenising shared by the text readers: strips CR (files from Windows) and a
// UTF-8 byte-order mark, skips blank and '#' comment lines, and parses integers strictly (no
// trailing junk, no overflow). Lines are bounded (kMaxLine bytes, so a hostile file costs no
// more memory than that) and so are fields (kMaxField); a longer one, a NUL byte, or UTF-16
// text ends the input with error() saying so, at line().
#pragma once
#include <cstdint>
#include <istream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace haloplot::host {

class LineReader {
 public:
  explicit LineReader(std::istream& in) : in_(in) {}
  // Next data line split on blanks; false at end of input. Comment lines are offered to
  // `comment` first, if set, so headers can carry settings.
  bool next(std::vector<std::string>* fields, std::string* comment = nullptr);
  // The same, the fields as views into the line: they hold until the next call (a big model's
  // reader builds no string per field).
  bool next(std::vector<std::string_view>* fields, std::string* comment = nullptr);
  int line() const { return line_; }
  const std::string& error() const { return error_; }  // why next() stopped early ("" at end)

  static constexpr size_t kMaxLine = size_t{1} << 20, kMaxField = 4096;

 private:
  bool read_line(std::string* text);  // false at the end or on a bad line (error_ set)
  // The next data line's fields as views into text_.
  bool split_next(std::vector<std::string_view>* fields, std::string* comment);
  std::istream& in_;
  int line_ = 0;
  std::string error_;
  std::string text_;  // the line being split (kept: its capacity serves the next line)
  std::vector<std::string_view> views_;
  std::unique_ptr<char[]> line_buffer_;  // kMaxLine + 2 bytes, once a line is read
};

// A field as an error message quotes it: at most 40 bytes, then "...".
std::string excerpt(const std::string& field);

// Strict decimal integer in [lo, hi]; false on anything else.
bool parse_int(const std::string& s, int64_t lo, int64_t hi, int64_t* out);
// The same for a field (no blanks in it), without a string.
bool parse_int_field(std::string_view s, int64_t lo, int64_t hi, int64_t* out);

// A whole field as a finite number, as strtod reads it (any form it takes, "+1", "0x1p3",
// ".5e2"); false when strtod would stop early or the value is not finite.
bool parse_finite(std::string_view s, double* out);

}  // namespace haloplot::host
