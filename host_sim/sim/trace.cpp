#include "sim/trace.h"

#include <algorithm>
#include <istream>
#include <ostream>

#include "io/line_reader.h"

namespace haloplot::host {

TraceWriter::TraceWriter(std::ostream& out, const Machine& m)
    : encoder_(CharSink{&write, &out}, m) {}

void TraceWriter::write(void* context, const char* text, uint32_t length) {
  static_cast<std::ostream*>(context)->write(text, length);
}

InputError read_trace(std::istream& in, const std::string& name, Trace* out, uint64_t max_events) {
  *out = Trace{};
  LineReader reader(in);
  std::vector<std::string> f;
  bool header = false, ended = false;
  while (reader.next(&f)) {
    const int line = reader.line();
    int64_t v[5];
    auto bad = [&](const std::string& what) { return InputError{name, line, what}; };
    if (f[0] == "haloplot-trace") {
      if (f.size() != 2 || f[1] != "1") return bad("unsupported trace version");
      header = true;
    } else if (!header) {
      return bad("not a haloplot trace (no 'haloplot-trace 1' line)");
    } else if (f[0] == "tick_hz" && f.size() == 2 && parse_int(f[1], 1, 1 << 30, &v[0])) {
      out->machine.tick_hz = uint32_t(v[0]);
    } else if (f[0] == "kinematics" && f.size() == 2 && (f[1] == "corexy" || f[1] == "cartesian")) {
      out->machine.kinematics = f[1] == "corexy" ? Kinematics::kCoreXY : Kinematics::kCartesian;
    } else if (f[0] == "steps" && f.size() == 2) {
      const size_t slash = f[1].find('/');
      if (slash == std::string::npos || !parse_int(f[1].substr(0, slash), 1, 1024, &v[0]) ||
          !parse_int(f[1].substr(slash + 1), 1, 1024, &v[1]))
        return bad("steps must be N/D");
      out->machine.steps_num = uint32_t(v[0]);
      out->machine.steps_den = uint32_t(v[1]);
    } else if (f[0] == "backlash" && f.size() == 3 && parse_int(f[1], 0, 65535, &v[0]) &&
               parse_int(f[2], 0, 65535, &v[1])) {
      out->machine.backlash[0] = uint32_t(v[0]);
      out->machine.backlash[1] = uint32_t(v[1]);
    } else if (f[0] == "p" && f.size() == 3 && parse_int(f[1], 0, INT64_MAX, &v[0]) &&
               (f[2] == "down" || f[2] == "up")) {
      if (out->events.size() >= max_events)
        return bad("more than " + std::to_string(max_events) + " events: damaged or too large");
      out->events.push_back({uint64_t(v[0]), 2, f[2] == "down"});
    } else if (f[0] == "m" && f.size() == 7 && parse_int(f[1], 0, 1, &v[0]) &&
               parse_int(f[2], 0, INT64_MAX, &v[1]) && parse_int(f[3], 1, INT64_MAX, &v[2]) &&
               parse_int(f[4], -(int64_t(1) << 40), int64_t(1) << 40, &v[3]) &&
               parse_int(f[5], -(int64_t(1) << 40), int64_t(1) << 40, &v[4]) &&
               (f[6] == "+" || f[6] == "-")) {
      if (uint64_t(v[2]) > max_events - out->events.size())
        return bad("more than " + std::to_string(max_events) + " events: damaged or too large");
      // Ticks t0, t0 + dt, t0 + 2 dt + ddt, ...: the gap grows by ddt after each step.
      int64_t t = v[1], gap = v[3];
      for (int64_t i = 0; i < v[2]; ++i) {
        if (t < 0) return bad("a run goes back before tick 0");
        out->events.push_back({uint64_t(t), uint8_t(v[0]), f[6] == "-"});
        t += gap;
        gap += v[4];
      }
    } else if (f[0] == "end" && f.size() == 2 && parse_int(f[1], 0, INT64_MAX, &v[0])) {
      out->end_tick = uint64_t(v[0]);
      ended = true;
    } else {
      return bad("unrecognised trace line '" + excerpt(f[0]) + "'");
    }
  }
  if (!header) return {name, 0, "empty trace"};
  if (!reader.error().empty()) return {name, reader.line(), reader.error()};
  if (!ended) return {name, 0, "the trace has no 'end' line: truncated?"};
  // Time order; at equal ticks motor 0, motor 1, then the pen: the tick steps first and only
  // then moves on to a pen change.
  std::stable_sort(out->events.begin(), out->events.end(),
                   [](const StepEvent& a, const StepEvent& b) {
                     return a.tick != b.tick ? a.tick < b.tick : a.motor < b.motor;
                   });
  return {};
}

}  // namespace haloplot::host
