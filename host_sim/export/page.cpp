#include "export/page.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "haloplot/geometry/contract.h"
#include "io/line_reader.h"

namespace haloplot::host {
namespace {

// "210", "215.9", "0.5" mm to thousandths; false if not such a number (up to 3 decimals).
bool parse_um(const std::string& s, int64_t lo, int64_t hi, int64_t* um) {
  const size_t dot = s.find('.');
  const std::string whole = s.substr(0, dot);
  std::string frac = dot == std::string::npos ? "" : s.substr(dot + 1);
  if (frac.size() > 3 || frac.find_first_not_of("0123456789") != std::string::npos ||
      (dot != std::string::npos && frac.empty()))
    return false;
  int64_t w = 0;
  if (whole.empty() || !parse_int(whole, 0, 100000, &w)) return false;
  while (frac.size() < 3) frac += '0';
  *um = w * 1000 + std::stoll(frac);
  return *um >= lo && *um <= hi;
}

bool named_page(const std::string& name, int64_t* w, int64_t* h) {
  struct Named {
    const char* name;
    int64_t w, h;
  };
  static const Named kPages[] = {{"a5", 148000, 210000},    {"a4", 210000, 297000},
                                 {"a3", 297000, 420000},    {"letter", 215900, 279400},
                                 {"legal", 215900, 355600}, {"tabloid", 279400, 431800}};
  std::string lower = name;
  for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
  for (const Named& p : kPages)
    if (lower == p.name) {
      *w = p.w;
      *h = p.h;
      return true;
    }
  const size_t x = lower.find('x');
  return x != std::string::npos && parse_um(lower.substr(0, x), 1000, 10000000, w) &&
         parse_um(lower.substr(x + 1), 1000, 10000000, h);
}

}  // namespace

bool parse_page(const Options& o, Page* page, std::string* error) {
  Page p;
  const std::string name = o.get("--page");
  if (!name.empty() && !named_page(name, &p.width_um, &p.height_um)) {
    *error = "--page '" + name +
             "' must be a4, a3, a5, letter, legal, tabloid or WxH in mm (e.g. 300x200)";
    return false;
  }
  // Named pages are portrait, as vpype's; without --page the default is A4 landscape.
  if (name.empty() || o.has("--landscape")) {
    if (p.width_um < p.height_um) std::swap(p.width_um, p.height_um);
  }
  const std::string margin = o.get("--margin");
  if (!margin.empty() && !parse_um(margin, 0, 10000000, &p.margin_um)) {
    *error = "--margin '" + margin + "' must be a distance in mm (up to three decimals)";
    return false;
  }
  if (2 * p.margin_um >= std::min(p.width_um, p.height_um)) {
    *error = "--margin " + um_text(p.margin_um) + " mm leaves nothing of a " + um_text(p.width_um) +
             " x " + um_text(p.height_um) + " mm page to draw on";
    return false;
  }
  const std::string scale = o.get("--scale");
  if (!scale.empty()) {
    if (o.has("--fit")) {
      *error = "--fit and --scale exclude each other: fit the page, or draw at a scale";
      return false;
    }
    char* end = nullptr;
    p.scale = std::strtod(scale.c_str(), &end);
    if (end != scale.c_str() + scale.size() || !(p.scale > 0) || p.scale > 1e9) {
      *error = "--scale '" + scale + "' must be a positive number (mm on paper per model unit)";
      return false;
    }
  }
  p.placed = o.has("--fit") || !scale.empty();
  *page = p;
  return true;
}

bool page_area(const Page& page, uint32_t steps_per_mm, int32_t* margin, int32_t* width,
               int32_t* height) {
  // The margin rounded up and the far edges down: the drawing stays inside the margins.
  const int64_t m = (page.margin_um * steps_per_mm + 999) / 1000;
  const int64_t w = (page.width_um - page.margin_um) * steps_per_mm / 1000 - m;
  const int64_t h = (page.height_um - page.margin_um) * steps_per_mm / 1000 - m;
  if (w < 1 || h < 1 || m + std::max(w, h) > kCoordMax) return false;
  *margin = int32_t(m);
  *width = int32_t(w);
  *height = int32_t(h);
  return true;
}

void centring_offset(const Page& page, uint32_t steps_per_mm, const std::vector<PathPoint>& path,
                     int32_t* offset_x, int32_t* offset_y) {
  *offset_x = *offset_y = 0;
  int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
  for (size_t i = 1; i < path.size(); ++i) {
    if (path[i].pen_down == 0) continue;
    for (const PathPoint* p : {&path[i - 1], &path[i]}) {
      x0 = std::min<int64_t>(x0, p->x), x1 = std::max<int64_t>(x1, p->x);
      y0 = std::min<int64_t>(y0, p->y), y1 = std::max<int64_t>(y1, p->y);
    }
  }
  int32_t m = 0, w = 0, h = 0;
  if (x0 > x1 || !page_area(page, steps_per_mm, &m, &w, &h)) return;
  // floor((2m + w - (x0 + x1)) / 2): the box's centre to the area's, to the step below.
  const auto shift = [](int64_t lo, int64_t size, int64_t a, int64_t b) {
    const int64_t twice = 2 * lo + size - a - b;
    return int32_t(twice >= 0 ? twice / 2 : -((1 - twice) / 2));
  };
  *offset_x = shift(m, w, x0, x1);
  *offset_y = shift(m, h, y0, y1);
}

std::string um_text(int64_t um) {
  std::string s = std::to_string(um / 1000);
  if (um % 1000 != 0) {
    std::string f = std::to_string(um % 1000);
    f = std::string(3 - f.size(), '0') + f;
    while (f.back() == '0') f.pop_back();
    s += "." + f;
  }
  return s;
}

}  // namespace haloplot::host
