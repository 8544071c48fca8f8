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

namespace {

constexpr int64_t kBig = int64_t(1) << 40;

// Version 2: the tick's schedule, expanded by the tick's rules. Time is a Q8 running sum:
// each event adds the interval register, fires at the floor of the sum over 256, and then the
// register grows by the line's add. The dominant motor steps on every event; the other one
// when Bresenham's error (major / 2 at a b line, plus minor per event) reaches major.
struct ScheduleReplay {
  Trace* out;
  uint64_t max_events;
  uint64_t time_q8 = 0, digest = 0;
  int64_t interval_q8 = 0;
  bool block = false;
  uint8_t dominant = 0;
  bool backward[2] = {false, false};
  uint64_t major = 1, minor = 0, error = 0;

  void emit(uint64_t tick, uint8_t motor, bool flag) {
    out->events.push_back({tick, motor, flag});
    const uint64_t code =
        motor == 2 ? 8 * tick + 4 + (flag ? 1 : 0) : 8 * tick + 2u * motor + (flag ? 1 : 0);
    digest = trace_digest_step(digest, code);
  }
  std::string block_line(const std::vector<std::string>& f) {
    int64_t v[3];
    if (f.size() != 5 || !parse_int(f[1], 0, 1, &v[0]) || !parse_int(f[2], 1, kBig, &v[1]) ||
        !parse_int(f[3], 0, kBig, &v[2]) || f[4].size() != 2 ||
        (f[4][0] != '+' && f[4][0] != '-') || (f[4][1] != '+' && f[4][1] != '-'))
      return "a b line is 'b DOMINANT MAJOR MINOR DIRS'";
    if (v[2] > v[1]) return "a block's MINOR exceeds its MAJOR";
    block = true;
    dominant = uint8_t(v[0]);
    major = uint64_t(v[1]);
    minor = uint64_t(v[2]);
    error = major / 2;
    backward[0] = f[4][0] == '-';
    backward[1] = f[4][1] == '-';
    return {};
  }
  std::string steps_line(const std::vector<std::string>& f) {
    int64_t v[3];
    if (f.size() != 4 || !parse_int(f[1], 1, kBig, &v[0]) || !parse_int(f[2], -kBig, kBig, &v[1]) ||
        !parse_int(f[3], -kBig, kBig, &v[2]))
      return "an s line is 's COUNT DELTA ADD'";
    if (!block) return "an s line before any b line";
    if (uint64_t(v[0]) > max_events - out->events.size())
      return "more than " + std::to_string(max_events) + " events: damaged or too large";
    interval_q8 += v[1];
    for (int64_t i = 0; i < v[0]; ++i) {
      if (interval_q8 <= 0) return "an interval of no time: damaged";
      time_q8 += uint64_t(interval_q8);
      interval_q8 += v[2];
      const uint64_t tick = time_q8 >> 8;
      emit(tick, dominant, backward[dominant]);
      error += minor;
      if (error >= major) {
        error -= major;
        emit(tick, uint8_t(1 - dominant), backward[1 - dominant]);
      }
    }
    return {};
  }
  std::string pen_line(const std::vector<std::string>& f) {
    int64_t v[2];
    if (f.size() != 4 || !parse_int(f[1], 0, INT64_MAX, &v[0]) ||
        (f[2] != "down" && f[2] != "up") || !parse_int(f[3], 0, kBig, &v[1]))
      return "a p line is 'p TICK down|up DWELL'";
    if (uint64_t(v[0]) != time_q8 >> 8)
      return "the pen changes at tick " + f[1] + " but the schedule is at tick " +
             std::to_string(time_q8 >> 8);
    emit(uint64_t(v[0]), 2, f[2] == "down");
    time_q8 += uint64_t(v[1]) * 256;
    return {};
  }
  std::string end_line(const std::vector<std::string>& f) {
    int64_t v[1];
    if (f.size() != 3 || !parse_int(f[1], 0, INT64_MAX, &v[0]))
      return "the end line is 'end TICK DIGEST'";
    if (f[2] != std::to_string(digest)) return "the steps do not match the trace's digest: damaged";
    out->end_tick = uint64_t(v[0]);
    return {};
  }
};

// Version 1: each motor's runs of steps, T0 and gaps growing by DDT.
std::string run_line_v1(const std::vector<std::string>& f, Trace* out, uint64_t max_events) {
  int64_t v[5];
  if (f.size() != 7 || !parse_int(f[1], 0, 1, &v[0]) || !parse_int(f[2], 0, INT64_MAX, &v[1]) ||
      !parse_int(f[3], 1, INT64_MAX, &v[2]) || !parse_int(f[4], -kBig, kBig, &v[3]) ||
      !parse_int(f[5], -kBig, kBig, &v[4]) || (f[6] != "+" && f[6] != "-"))
    return "an m line is 'm MOTOR T0 COUNT DT DDT DIR'";
  if (uint64_t(v[2]) > max_events - out->events.size())
    return "more than " + std::to_string(max_events) + " events: damaged or too large";
  int64_t t = v[1], gap = v[3];
  for (int64_t i = 0; i < v[2]; ++i) {
    if (t < 0) return "a run goes back before tick 0";
    out->events.push_back({uint64_t(t), uint8_t(v[0]), f[6] == "-"});
    t += gap;
    gap += v[4];
  }
  return {};
}

std::string header_line(const std::vector<std::string>& f, Trace* out) {
  int64_t v[2];
  if (f[0] == "tick_hz" && f.size() == 2 && parse_int(f[1], 1, 1 << 30, &v[0])) {
    out->machine.tick_hz = uint32_t(v[0]);
  } else if (f[0] == "kinematics" && f.size() == 2 && (f[1] == "corexy" || f[1] == "cartesian")) {
    out->machine.kinematics = f[1] == "corexy" ? Kinematics::kCoreXY : Kinematics::kCartesian;
  } else if (f[0] == "steps" && f.size() == 2) {
    const size_t slash = f[1].find('/');
    if (slash == std::string::npos || !parse_int(f[1].substr(0, slash), 1, 1024, &v[0]) ||
        !parse_int(f[1].substr(slash + 1), 1, 1024, &v[1]))
      return "steps must be N/D";
    out->machine.steps_num = uint32_t(v[0]);
    out->machine.steps_den = uint32_t(v[1]);
  } else if (f[0] == "backlash" && f.size() == 3 && parse_int(f[1], 0, 65535, &v[0]) &&
             parse_int(f[2], 0, 65535, &v[1])) {
    out->machine.backlash[0] = uint32_t(v[0]);
    out->machine.backlash[1] = uint32_t(v[1]);
  } else {
    return "unrecognised trace line '" + excerpt(f[0]) + "'";
  }
  return {};
}

}  // namespace

