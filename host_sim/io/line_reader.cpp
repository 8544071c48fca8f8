#include "io/line_reader.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace haloplot::host {

bool LineReader::read_line(std::string* text) {
  text->clear();
  // One getline a line (it scans the stream's buffer for the newline, where get() built a
  // sentry per byte), into a buffer one byte longer than a line may be: a longer one fills it.
  if (!line_buffer_) line_buffer_.reset(new char[kMaxLine + 2]);
  in_.getline(line_buffer_.get(), std::streamsize(kMaxLine + 2));
  const size_t got = size_t(in_.gcount());
  if (got == 0) return false;                      // the end (or a stream that was not good)
  const bool newline = !in_.fail() && !in_.eof();  // the delimiter was taken, and counted
  const size_t length = newline ? got - 1 : got;
  if (length > kMaxLine) {
    ++line_;
    error_ = "line longer than " + std::to_string(kMaxLine) + " bytes";
    return false;
  }
  text->assign(line_buffer_.get(), length);
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

namespace {

// The blanks `>>` skips in the classic locale.
bool blank(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

}  // namespace

bool LineReader::split_next(std::vector<std::string_view>* fields, std::string* comment) {
  std::string& text = text_;
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
    for (size_t i = start; i < text.size();) {
      if (blank(text[i])) {
        ++i;
        continue;
      }
      size_t end = i;
      while (end < text.size() && !blank(text[end])) ++end;
      if (end - i > kMaxField) {
        const std::string w = text.substr(i, end - i);
        error_ = "field " + std::to_string(fields->size() + 1) + " ('" + excerpt(w) + "') is " +
                 std::to_string(w.size()) + " bytes long, more than " + std::to_string(kMaxField);
        return false;
      }
      fields->push_back(std::string_view(text).substr(i, end - i));
      i = end;
    }
    if (fields->empty()) continue;
    return true;
  }
  return false;
}

bool LineReader::next(std::vector<std::string_view>* fields, std::string* comment) {
  return split_next(fields, comment);
}

bool LineReader::next(std::vector<std::string>* fields, std::string* comment) {
  if (!split_next(&views_, comment)) return false;
  fields->resize(views_.size());
  for (size_t i = 0; i < views_.size(); ++i) (*fields)[i].assign(views_[i]);
  return true;
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

bool parse_int_field(std::string_view s, int64_t lo, int64_t hi, int64_t* out) {
  // What strtoll reads in base 10 from a field (no blanks in it): a sign, then digits only.
  size_t i = 0;
  const bool negative = !s.empty() && s[0] == '-';
  if (!s.empty() && (s[0] == '-' || s[0] == '+')) i = 1;
  if (i == s.size()) return false;
  uint64_t v = 0;
  for (; i < s.size(); ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
    if (v > (uint64_t{1} << 63) / 10) return false;  // past any int64_t: strtoll's overflow
    v = v * 10 + uint64_t(s[i] - '0');
  }
  if (v > (uint64_t{1} << 63) || (!negative && v == (uint64_t{1} << 63))) return false;
  const int64_t value = negative ? int64_t(0 - v) : int64_t(v);
  if (value < lo || value > hi) return false;
  *out = value;
  return true;
}

bool parse_finite(std::string_view s, double* out) {
  if (s.empty()) return false;
  // from_chars rounds correctly, as strtod does, and takes the plain decimal forms; anything
  // it does not read to the end (a '+', hex, out of range) goes to strtod itself.
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec == std::errc() && end == s.data() + s.size()) {
    *out = v;
    return std::isfinite(v);
  }
  const std::string copy(s);
  char* stop = nullptr;
  *out = std::strtod(copy.c_str(), &stop);
  return stop == copy.c_str() + copy.size() && std::isfinite(*out);
}

}  // namespace haloplot::host
