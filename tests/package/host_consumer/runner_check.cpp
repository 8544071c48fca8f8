// The installed motion runner (motion/motion_runner.h) on a fake board written here: a one-shot
// timer whose delays longer than 65,536 ticks run in chunks, STEP/DIR pins that record every
// pulse, a pen, end stops. The interrupts and the main loop are played in turn. Checked against
// the simulator's loop (run_virtual, another driver of the same planner and tick) and against
// facts of the board: each STEP rises only after the runner lowered it, the plot ends where it
// began (finish home, after a feed hold too), an end stop stops the timer at once, an abort
// lifts the pen.
#include <haloplot/controller/motion_runner.h>
#include <haloplot/job/job.h>

#include <cstdio>
#include <vector>

using namespace haloplot;

namespace {

struct Event {  // a step at the plot's time, or a pen change (motor 9)
  uint64_t at;
  uint8_t motor;
  bool backward;
  bool operator==(const Event& o) const {
    return at == o.at && motor == o.motor && backward == o.backward;
  }
};

int failures = 0;
void expect(bool ok, const char* what) {
  if (!ok) std::printf("FAILED: %s\n", what), ++failures;
}

// The fake board: its state is static, as a board's registers are.
struct FakeBoard {
  static constexpr uint32_t kChunk = 65536;  // the timer's reach, ticks
  static inline bool armed = false, high[2] = {false, false}, dir[2] = {false, false};
  static inline bool pen_down = false, enabled = false, pulse_while_high = false;
  static inline uint32_t left = 0;  // ticks of the delay still to run after this interrupt
  static inline int64_t position[2] = {0, 0};
  static inline std::vector<Event>* events = nullptr;
  static inline const uint64_t* now = nullptr;  // the runner's HAL clock, for the record

  static void init() {}
  static void step_high(uint8_t m) {
    if (high[m]) pulse_while_high = true;
    high[m] = true;
    position[m] += dir[m] ? -1 : 1;
    events->push_back(Event{*now, m, dir[m]});
  }
  static void steps_low() { high[0] = high[1] = false; }
  static void set_dir(uint8_t m, bool backward) { dir[m] = backward; }
  static void enable_drivers(bool on) { enabled = on; }
  static void pen_init() {}
  static void pen_set(bool down) {
    pen_down = down;
    events->push_back(Event{*now, 9, down});
  }
  static Status timer_init(TickRate, TimeScale) { return Status::kOk; }
  static void timer_start(uint32_t d) { armed = true, left = d; }
  static void timer_next(uint32_t d) { left = d; }
  static void timer_stop() { armed = false; }
  // Each interrupt runs up to kChunk ticks of the delay; all but the last are chunks.
  static bool timer_chunk_pending() { return left > 0; }
  static void fire() { left = left > kChunk ? left - kChunk : 0; }
};

using Runner = MotionRunner<FakeBoard>;

// Interrupts until the plot ends; service() after every `every` of them (a slow main loop
// lets the queue run dry). `stop_after` > 0: an end stop closes after that many interrupts.
Status run(Runner& r, uint32_t every, uint32_t stop_after = 0, bool abort_it = false) {
  uint32_t fired = 0;
  while (r.running()) {
    if (FakeBoard::armed) {
      FakeBoard::fire();
      r.on_timer();
      ++fired;
      if (stop_after > 0 && fired == stop_after) {
        if (abort_it)
          r.abort();
        else
          r.on_limit(1);
        expect(abort_it || !FakeBoard::armed, "the end stop's interrupt stops the timer");
      }
    }
    if (!FakeBoard::armed || fired % every == 0) r.service();
  }
  return r.result();
}

// The simulator's loop over the same job: its events, stamped with its clock.
struct RecordingHal {
  uint64_t now = 0;
  std::vector<Event>* out;
  bool dir[2] = {false, false};
  void step(uint8_t m) { out->push_back(Event{now, m, dir[m]}); }
  void set_direction(uint8_t m, bool b) { dir[m] = b; }
  void pen(bool down) { out->push_back(Event{now, 9, down}); }
};

}  // namespace

