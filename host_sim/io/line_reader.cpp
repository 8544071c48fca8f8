#include "io/line_reader.h"

#include <cerrno>
#include <cstdlib>
#include <sstream>

namespace haloplot::host {

bool LineReader::read_line(std::string* text) {
  text->clear();
  int c;
  while ((c = in_.get()) != EOF && c != '\n') {
    if (text->size() == kMaxLine) {
      ++line_;
      error_ = "line longer than " + std::to_string(kMaxLine) + " bytes";
      return false;
    }
    text->push_back(char(c));
  }
  if (c == EOF && text->empty()) return false;
  ++line_;
  if (line_ == 1 && text->size() >= 2 &&
      ((uint8_t((*text)[0]) == 0xFF && uint8_t((*text)[1]) == 0xFE) ||
       (uint8_t((*text)[0]) == 0xFE && uint8_t((*text)[1]) == 0xFF))) {
    error_ = "UTF-16 text: save the file as UTF-8 (or ASCII)";
    return false;
  }
  if (line_ == 1 && text->compare(0, 3, "\xEF\xBB\xBF") == 0) text->erase(0, 3);  // UTF-8 BOM
  const size_t nul = text->find('\0');
  if (nul != std::string::npos) {
    error_ = "NUL byte at column " + std::to_string(nul + 1) + " (a binary or UTF-16 file?)";
    return false;
  }
  return true;
}

std::string excerpt(const std::string& field) {
  return field.size() <= 40 ? field : field.substr(0, 40) + "...";
}

bool LineReader::next(std::vector<std::string>* fields, std::string* comment) {
  std::string text;
  while (read_line(&text)) {
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
    while (words >> w) {
      if (w.size() > kMaxField) {
        error_ = "field " + std::to_string(fields->size() + 1) + " ('" + excerpt(w) + "') is " +
                 std::to_string(w.size()) + " bytes long, more than " + std::to_string(kMaxField);
        return false;
      }
      fields->push_back(w);
    }
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
