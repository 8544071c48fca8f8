#include "io/line_reader.h"

#include <cerrno>
#include <cstdlib>
#include <sstream>

namespace haloplot::host {

bool LineReader::next(std::vector<std::string>* fields, std::string* comment) {
  std::string text;
  while (std::getline(in_, text)) {
    ++line_;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    // Blank means any whitespace the field split below skips (\v and \f too: the fuzzer
    // found a line of vertical tabs that split into no fields at all).
    size_t start = text.find_first_not_of(" \t\v\f\r");
    if (start == std::string::npos) continue;
    if (text[start] == '#') {
      if (comment) *comment += text.substr(start) + "\n";
      continue;
    }
    fields->clear();
    std::istringstream words(text);
    std::string w;
    while (words >> w) fields->push_back(w);
    if (fields->empty()) continue;  // whitespace the stream skips that the check above missed
    return true;
  }
  return false;
}

bool parse_int(const std::string& s, int64_t lo, int64_t hi, int64_t* out) {
  if (s.empty()) return false;
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if (errno != 0 || end != s.c_str() + s.size()) return false;
  if (v < lo || v > hi) return false;
  *out = v;
  return true;
}

}  // namespace haloplot::host
