#include "io/coordinate_rounding.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

namespace haloplot::host {
namespace {

// Exporters print at least 6 significant digits ("%g", Blender's "%f" of metres); a file whose
// every coordinate is shorter ("v 0.5 1 2") was written by hand or on a grid, and is taken as
// exact: its last place rounded nothing (trusting it would weld corners 0.1 apart in a file of
// one decimal).
constexpr int kExporterDigits = 6;

}  // namespace

void CoordinateRounding::note_text(std::string_view s) {
  size_t i = s.empty() || (s[0] != '-' && s[0] != '+') ? 0 : 1;
  int whole = 0, fraction = 0, significant = 0;
  bool point = false, nonzero = false;
  for (; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '.' && !point) {
      point = true;
      continue;
    }
    if (c < '0' || c > '9') break;
    nonzero = nonzero || c != '0';
    significant += nonzero ? 1 : 0;  // leading zeros ("0.0012") are not significant
    ++(point ? fraction : whole);
  }
  if (whole + fraction == 0) return;  // not a decimal number (strtod's "inf", hex): no rounding
  int exponent = 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    const std::string rest(s.substr(i + 1));
    char* end = nullptr;
    const long e = std::strtol(rest.c_str(), &end, 10);
    if (end != rest.c_str() + rest.size() || e < -400 || e > 400) return;
    exponent = int(e);
  }
  text_ = true;
  decimals_ = std::max(decimals_, fraction - exponent);
  significant_ = std::max(significant_, significant);
}

void CoordinateRounding::note_binary(int mantissa_bits) {
  binary_bits_ = binary_bits_ < 0 ? mantissa_bits : std::min(binary_bits_, mantissa_bits);
}

double CoordinateRounding::bound(double magnitude) const {
  double r = 0;
  if (binary_bits_ > 0) r = std::ldexp(magnitude, -binary_bits_);
  if (!text_) return r;
  const double float32 = std::ldexp(magnitude, -23);
  if (significant_ < kExporterDigits) return std::max(r, float32);
  const double fixed = 0.5 * std::pow(10.0, -decimals_);
  const double relative = significant_ > 0 ? 0.5 * std::pow(10.0, 1 - significant_) * magnitude : 0;
  return std::max({r, fixed, relative, float32});
}

}  // namespace haloplot::host