InputError read_trace(std::istream& in, const std::string& name, Trace* out, uint64_t max_events) {
  *out = Trace{};
  LineReader reader(in);
  std::vector<std::string> f;
  int version = 0;
  bool ended = false;
  ScheduleReplay replay{out, max_events};
  while (reader.next(&f)) {
    const int line = reader.line();
    std::string why;
    if (ended) {
      why = "a line after the end line";
    } else if (f[0] == "haloplot-trace") {
      if (version != 0 || f.size() != 2 || (f[1] != "1" && f[1] != "2"))
        why = "unsupported trace version (this reader takes 1 and 2)";
      else
        version = f[1] == "1" ? 1 : 2;
    } else if (version == 0) {
      why = "not a haloplot trace (no 'haloplot-trace 2' line)";
    } else if (version == 2 && f[0] == "b") {
      why = replay.block_line(f);
    } else if (version == 2 && f[0] == "s") {
      why = replay.steps_line(f);
    } else if (version == 2 && f[0] == "p") {
      why = replay.pen_line(f);
    } else if (version == 2 && f[0] == "end") {
      why = replay.end_line(f);
      ended = why.empty();
    } else if (version == 1 && f[0] == "m") {
      why = run_line_v1(f, out, max_events);
    } else if (version == 1 && f[0] == "p") {
      int64_t tick;
      if (f.size() != 3 || !parse_int(f[1], 0, INT64_MAX, &tick) ||
          (f[2] != "down" && f[2] != "up"))
        why = "a p line is 'p TICK down|up'";
      else if (out->events.size() >= max_events)
        why = "more than " + std::to_string(max_events) + " events: damaged or too large";
      else
        out->events.push_back({uint64_t(tick), 2, f[2] == "down"});
    } else if (version == 1 && f[0] == "end") {
      int64_t tick;
      if (f.size() != 2 || !parse_int(f[1], 0, INT64_MAX, &tick))
        why = "the end line is 'end TICK'";
      out->end_tick = uint64_t(tick);
      ended = why.empty();
    } else {
      why = header_line(f, out);
    }
    if (!why.empty()) return {name, line, why};
  }
  if (version == 0) return {name, 0, "empty trace"};
  if (!reader.error().empty()) return {name, reader.line(), reader.error()};
  if (!ended) return {name, 0, "the trace has no 'end' line: truncated?"};
  // Time order (version 1 lists runs as they close); at equal ticks motor 0, motor 1, then
  // the pen: the tick steps first and only then moves on to a pen change.
  std::stable_sort(out->events.begin(), out->events.end(),
                   [](const StepEvent& a, const StepEvent& b) {
                     return a.tick != b.tick ? a.tick < b.tick : a.motor < b.motor;
                   });
  return {};
}

}  // namespace haloplot::host
