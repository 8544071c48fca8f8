#include "io/spans_file.h"

#include <ostream>

#include "haloplot/solid/qi.h"

namespace haloplot::host {

std::string qi_text(int32_t halves) {
  if (halves == kQiUnknown) return "?";
  return std::to_string(halves / 2) + (halves % 2 != 0 ? ".5" : "");
}

void write_spans(std::ostream& out, const std::vector<Span>& spans) {
  out << "# haloplot spans v1: s EDGE X0 Y0 X1 Y1 (steps)\n";
  for (const Span& s : spans)
    out << "s " << s.edge << ' ' << s.x0 << ' ' << s.y0 << ' ' << s.x1 << ' ' << s.y1 << '\n';
}

void write_spans_qi(std::ostream& out, const std::vector<Span>& spans,
                    const std::vector<int32_t>& qi, const std::vector<Span>& outline,
                    const std::vector<Span>& hatch) {
  out << "# haloplot spans v2: s EDGE X0 Y0 X1 Y1 QI (steps; o: outline pass)\n";
  for (size_t i = 0; i < spans.size(); ++i) {
    const Span& s = spans[i];
    out << "s " << s.edge << ' ' << s.x0 << ' ' << s.y0 << ' ' << s.x1 << ' ' << s.y1 << ' '
        << qi_text(qi[i]) << '\n';
  }
  for (const Span& s : outline)
    out << "o " << s.edge << ' ' << s.x0 << ' ' << s.y0 << ' ' << s.x1 << ' ' << s.y1 << " 0\n";
  for (const Span& s : hatch)
    out << "h " << s.edge << ' ' << s.x0 << ' ' << s.y0 << ' ' << s.x1 << ' ' << s.y1 << " 0\n";
}

}  // namespace haloplot::host
