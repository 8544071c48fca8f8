// Line-by-line tokenising shared by the text readers: strips CR (files from Windows) and a
// UTF-8 byte-order mark, skips blank and '#' comment lines, and parses integers strictly (no
// trailing junk, no overflow). Lines are bounded (kMaxLine bytes, so a hostile file costs no
// more memory than that) and so are fields (kMaxField); a longer one, a NUL byte, or UTF-16
// text ends the input with error() saying so, at line().
#pragma once
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace haloplot::host {

class LineReader {
 public:
  explicit LineReader(std::istream& in) : in_(in) {}
  // Next data line split on blanks; false at end of input. Comment lines are offered to
  // `comment` first, if set, so headers can carry settings.
  bool next(std::vector<std::string>* fields, std::string* comment = nullptr);
  int line() const { return line_; }
  const std::string& error() const { return error_; }  // why next() stopped early ("" at end)

  static constexpr size_t kMaxLine = size_t{1} << 20, kMaxField = 4096;

 private:
  bool read_line(std::string* text);  // false at the end or on a bad line (error_ set)
  std::istream& in_;
  int line_ = 0;
  std::string error_;
};

// A field as an error message quotes it: at most 40 bytes, then "...".
std::string excerpt(const std::string& field);

// Strict decimal integer in [lo, hi]; false on anything else.
bool parse_int(const std::string& s, int64_t lo, int64_t hi, int64_t* out);

}  // namespace haloplot::host
