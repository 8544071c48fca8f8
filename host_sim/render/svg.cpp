#include "render/svg.h"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>

#include "haloplot/geometry/fraction.h"

namespace haloplot::host {

namespace {

// One path point on the page, in micrometres, rounded as the G-code's mm_text rounds.
struct PagePoint {
  const PlotSvgStyle& s;
  int64_t um(int64_t steps, int32_t offset) const {
    const int64_t per = s.placement.steps_per_mm;
    return floor_div((steps + offset) * 2000 + per, 2 * per);
  }
  void append(std::string* out, const PathPoint& p) const {
    append_thousandths(out, um(p.x, s.placement.offset_x));
    *out += ',';
    append_thousandths(out, s.page.height_um - um(p.y, s.placement.offset_y));
  }
};

// One layer: a <path> per pen-down stroke, from the point the pen went down at. Its id is its
// label's number, not its place among the layers drawn (an empty layer is left out), so vpype
// and the AxiDraw extension, which go by either, see the same layer; its colour is its kind's.
void write_layer(std::ostream& out, const PlannedLayer& l, const PlotSvgStyle& s) {
  char width[32];
  std::snprintf(width, sizeof width, "%.3f", s.pen_width_mm * l.pen_width);
  const int number = layer_number(l.label);
  out << "<g inkscape:groupmode=\"layer\" inkscape:label=\"" << l.label << "\" id=\"layer" << number
      << "\" fill=\"none\" stroke=\"" << layer_colour(number) << "\" stroke-width=\"" << width
      << "\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  const PagePoint page{s};
  PathPoint at{l.start_x, l.start_y, 0};
  bool open = false;
  BlockWriter block(out);
  std::string& text = block.text;
  for (const PathPoint& p : l.path) {
    if (p.pen_down != 0 && !open) {
      text += "<path d=\"M";
      page.append(&text, at);
      text += " L";
      open = true;
    } else if (p.pen_down != 0) {
      text += ' ';
    } else if (open) {
      text += "\"/>\n";
      open = false;
    }
    if (p.pen_down != 0) page.append(&text, p);
    at = p;
    block.maybe_flush();
  }
  if (open) text += "\"/>\n";
  text += "</g>\n";
}

// Millimetres to three decimals (a micrometre), without a locale's comma.
std::string mm_text(double mm) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", mm);
  return buf;
}

}  // namespace

void write_plot_svg(std::ostream& out, const std::vector<PlannedLayer>& layers,
                    const PlotSvgStyle& style) {
  const std::string w = um_text(style.page.width_um), h = um_text(style.page.height_um);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" "
      << "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\"" << w
      << "mm\" height=\"" << h << "mm\" viewBox=\"0 0 " << w << ' ' << h << "\">\n";
  if (style.background)
    out << "<rect x=\"0\" y=\"0\" width=\"" << w << "\" height=\"" << h << "\" fill=\"white\"/>\n";
  for (const PlannedLayer& l : layers) write_layer(out, l, style);
  out << "</svg>\n";
}

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
