#include "render/svg.h"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>

namespace haloplot::host {

namespace {

// Millimetres to three decimals (a micrometre), without a locale's comma.
std::string mm_text(double mm) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", mm);
  return buf;
}

}  // namespace

void write_svg(std::ostream& out, const std::vector<Span>& spans, const SvgStyle& style) {
  int32_t xmin = 0, ymin = 0, xmax = 1, ymax = 1;
  if (!spans.empty()) {
    xmin = ymin = kCoordMax;
    xmax = ymax = 0;
    for (const Span& s : spans) {
      xmin = std::min({xmin, s.x0, s.x1});
      xmax = std::max({xmax, s.x0, s.x1});
      ymin = std::min({ymin, s.y0, s.y1});
      ymax = std::max({ymax, s.y0, s.y1});
    }
  }
  const int32_t span_max = std::max(xmax - xmin, ymax - ymin) + 1;
  const int32_t margin = span_max / 40 + 1;
  const int32_t w = xmax - xmin + 2 * margin, h = ymax - ymin + 2 * margin;
  const double stroke = style.stroke_steps > 0 ? style.stroke_steps : span_max / 1000.0 + 0.5;
  const double per_mm = style.steps_per_mm > 0 ? style.steps_per_mm : 80;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << mm_text(w / per_mm)
      << "mm\" height=\"" << mm_text(h / per_mm) << "mm\" viewBox=\"" << xmin - margin << ' '
      << -(ymax + margin) << ' ' << w << ' ' << h << "\">\n"
      << "<rect x=\"" << xmin - margin << "\" y=\"" << -(ymax + margin) << "\" width=\"" << w
      << "\" height=\"" << h << "\" fill=\"white\"/>\n"
      << "<path fill=\"none\" stroke=\"black\" stroke-linecap=\"round\" stroke-width=\"" << stroke
      << "\" d=\"";
  // One path, y negated: the viewBox above starts at -(ymax + margin).
  for (const Span& s : spans) out << 'M' << s.x0 << ' ' << -s.y0 << 'L' << s.x1 << ' ' << -s.y1;
  out << "\"/>\n";
  if (style.second_pen != nullptr && !style.second_pen->empty()) {
    out << "<path fill=\"none\" stroke=\"black\" stroke-linecap=\"round\" stroke-width=\""
        << stroke * style.second_pen_width << "\" d=\"";
    for (const Span& s : *style.second_pen)
      out << 'M' << s.x0 << ' ' << -s.y0 << 'L' << s.x1 << ' ' << -s.y1;
    out << "\"/>\n";
  }
  out << "</svg>\n";
}

}  // namespace haloplot::host
