#include "export/exporters.h"

#include <charconv>
#include <ostream>
#include <string>

#include "haloplot/geometry/fraction.h"

namespace haloplot::host {

void append_thousandths(std::string* out, int64_t v) {
  char buf[32];
  char* const end = buf + sizeof buf;
  char* p = end;
  const bool neg = v < 0;
  uint64_t a = neg ? 0 - uint64_t(v) : uint64_t(v);
  const uint64_t frac = a % 1000;
  a /= 1000;
  *--p = char('0' + frac % 10);
  *--p = char('0' + frac / 10 % 10);
  *--p = char('0' + frac / 100);
  *--p = '.';
  do {
    *--p = char('0' + a % 10);
    a /= 10;
  } while (a != 0);
  if (neg) *--p = '-';
  out->append(p, size_t(end - p));
}

void append_int(std::string* out, int64_t v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out->append(buf, size_t(r.ptr - buf));
}

void append_mm(std::string* out, int64_t steps, uint32_t per_mm) {
  append_thousandths(out, floor_div(steps * 2000 + per_mm, 2 * int64_t(per_mm)));
}

std::string mm_text(int64_t steps, uint32_t per_mm) {
  std::string s;
  append_mm(&s, steps, per_mm);
  return s;
}

void BlockWriter::flush() {
  out_.write(text.data(), std::streamsize(text.size()));
  text.clear();
}

bool apply_feeds(const ExportStyle& s, Machine* m, std::string* error) {
  const auto speed = [&](int64_t feed_milli, const char* name, uint32_t* out) {
    if (feed_milli == 0) return true;
    // mm/min to plot steps/s: feed / 1000 * steps_per_mm / 60, rounded to the nearest.
    const int64_t v = (feed_milli * s.steps_per_mm + 30000) / 60000;
    if (v < 1 || v > 65535) {
      *error = std::string(name) + " " + mm_text(feed_milli, 1000) + " mm/min is " +
               std::to_string(v) + " steps/s at " + std::to_string(s.steps_per_mm) +
               " steps/mm: the machine takes 1 to 65535";
      return false;
    }
    *out = uint32_t(v);
    return true;
  };
  return speed(s.draw_feed_milli, "draw-feed", &m->draw_speed) &&
         speed(s.travel_feed_milli, "travel-feed", &m->travel_speed);
}

namespace {

// Where each non-empty layer starts in the path (its first point) and its number (1 for
// the first kind), when the style asks for pen changes; else nothing.
std::vector<std::pair<size_t, int>> layer_starts(const LayerCounts& layers, const ExportStyle& s) {
  std::vector<std::pair<size_t, int>> starts;
  if (!s.pause_between_layers) return starts;
  size_t at = 0;
  for (uint32_t k = 0; k < layers.n && k < kMaxLayers; ++k) {
    if (layers.count[k] > 0) starts.push_back({at, int(k) + 1});
    at += layers.count[k];
  }
  return starts;
}

// The G-code lines that lower or lift the pen, by the style's profile and dialect. `dwell_ms`:
// the machine's pen travel and settle time.
std::string pen_gcode(const ExportStyle& s, bool down, int64_t dwell_ms) {
  std::string t;
  if (s.pen == PenProfile::kZ) {
    if (down)
      t = "G1 Z" + mm_text(s.z_down_um, 1000) + " F" + mm_text(s.z_feed_milli, 1000) + '\n';
    else
      t = "G0 Z" + mm_text(s.z_up_um, 1000) + '\n';
    return t;
  }
  if (s.pen == PenProfile::kCustom) {
    const std::string& text = down ? s.pen_down_text : s.pen_up_text;
    return text.empty() ? t : text + '\n';
  }
  if (s.flavor == GcodeFlavor::kMarlin) {
    t = "M400\nM280 P0 S";
    append_int(&t, down ? s.pen_down_s : s.servo_up_angle);
    t += "\nG4 P";
    append_int(&t, dwell_ms);
  } else {
    t = down ? "M3 S" + std::to_string(s.pen_down_s) + "\nG4 P" : std::string("M5\nG4 P");
    append_thousandths(&t, dwell_ms);
  }
  return t + '\n';
}

}  // namespace

void write_gcode(std::ostream& out, const std::vector<PathPoint>& path, const Machine& m,
                 const ExportStyle& s, const LayerCounts& layers) {
  // Milliseconds, rounded to the nearest: grbl writes them as seconds to three places.
  const int64_t dwell_ms =
      floor_div((int64_t(m.pen_travel_ticks) + m.pen_settle_ticks) * 2000 + m.tick_hz,
                2 * int64_t(m.tick_hz));
  // Feeds in mm/min: as given, or the machine's speeds.
  const auto feed = [&](int64_t given, uint32_t speed) {
    return given != 0 ? mm_text(given, 1000) : mm_text(int64_t(speed) * 60, s.steps_per_mm);
  };
  const std::string draw_feed = feed(s.draw_feed_milli, m.draw_speed);
  const std::string travel_feed = feed(s.travel_feed_milli, m.travel_speed);
  const std::string pen_up = pen_gcode(s, false, dwell_ms), pen_down = pen_gcode(s, true, dwell_ms);
  out << "; haloplot G-code\nG21\nG90\n";
  if (!s.header_text.empty()) out << s.header_text << '\n';
  out << pen_up;
  bool down = false;
  const std::vector<std::pair<size_t, int>> starts = layer_starts(layers, s);
  size_t next = 1;         // the first layer needs no change
  BlockWriter block(out);  // the moves; written out before any pen command
  std::string& text = block.text;
  for (size_t i = 0; i < path.size(); ++i) {
    const PathPoint& p = path[i];
    const bool change = next < starts.size() && i == starts[next].first;
    if (change || (p.pen_down != 0) != down) block.flush();
    if (change) {
      if (down) out << pen_up;
      down = false;
      out << "; layer " << starts[next++].second << ": change the pen, then resume\nM0\n";
    }
    if ((p.pen_down != 0) != down) {
      down = p.pen_down != 0;
      out << (down ? pen_down : pen_up);
    }
    text += down ? "G1 X" : "G0 X";
    append_mm(&text, int64_t(p.x) + s.offset_x, s.steps_per_mm);
    text += " Y";
    append_mm(&text, int64_t(p.y) + s.offset_y, s.steps_per_mm);
    text += " F";
    text += down ? draw_feed : travel_feed;
    text += '\n';
    block.maybe_flush();
  }
  block.flush();
  if (down) out << pen_up;
  if (!s.footer_text.empty()) out << s.footer_text << '\n';
  if (s.flavor == GcodeFlavor::kGrbl) out << "M2\n";
}

void write_hpgl(std::ostream& out, const std::vector<PathPoint>& path, const ExportStyle& s,
                const LayerCounts& layers) {
  // 40 plotter units per mm: units = steps * 40 / steps_per_mm, rounded.
  const auto unit = [&](int64_t v) {
    return floor_div(v * 80 + s.steps_per_mm, 2 * int64_t(s.steps_per_mm));
  };
  BlockWriter block(out);
  std::string& text = block.text;
  text += "IN;SP1;";
  bool down = false;
  bool open = false;
  const std::vector<std::pair<size_t, int>> starts = layer_starts(layers, s);
  size_t next = 0;
  int pen = 1;
  for (size_t i = 0; i < path.size(); ++i) {
    const PathPoint& p = path[i];
    if (next < starts.size() && i == starts[next].first) {
      if (starts[next].second != pen) {
        pen = starts[next].second;
        text += open ? ";" : "";
        text += down ? "PU;" : "";
        text += "SP";
        append_int(&text, pen);
        text += ';';
        open = down = false;
      }
      ++next;
    }
    const bool want = p.pen_down != 0;
    if (want != down || !open) {
      text += open ? ";" : "";
      text += want ? "PD" : "PU";
      down = want;
      open = true;
    } else {
      text += ',';
    }
    append_int(&text, unit(int64_t(p.x) + s.offset_x));
    text += ',';
    append_int(&text, unit(int64_t(p.y) + s.offset_y));
    block.maybe_flush();
  }
  text += open ? ";" : "";
  text += "PU;SP0;\n";
}

}  // namespace haloplot::host
