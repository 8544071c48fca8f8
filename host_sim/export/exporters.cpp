#include "export/exporters.h"

#include <ostream>
#include <string>

#include "geometry/fraction.h"

namespace haloplot::host {

std::string mm_text(int64_t steps, uint32_t per_mm) {
  const int64_t micro = floor_div(steps * 2000 + per_mm, 2 * int64_t(per_mm));  // thousandths
  const bool neg = micro < 0;
  const int64_t a = neg ? -micro : micro;
  std::string frac = std::to_string(a % 1000);
  return (neg ? "-" : "") + std::to_string(a / 1000) + "." + std::string(3 - frac.size(), '0') +
         frac;
}

void write_gcode(std::ostream& out, const std::vector<PathPoint>& path, const Machine& m,
                 const ExportStyle& s) {
  const auto seconds = [&](uint32_t ticks) { return mm_text(ticks, m.tick_hz); };  // 3 places
  const std::string dwell = seconds(m.pen_travel_ticks + m.pen_settle_ticks);
  // Feeds in mm/min.
  const std::string draw_feed = mm_text(int64_t(m.draw_speed) * 60, s.steps_per_mm);
  const std::string travel_feed = mm_text(int64_t(m.travel_speed) * 60, s.steps_per_mm);
  out << "; haloplot G-code\nG21\nG90\n";
  auto pen = [&](bool down) {
    if (s.pen_by_z)
      out << "G1 Z" << mm_text(down ? s.z_down_um : s.z_up_um, 1000) << " F" << travel_feed << '\n';
    else if (down)
      out << "M3 S" << s.pen_down_s << '\n';
    else
      out << "M5\n";
    out << "G4 P" << dwell << '\n';
  };
  pen(false);
  bool down = false;
  for (const PathPoint& p : path) {
    if ((p.pen_down != 0) != down) {
      down = p.pen_down != 0;
      pen(down);
    }
    out << (down ? "G1 X" : "G0 X") << mm_text(int64_t(p.x) + s.offset_x, s.steps_per_mm) << " Y"
        << mm_text(int64_t(p.y) + s.offset_y, s.steps_per_mm) << " F"
        << (down ? draw_feed : travel_feed) << '\n';
  }
  if (down) pen(false);
  out << "M2\n";
}

void write_hpgl(std::ostream& out, const std::vector<PathPoint>& path, const ExportStyle& s) {
  // 40 plotter units per mm: units = steps * 40 / steps_per_mm, rounded.
  const auto unit = [&](int64_t v) {
    return floor_div(v * 80 + s.steps_per_mm, 2 * int64_t(s.steps_per_mm));
  };
  out << "IN;SP1;";
  bool down = false;
  bool open = false;
  for (const PathPoint& p : path) {
    const bool want = p.pen_down != 0;
    if (want != down || !open) {
      out << (open ? ";" : "") << (want ? "PD" : "PU");
      down = want;
      open = true;
    } else {
      out << ',';
    }
    out << unit(int64_t(p.x) + s.offset_x) << ',' << unit(int64_t(p.y) + s.offset_y);
  }
  out << (open ? ";" : "") << "PU;SP0;\n";
}

}  // namespace haloplot::host
