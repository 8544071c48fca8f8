// Line-by-line tokenising shared by the text readers: strips CR (files from Windows), skips
// blank and '#' comment lines, and parses integers strictly (no trailing junk, no overflow).
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

 private:
  std::istream& in_;
  int line_ = 0;
};

// Strict decimal integer in [lo, hi]; false on anything else.
bool parse_int(const std::string& s, int64_t lo, int64_t hi, int64_t* out);

}  // namespace haloplot::host
