// A small SVG line chart for benchmark reports (log or linear x), so the reports need no
// plotting package. Converted to PNG by rsvg-convert where it exists.
#pragma once
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace bench {

struct Series {
  std::string name, color;
  std::vector<std::pair<double, double>> points;
};

inline void write_chart(const std::string& path, const std::string& title,
                        const std::string& xlabel, const std::string& ylabel,
                        const std::vector<Series>& series, bool log_x, double y_min = 0) {
  const double W = 720, H = 420, L = 70, R = 20, T = 40, B = 60;
  double x0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& s : series)
    for (auto [x, y] : s.points) {
      const double xv = log_x ? std::log10(x) : x;
      x0 = std::min(x0, xv), x1 = std::max(x1, xv), y1 = std::max(y1, y);
    }
  if (x1 <= x0) x1 = x0 + 1;
  y1 = y1 * 1.1 + 1e-9;
  const double y0 = y_min;
  auto X = [&](double x) {
    return L + ((log_x ? std::log10(x) : x) - x0) / (x1 - x0) * (W - L - R);
  };
  auto Y = [&](double y) { return H - B - (y - y0) / (y1 - y0) * (H - T - B); };
  std::ofstream o(path);
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" "
       "fill=\"white\"/>\n";
  o << "<text x=\"" << W / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << title
    << "</text>\n";
  o << "<line x1=\"" << L << "\" y1=\"" << H - B << "\" x2=\"" << W - R << "\" y2=\"" << H - B
    << "\" stroke=\"black\"/>\n";
  o << "<line x1=\"" << L << "\" y1=\"" << T << "\" x2=\"" << L << "\" y2=\"" << H - B
    << "\" stroke=\"black\"/>\n";
  for (int i = 0; i <= 5; ++i) {  // y ticks
    const double y = y0 + (y1 - y0) * i / 5;
    o << "<text x=\"" << L - 6 << "\" y=\"" << Y(y) + 4 << "\" text-anchor=\"end\">"
      << (std::round(y * 100) / 100) << "</text>\n";
    o << "<line x1=\"" << L << "\" y1=\"" << Y(y) << "\" x2=\"" << W - R << "\" y2=\"" << Y(y)
      << "\" stroke=\"#ddd\"/>\n";
  }
  for (const auto& s : series)  // x ticks at the data points of the first series
    if (&s == &series.front())
      for (auto [x, y] : s.points) {
        (void)y;
        o << "<text x=\"" << X(x) << "\" y=\"" << H - B + 16 << "\" text-anchor=\"middle\">" << x
          << "</text>\n";
      }
  o << "<text x=\"" << (L + W - R) / 2 << "\" y=\"" << H - 18 << "\" text-anchor=\"middle\">"
    << xlabel << "</text>\n";
  o << "<text x=\"16\" y=\"" << (T + H - B) / 2
    << "\" text-anchor=\"middle\" transform=\"rotate(-90 16 " << (T + H - B) / 2 << ")\">" << ylabel
    << "</text>\n";
  int k = 0;
  for (const auto& s : series) {
    o << "<polyline fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\"2\" points=\"";
    for (auto [x, y] : s.points) o << X(x) << ',' << Y(y) << ' ';
    o << "\"/>\n";
    for (auto [x, y] : s.points)
      o << "<circle cx=\"" << X(x) << "\" cy=\"" << Y(y) << "\" r=\"3\" fill=\"" << s.color
        << "\"/>\n";
    o << "<text x=\"" << L + 12 << "\" y=\"" << T + 14 + 16 * k << "\" fill=\"" << s.color << "\">"
      << s.name << "</text>\n";
    ++k;
  }
  o << "</svg>\n";
}

}  // namespace bench
