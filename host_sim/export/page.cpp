#include "export/page.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "haloplot/geometry/contract.h"
#include "io/line_reader.h"

namespace haloplot::host {
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
