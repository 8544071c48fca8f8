#include "io/spans_file.h"

#include <ostream>

namespace haloplot::host {

void write_spans(std::ostream& out, const std::vector<Span>& spans) {
  out << "# haloplot spans v1: s EDGE X0 Y0 X1 Y1 (steps)\n";
  for (const Span& s : spans)
    out << "s " << s.edge << ' ' << s.x0 << ' ' << s.y0 << ' ' << s.x1 << ' ' << s.y1 << '\n';
}

}  // namespace haloplot::host
