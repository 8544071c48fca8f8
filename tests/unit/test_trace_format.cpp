// The step trace (version 2) records the tick's schedule, not its steps: this checks that the
// schedule really is the steps. A plan is run on the core's step tick with a HAL that records
// every pin call itself (tick, motor, direction, pen); the trace written beside it must expand,
// by the simulator's reader and by the independent reader in tests/reference, to exactly those
// calls, on both kinematics, with backlash, the pen servo and an odd steps ratio. A damaged
// trace (one number changed, one line lost) must be refused: its digest no longer matches.
// Also: a long cruise at a fractional interval takes a handful of lines, not one per segment.
#include <sstream>

#include "../check.h"
#include "../reference/trace_checker.h"
#include "../support/test_machine.h"
#include "demo/cube_array.h"
#include "haloplot/motion/step_engine.h"
#include "haloplot/motion/virtual_run.h"
#include "haloplot/trace/traced_queue.h"
#include "sim/simulator.h"
#include "sim/trace.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

std::vector<Edge3> cubes(int n) {
  CubeArrayParams p;
  p.cubes = n;
  return cube_array(p);
}

struct PinCall {
  uint64_t tick;
  uint8_t motor;  // 2: the pen
  bool flag;      // backward, or pen down
  bool operator==(const PinCall& o) const {
    return tick == o.tick && motor == o.motor && flag == o.flag;
  }
};

// Records the pins itself, and hands the same calls to the encoder.
struct PinHal {
  uint64_t now = 0;
  bool backward[2] = {false, false};
  TraceEncoder* trace = nullptr;
  std::vector<PinCall> calls;
  void set_direction(uint8_t m, bool b) { backward[m] = b; }
  void step(uint8_t m) {
    calls.push_back({now, m, backward[m]});
    trace->step(now, m, backward[m]);
  }
  void pen(bool down) {
    calls.push_back({now, 2, down});
    trace->pen(now, down);
  }
};

struct Recorded {
  std::string trace;
  std::vector<PinCall> calls;
  uint64_t end = 0;
};

// The plan's points come from the simulator; the motion runs here on the core alone.
Recorded run_pins(const JobSpec& spec, const std::vector<Edge3>& edges,
                  TraceForm form = TraceForm::kText) {
  SimReport report;
  CHECK(ok(simulate(spec, edges, nullptr, &report)));
  PreparedJob job;
  job.points = report.points.data();
  job.n_points = uint32_t(report.points.size());
  if (spec.finish_home && job.n_points > 0) --job.n_points;  // the report adds the way home
  std::vector<uint8_t> ws(MotionPlanner::workspace_bytes(spec.effects) + 8);
  MotionPlanner planner;
  CHECK(ok(init_planner(&planner, spec, job, ws.data(), ws.size())));
  StepPrep prep;
  CHECK(ok(prep.init(spec.machine, spec.effects)));
  Recorded r;
  const CharSink sink{
      [](void* c, const char* t, uint32_t n) { static_cast<std::string*>(c)->append(t, n); },
      &r.trace};
  TraceEncoder encoder(sink, spec.machine, form);
  PinHal hal;
  hal.trace = &encoder;
  TracedQueue<SegmentQueue<64>> queue;
  queue.set_encoder(&encoder);
  StepEngine<PinHal, TracedQueue<SegmentQueue<64>>> engine(hal, queue);
  CHECK(ok(run_virtual(planner, prep, queue, hal, engine)));
  encoder.finish(hal.now);
  r.calls = std::move(hal.calls);
  r.end = hal.now;
  return r;
}

// The pin calls in the readers' order: by tick, and at one tick motor 0, motor 1, the pen.
std::vector<PinCall> sorted(std::vector<PinCall> c) {
  std::stable_sort(c.begin(), c.end(), [](const PinCall& a, const PinCall& b) {
    return a.tick != b.tick ? a.tick < b.tick : a.motor < b.motor;
  });
  return c;
}

