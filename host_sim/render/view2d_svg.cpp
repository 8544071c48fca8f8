#include "render/view2d_svg.h"

#include <algorithm>

namespace haloplot::host {

void write_view2d_svg(std::ostream& out, const std::vector<Point2>& poly, Point2 eye,
                      const std::vector<VisibleSpan>& visible) {
  int64_t x0 = eye.x, x1 = eye.x, y0 = eye.y, y1 = eye.y;
  for (const Point2& p : poly)
    x0 = std::min<int64_t>(x0, p.x), x1 = std::max<int64_t>(x1, p.x),
    y0 = std::min<int64_t>(y0, p.y), y1 = std::max<int64_t>(y1, p.y);
  const int64_t size = std::max<int64_t>({x1 - x0, y1 - y0, 1});
  const int64_t pad = size / 20 + 1;
  const double stroke = double(size) / 300;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\""
      << 800 * (y1 - y0 + 2 * pad) / (x1 - x0 + 2 * pad) << "\" viewBox=\"" << x0 - pad << " "
      << -(y1 + pad) << " " << x1 - x0 + 2 * pad << " " << y1 - y0 + 2 * pad << "\">\n"
      << "<rect x=\"" << x0 - pad << "\" y=\"" << -(y1 + pad) << "\" width=\"" << x1 - x0 + 2 * pad
      << "\" height=\"" << y1 - y0 + 2 * pad << "\" fill=\"white\"/>\n";
  // Hidden: the whole outline dashed; visible parts drawn over it, solid.
  out << "<polygon fill=\"none\" stroke=\"#888\" stroke-width=\"" << stroke * 0.6
      << "\" stroke-dasharray=\"" << stroke * 3 << " " << stroke * 3 << "\" points=\"";
  for (const Point2& p : poly) out << p.x << "," << -p.y << " ";
  out << "\"/>\n<g stroke=\"black\" stroke-width=\"" << stroke * 1.6
      << "\" stroke-linecap=\"round\">\n";
  const uint32_t n = uint32_t(poly.size());
  for (const VisibleSpan& s : visible) {
    const Point2 a = poly[s.edge], b = poly[(s.edge + 1) % n];
    int32_t ax, ay, bx, by;
    visible_point(a, b, s.s0, &ax, &ay);
    visible_point(a, b, s.s1, &bx, &by);
    out << "<line x1=\"" << ax << "\" y1=\"" << -ay << "\" x2=\"" << bx << "\" y2=\"" << -by
        << "\"/>\n";
  }
  out << "</g>\n<circle cx=\"" << eye.x << "\" cy=\"" << -eye.y << "\" r=\"" << stroke * 3
      << "\" fill=\"#d62728\"/>\n<text x=\"" << eye.x + stroke * 5 << "\" y=\"" << -eye.y
      << "\" font-size=\"" << stroke * 12 << "\" fill=\"#d62728\">E</text>\n</svg>\n";
}

}  // namespace haloplot::host
