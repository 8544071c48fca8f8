#include "sim/trace.h"

#include <algorithm>
#include <istream>
#include <ostream>

#include "io/line_reader.h"

namespace haloplot::host {

TraceWriter::TraceWriter(std::ostream& out, const Machine& m, TraceForm form)
    : encoder_(CharSink{&write, &out}, m, form) {}

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
  bool block_seen = false;
  uint8_t dominant = 0;
  bool backward[2] = {false, false};
  uint64_t major = 1, minor = 0, error = 0;

  void emit(uint64_t tick, uint8_t motor, bool flag) {
    out->events.push_back({tick, motor, flag});
    const uint64_t code =
        motor == 2 ? 8 * tick + 4 + (flag ? 1 : 0) : 8 * tick + 2u * motor + (flag ? 1 : 0);
    digest = trace_digest_step(digest, code);
  }
  std::string block(uint8_t dom, uint64_t maj, uint64_t min, bool back0, bool back1) {
    if (dom > 1 || maj == 0 || maj > uint64_t(kBig)) return "a block's MAJOR is out of range";
    if (min > maj) return "a block's MINOR exceeds its MAJOR";
    block_seen = true;
    dominant = dom;
    major = maj;
    minor = min;
    error = major / 2;
    backward[0] = back0;
    backward[1] = back1;
    return {};
  }
  std::string steps(uint64_t count, int64_t delta, int64_t add) {
    if (count == 0 || count > uint64_t(kBig)) return "an s record's COUNT is out of range";
    if (delta < -kBig || delta > kBig || add < -kBig || add > kBig)
      return "an s record's DELTA or ADD is out of range";
    if (!block_seen) return "an s record before any b record";
    if (count > max_events - out->events.size())
      return "more than " + std::to_string(max_events) + " events: damaged or too large";
    interval_q8 += delta;
    for (uint64_t i = 0; i < count; ++i) {
      if (interval_q8 <= 0 || interval_q8 > kBig) return "an interval out of range: damaged";
      time_q8 += uint64_t(interval_q8);
      interval_q8 += add;
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
  std::string pen(uint64_t tick, bool down, uint64_t dwell) {
    if (dwell > uint64_t(kBig)) return "a pen dwell out of range";
    if (tick != time_q8 >> 8)
      return "the pen changes at tick " + std::to_string(tick) + " but the schedule is at tick " +
             std::to_string(time_q8 >> 8);
    if (out->events.size() >= max_events)
      return "more than " + std::to_string(max_events) + " events: damaged or too large";
    emit(tick, 2, down);
    time_q8 += dwell * 256;
    return {};
  }
  std::string end(uint64_t tick, uint64_t trace_digest) {
    if (trace_digest != digest) return "the steps do not match the trace's digest: damaged";
    out->end_tick = tick;
    return {};
  }

  // The text form's lines.
  std::string block_line(const std::vector<std::string>& f) {
    int64_t v[3];
    if (f.size() != 5 || !parse_int(f[1], 0, 1, &v[0]) || !parse_int(f[2], 1, kBig, &v[1]) ||
        !parse_int(f[3], 0, kBig, &v[2]) || f[4].size() != 2 ||
        (f[4][0] != '+' && f[4][0] != '-') || (f[4][1] != '+' && f[4][1] != '-'))
      return "a b line is 'b DOMINANT MAJOR MINOR DIRS'";
    return block(uint8_t(v[0]), uint64_t(v[1]), uint64_t(v[2]), f[4][0] == '-', f[4][1] == '-');
  }
  std::string steps_line(const std::vector<std::string>& f) {
    int64_t v[3];
    if (f.size() != 4 || !parse_int(f[1], 1, kBig, &v[0]) || !parse_int(f[2], -kBig, kBig, &v[1]) ||
        !parse_int(f[3], -kBig, kBig, &v[2]))
      return "an s line is 's COUNT DELTA ADD'";
    return steps(uint64_t(v[0]), v[1], v[2]);
  }
  std::string pen_line(const std::vector<std::string>& f) {
    int64_t v[2];
    if (f.size() != 4 || !parse_int(f[1], 0, INT64_MAX, &v[0]) ||
        (f[2] != "down" && f[2] != "up") || !parse_int(f[3], 0, kBig, &v[1]))
      return "a p line is 'p TICK down|up DWELL'";
    return pen(uint64_t(v[0]), f[2] == "down", uint64_t(v[1]));
  }
  std::string end_line(const std::vector<std::string>& f) {
    int64_t v[1];
    uint64_t d = 0;
    if (f.size() != 3 || !parse_int(f[1], 0, INT64_MAX, &v[0]) || f[2].empty() ||
        f[2].size() > 20 || f[2].find_first_not_of("0123456789") != std::string::npos)
      return "the end line is 'end TICK DIGEST'";
    for (char c : f[2]) d = d * 10 + uint64_t(c - '0');
    return end(uint64_t(v[0]), d);
  }
};

// The binary form's records after the "data" line: a tag byte (low two bits: 0 s, 1 b, 2 p,
// 3 end) and LEB128 varints, signed ones zigzagged. Returns "" or what is wrong, and the
// record's number in *record.
std::string read_binary(std::istream& in, ScheduleReplay* r, uint64_t* record) {
  auto varint = [&](uint64_t* v) {
    *v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      const int c = in.get();
      if (c == EOF) return false;
      *v |= uint64_t(c & 0x7f) << shift;
      if (!(c & 0x80)) return true;
    }
    return false;
  };
  auto signed_of = [](uint64_t z) { return int64_t(z >> 1) ^ -int64_t(z & 1); };
  for (*record = 1;; ++*record) {
    const int tag = in.get();
    if (tag == EOF) return "the trace has no end record: truncated?";
    uint64_t a = 0, b = 0, c = 0;
    std::string why;
    switch (tag & 3) {
      case 0:
        a = uint64_t(tag >> 2);
        if ((a == 0 && !varint(&a)) || !varint(&b) || !varint(&c)) return "a cut-off s record";
        why = r->steps(a, signed_of(b), signed_of(c));
        break;
      case 1:
        if (tag >> 5 || !varint(&a) || !varint(&b)) return "a damaged b record";
        why = r->block(uint8_t(tag >> 2 & 1), a, b, tag >> 3 & 1, tag >> 4 & 1);
        break;
      case 2:
        if (tag >> 3 || !varint(&a) || !varint(&b)) return "a damaged p record";
        why = r->pen(a, tag >> 2 & 1, b);
        break;
      default:
        if (tag != 3 || !varint(&a) || !varint(&b)) return "a damaged end record";
        why = r->end(a, b);
        if (why.empty() && in.get() != EOF) why = "bytes after the end record";
        return why;
    }
    if (!why.empty()) return why;
  }
}

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
  bool ended = false, binary = false;
  ScheduleReplay replay{out, max_events};
  while (reader.next(&f)) {
    const int line = reader.line();
    std::string why;
    if (ended) {
      why = "a line after the end line";
    } else if (f[0] == "haloplot-trace") {
      binary = f.size() == 3 && f[1] == "2" && f[2] == "binary";
      if (version != 0 || !(binary || (f.size() == 2 && (f[1] == "1" || f[1] == "2"))))
        why = "unsupported trace version (this reader takes 1, 2 and 2 binary)";
      else
        version = f[1] == "1" ? 1 : 2;
    } else if (binary && f[0] == "data" && f.size() == 1) {
      uint64_t record = 0;
      why = read_binary(in, &replay, &record);
      if (!why.empty()) return {name, 0, "record " + std::to_string(record) + ": " + why};
      ended = true;
      break;
    } else if (binary) {
      why = header_line(f, out);  // a binary trace's records follow its data line
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
      int64_t tick = 0;
      if (f.size() != 3 || !parse_int(f[1], 0, INT64_MAX, &tick) ||
          (f[2] != "down" && f[2] != "up"))
        why = "a p line is 'p TICK down|up'";
      else if (out->events.size() >= max_events)
        why = "more than " + std::to_string(max_events) + " events: damaged or too large";
      else
        out->events.push_back({uint64_t(tick), 2, f[2] == "down"});
    } else if (version == 1 && f[0] == "end") {
      int64_t tick = 0;
      if (f.size() != 2 || !parse_int(f[1], 0, INT64_MAX, &tick))
        why = "the end line is 'end TICK'";
      else
        out->end_tick = uint64_t(tick), ended = true;
    } else {
      why = header_line(f, out);
    }
    if (!why.empty()) return {name, line, why};
  }
  if (binary && !ended) return {name, 0, "a binary trace with no data line"};
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