void expands_to_the_pins(const std::string& label, const JobSpec& spec,
                         const std::vector<Edge3>& edges) {
  const Recorded r = run_pins(spec, edges);
  const std::vector<PinCall> pins = sorted(r.calls);
  CHECK_MSG(pins.size() > 1000, label + ": the plan moves");
  // The simulator's reader.
  std::istringstream in(r.trace);
  Trace t;
  const InputError e = read_trace(in, label, &t);
  CHECK_MSG(!e.failed(), label + ": " + e.message());
  std::vector<PinCall> read;
  for (const StepEvent& ev : t.events) read.push_back({ev.tick, ev.motor, ev.flag});
  CHECK_MSG(read == pins, label + ": the simulator's reader expands the trace to the pin calls");
  CHECK_EQ(t.end_tick, r.end);
  // The independent reader.
  const auto x = reference::parse_trace_independently(r.trace);
  CHECK_MSG(x.error.empty(), label + ": " + x.error);
  for (int m = 0; m < 2; ++m) {
    std::vector<int64_t> ticks;
    std::vector<int8_t> dirs;
    for (const PinCall& c : pins)
      if (c.motor == m) ticks.push_back(int64_t(c.tick)), dirs.push_back(c.flag ? -1 : 1);
    CHECK_MSG(x.step_tick[m] == ticks && x.step_dir[m] == dirs,
              label + ": the independent reader gives motor " + std::to_string(m) + "'s steps");
  }
  size_t pens = 0;
  for (const PinCall& c : pins) pens += c.motor == 2;
  CHECK_EQ(x.pen.size(), pens);
  // The binary form of the same run: the same pin calls through the simulator's reader, and
  // fewer bytes.
  const Recorded b = run_pins(spec, edges, TraceForm::kBinary);
  std::istringstream bin(b.trace);
  Trace bt;
  const InputError be = read_trace(bin, label + " (binary)", &bt);
  CHECK_MSG(!be.failed(), be.message());
  std::vector<PinCall> bread;
  for (const StepEvent& ev : bt.events) bread.push_back({ev.tick, ev.motor, ev.flag});
  CHECK_MSG(bread == pins, label + ": the binary trace expands to the pin calls");
  CHECK_EQ(bt.end_tick, r.end);
  CHECK_MSG(b.trace.size() * 2 < r.trace.size(), label + ": binary is under half the text");
  const double steps = double(pins.size() - pens);
  std::printf("%s: %zu pin calls, %zu text bytes (%.2f per step), %zu binary (%.2f)\n",
              label.c_str(), pins.size(), r.trace.size(), double(r.trace.size()) / steps,
              b.trace.size(), double(b.trace.size()) / steps);
}

JobSpec machine(Kinematics k, uint32_t num, uint32_t den, bool backlash) {
  JobSpec s = test_support::test_machine(k, num, den);
  if (backlash) {
    s.effects.backlash = true;
    s.machine.backlash[0] = 7;
    s.machine.backlash[1] = 3;
  }
  return s;
}

void expansion_is_exact() {
  const std::vector<Edge3> scene = cubes(4);
  expands_to_the_pins("corexy 1/1", machine(Kinematics::kCoreXY, 1, 1, false), scene);
  expands_to_the_pins("cartesian 3/2 backlash", machine(Kinematics::kCartesian, 3, 2, true), scene);
  JobSpec flat = machine(Kinematics::kCoreXY, 1, 1, true);
  flat.effects.acceleration = false;
  flat.effects.pen_servo = false;
  expands_to_the_pins("corexy, no ramps, no servo", flat, scene);
}