template class haloplot::MotionRunner<FakeBoard>;  // every member compiles from the package

int check_motion_runner() {
  static const Edge3 scene[] = {{{100, 100, 10}, {900, 700, 10}},
                                {{100, 800, 20}, {900, 100, 20}},
                                {{500, 50, 5}, {520, 950, 30}}};
  JobSpec spec;
  spec.draw.halo = 40;
  std::vector<uint64_t> buffer(1 << 14);
  PreparedJob job;
  JobCounters counters;
  if (!ok(job_prepare(spec, Edges{scene, 3}, 64, buffer.data(), buffer.size() * 8, &job,
                      &counters)))
    return 1;

  std::vector<Event> want;
  {
    static uint8_t ws[MotionPlanner::workspace_bytes(PlotterEffects{})];
    MotionPlanner planner;
    StepPrep prep;
    SegmentQueue<64> queue;
    RecordingHal hal{0, &want};
    StepEngine<RecordingHal, SegmentQueue<64>> engine(hal, queue);
    if (!ok(init_planner(&planner, spec, job, ws, sizeof ws)) ||
        !ok(prep.init(spec.machine, spec.effects)) ||
        !ok(run_virtual(planner, prep, queue, hal, engine)))
      return 1;
  }

  static Runner runner;
  FakeBoard::now = &runner.hal().now;
  for (uint32_t every : {1u, 700u}) {  // a main loop in time, and one that falls behind
    std::vector<Event> got;
    FakeBoard::events = &got;
    FakeBoard::position[0] = FakeBoard::position[1] = 0;
    expect(ok(runner.begin(spec, job)) && FakeBoard::enabled, "the plot starts");
    expect(ok(run(runner, every)), "the plot ends kOk");
    expect(got == want, "the runner's steps and pen changes are the simulator's, at its ticks");
    expect(!FakeBoard::armed && !FakeBoard::high[0] && !FakeBoard::high[1],
           "at the end the timer is stopped and STEP is low");
    expect(FakeBoard::position[0] == 0 && FakeBoard::position[1] == 0, "the plot ends home");
    expect((runner.underruns() == 0) == (every == 1), "a slow main loop underruns, a fast one not");
    std::printf("runner: %zu events, %u underruns with service() every %u interrupts\n", got.size(),
                runner.underruns(), every);
  }
  expect(!FakeBoard::pulse_while_high, "each STEP rose only after the runner lowered it");

  {  // feed hold: asked after 300 interrupts, it comes to rest with the pen up and the timer
     // stopped; resumed, the plot ends home
    std::vector<Event> got;
    FakeBoard::events = &got;
    FakeBoard::position[0] = FakeBoard::position[1] = 0;
    expect(ok(runner.begin(spec, job)), "the plot starts for a hold");
    for (uint32_t fired = 0; fired < 300 && FakeBoard::armed; ++fired) {
      FakeBoard::fire();
      runner.on_timer();
      runner.service();
    }
    runner.pause();
    for (uint32_t i = 0; i < 100000 && !runner.paused(); ++i) {
      if (FakeBoard::armed) FakeBoard::fire(), runner.on_timer();
      runner.service();
    }
    expect(runner.paused() && !FakeBoard::armed && !FakeBoard::pen_down, "held at rest, pen up");
    runner.resume();
    expect(ok(run(runner, 1)), "the held plot ends kOk");
    expect(FakeBoard::position[0] == 0 && FakeBoard::position[1] == 0, "the held plot ends home");
    std::printf("runner: hold after %u step events\n", runner.hold_events());
  }
  for (bool abort_it : {false, true}) {
    std::vector<Event> got;
    FakeBoard::events = &got;
    expect(ok(runner.begin(spec, job)), "the plot starts again");
    const Status s = run(runner, 1, 200, abort_it);
    expect(s == (abort_it ? Status::kAborted : Status::kLimitSwitch), "stopped by its cause");
    expect(got.size() < want.size() && !FakeBoard::pen_down && !FakeBoard::armed,
           "a stopped plot ends early, the pen up, the timer stopped");
  }
  return failures == 0 ? 0 : 1;
}