// One changed number or one lost line breaks the digest (or the schedule's own pen ticks):
// both readers refuse the trace.
void damage_is_refused() {
  const Recorded r = run_pins(machine(Kinematics::kCoreXY, 1, 1, false), cubes(2));
  std::vector<std::string> lines;
  std::istringstream in(r.trace);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  auto refused = [&](const std::vector<std::string>& ls, const std::string& what) {
    std::string text;
    for (const std::string& l : ls) text += l + "\n";
    std::istringstream s(text);
    Trace t;
    CHECK_MSG(read_trace(s, "damaged", &t).failed(), "the simulator's reader refuses " + what);
    const auto x = reference::parse_trace_independently(text);
    reference::Limits lim;
    CHECK_MSG(!reference::check_trace(x, lim).ok, "the independent checker refuses " + what);
  };
  size_t s_line = 0, b_line = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (s_line == 0 && lines[i].rfind("s ", 0) == 0 && i > lines.size() / 2) s_line = i;
    if (b_line == 0 && lines[i].rfind("b ", 0) == 0 && i > lines.size() / 3) b_line = i;
  }
  CHECK(s_line > 0 && b_line > 0);
  {
    auto ls = lines;
    std::istringstream w(ls[s_line]);
    std::string k;
    int64_t count, delta, add;
    w >> k >> count >> delta >> add;
    ls[s_line] =
        "s " + std::to_string(count) + " " + std::to_string(delta + 1) + " " + std::to_string(add);
    refused(ls, "an interval changed by 1/256 tick");
  }
  {
    auto ls = lines;
    ls.erase(ls.begin() + long(s_line));
    refused(ls, "a lost s line");
  }
  {
    auto ls = lines;
    const size_t last = ls[b_line].size() - 1;
    ls[b_line][last] = ls[b_line][last] == '+' ? '-' : '+';
    refused(ls, "a direction flipped");
  }
  // The binary form: a byte changed anywhere in its records, or the trace cut short.
  const Recorded b =
      run_pins(machine(Kinematics::kCoreXY, 1, 1, false), cubes(2), TraceForm::kBinary);
  const size_t data = b.trace.find("data\n") + 5;
  CHECK(data > 5 && data < b.trace.size());
  int missed = 0;
  for (size_t k = 0; k < 50; ++k) {
    std::string damaged = b.trace;
    const size_t at = data + (damaged.size() - data) * (2 * k + 1) / 100;
    damaged[at] = char(damaged[at] ^ (1 << (k % 7)));
    std::istringstream in2(damaged);
    Trace t2;
    missed += !read_trace(in2, "damaged", &t2).failed();
  }
  CHECK_MSG(missed == 0, std::to_string(missed) + " of 50 one-bit changes read as a whole trace");
  {
    std::istringstream in2(b.trace.substr(0, b.trace.size() - 3));
    Trace t2;
    CHECK_MSG(read_trace(in2, "cut", &t2).failed(), "a binary trace cut short is refused");
  }
  // The undamaged trace passes both.
  std::istringstream s(r.trace);
  Trace t;
  CHECK(!read_trace(s, "whole", &t).failed());
}

// A long straight stroke cruises at 3000 steps/s: 333.33 ticks, a fractional interval. The
// cruise must take few lines (a flat ramp goes on while its Q8 interval keeps the time within
// an eighth of a tick of the exact one, then the next one starts), not one per 16-step
// segment: at least 32 events a line.
void cruise_is_few_lines() {
  JobSpec spec = machine(Kinematics::kCartesian, 1, 1, false);
  spec.drawing = DrawingEffect::kAllEdges;
  spec.finish_home = false;
  const Recorded r = run_pins(spec, {Edge3{{0, 0, 0}, {60000, 0, 0}}});
  size_t s_lines = 0, steps = 0;
  std::istringstream in(r.trace);
  for (std::string l; std::getline(in, l);) s_lines += l.rfind("s ", 0) == 0;
  for (const PinCall& c : r.calls) steps += c.motor != 2;
  CHECK_MSG(s_lines * 32 < steps,
            "a cruise of " + std::to_string(steps) + " steps takes " + std::to_string(s_lines) +
                " s lines (one a segment: " + std::to_string(steps / 16) + ")");
}

}  // namespace

int main() {
  expansion_is_exact();
  damage_is_refused();
  cruise_is_few_lines();
  return check::finish("trace_format");
}
