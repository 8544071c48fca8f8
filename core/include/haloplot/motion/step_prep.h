// Step preparation (main loop, not the interrupt): turns each motion item into step segments
// of at most kSegmentSteps dominant steps.
//
// Timing is exact at segment boundaries: the time of dominant step j of a move comes from the
// closed-form trapezoid (t = (v(s) - v_in) / a with v(s) = sqrt(v_in^2 + 2 a s) while
// accelerating, s / v while cruising, and the mirror image while braking), evaluated in Q8
// ticks with integer square roots. Inside a segment the tick interpolates with a linear
// interval change. The prep mirrors the tick's arithmetic exactly, so each segment aims at
// the exact boundary time from where the tick really is: timing error never accumulates.
//
// Budget: tick_hz < 2^24 (validated), speeds Q8 < 2^24, so speed * tick_hz < 2^48; distances
// along a move are Q16 (< 2^37: moves < 2^21 steps), so distance * tick_hz < 2^61 and
// 2 * accel * distance < 2^60 (accel < 2^22).
#pragma once
#include <stdint.h>

#include "haloplot/motion/machine.h"
#include "haloplot/motion/planner.h"
#include "haloplot/motion/step_segment.h"
#include "haloplot/status/status.h"

namespace haloplot {

struct PrepCounters {
  uint64_t segments = 0;
  uint64_t blocks = 0;
  uint64_t backlash_takeups = 0;  // backlash effect
  uint64_t motor_steps[2] = {0, 0};
  uint64_t holds = 0;  // feed holds that came to rest
};

class StepPrep {
 public:
  static constexpr uint32_t kSegmentSteps = 16;

  Status init(const Machine& m, const PlotterEffects& fx);

  // Push segments until the queue is full or the plan is done. A move whose step interval
  // would fall below the timer floor is rejected with kTimerFloor.
  template <typename Queue>
  Status fill(MotionPlanner& planner, Queue& queue) {
    while (!queue.full()) {
      StepSegment s;
      bool have = false;
      const Status st = next_segment(planner, &s, &have);
      if (!ok(st)) return st;
      if (!have) break;
      queue.push(s);
    }
    return Status::kOk;
  }
  // Push at most one segment (*pushed says whether one was): skip_events() keeps one segment
  // in flight, so the prep's last segment is the one the tick is in.
  template <typename Queue>
  Status fill_one(MotionPlanner& planner, Queue& queue, bool* pushed) {
    StepSegment s;
    *pushed = false;
    const Status st = next_segment(planner, &s, pushed);
    if (ok(st) && *pushed) queue.push(s);
    return st;
  }
  // Resume a plot where an earlier run of it stopped (an abort, a reset), after the tick has
  // made that run's events again with no motor moving (motion/virtual_run.h skip_events):
  // `remaining` events of the last segment were not made, and the motors were at `motors`.
  // From the origin, at rest and pen up (a controller after a reset), travel there pen up,
  // lower the pen if it was down, and go on with the rest of the move from rest, as after a
  // feed hold.
  void restart_at(uint32_t remaining, const int32_t motors[2]);
  bool in_takeup() const { return last_takeup_; }  // the last segment took up backlash
  bool done() const { return done_; }
  const PrepCounters& counters() const { return counters_; }

  // Feed hold (pause), grbl's cycle stop. hold(): from the end of the segments already
  // queued, brake at the machine's acceleration to rest (over as many moves as that takes),
  // lift the pen if it is down, and push nothing more: held() is then true. resume(): lower
  // the pen where it was lifted and go on from rest with the rest of the move; the planner's
  // next entry speed is lowered to what the rest of the move can reach from rest. A move is
  // split at a motor step (the Bresenham position of the dominant step where the braking
  // ends); the braking stretch keeps the move's block and Bresenham rhythm, the rest runs its
  // own straight line from rest between exact step positions: the pen path stays within a
  // step of the unpaused one. Latency: the queued segments run first.
  void hold();
  void resume();
  bool holding() const { return hold_ != Hold::kNone; }  // requested, braking or held
  bool held() const { return hold_ == Hold::kHeld; }
  uint64_t engine_time_q8() const { return time_q8_; }

 private:
  // kTravel: restart_at()'s travel to where the plot stopped; then kResume.
  enum class Hold : uint8_t { kNone, kRequested, kBraking, kHeld, kResume, kTravel };
  Status next_segment(MotionPlanner& planner, StepSegment* out, bool* have);
  uint64_t speed2_at(uint32_t j) const;             // the profile's v^2 (Q8) at dominant step j
  uint64_t distance_q16(uint32_t j) const;          // plot distance of dominant step j, Q16
  MotionItem part(uint32_t j0, uint32_t j1) const;  // dominant steps (j0, j1] of the move
  void brake(uint64_t v2);                          // begin braking from step j_ at speed^2 v2
  void pen_segment(bool down, StepSegment* out);
  void resume_move(MotionPlanner& planner, StepSegment* out, bool* have);
  MotionItem travel(const int32_t delta[2]) const;  // pen up, rest to rest
  void begin_move(const MotionItem& item);
  void set_profile(uint64_t entry_v2, uint64_t top_v2, uint64_t exit_v2, uint32_t j0,
                   uint32_t j_end);
  uint32_t minor_at(uint32_t j) const;       // the other motor's steps after dominant step j
  uint64_t block_time_q8(uint32_t j) const;  // time of dominant step j from the block start
  void advance_time(uint32_t events, int64_t interval, int64_t add);
  int64_t interval_at(uint32_t j) const;  // the exact interval before dominant step j (1-based)
  bool fits(uint32_t j1, int64_t first, int64_t add) const;  // close enough to the exact times?
  void choose_ramp(uint32_t* j1, int64_t* first, int64_t* add) const;  // the next segment
  // next_segment()'s three kinds of segment, each written to *out.
  void planned_pen(const MotionItem& it, StepSegment* out);
  Status takeup_segment(uint8_t motor, StepSegment* out);  // a motor's backlash, from rest
  Status steps_segment(StepSegment* out);                  // the move's next ramp

  Machine m_ = kUnsetMachine;  // init() sets both; zero until then (machine.h)
  PlotterEffects fx_ = kUnsetEffects;
  MotionItem item_{};
  bool in_move_ = false, done_ = false, takeup_pending_[2] = {false, false};
  bool first_segment_ = false;
  bool last_backward_[2] = {false, false};
  uint32_t n_ = 0, j_ = 0;  // dominant steps in the move, steps prepared
  uint8_t dominant_ = 0, dir_bits_ = 0;
  uint32_t minor_ = 0;

  uint64_t block_start_q8_ = 0;  // tick time (Q8) the speed profile starts at
  // The speed profile runs over dominant steps [prof_j0_, end_j_] (all of the move, or a feed
  // hold's braking stretch), from plot distance prof_s0_q16_, and ends at prof_exit2_.
  uint32_t prof_j0_ = 0, end_j_ = 0;
  uint64_t prof_s0_q16_ = 0, prof_exit2_ = 0;
  uint64_t time_q8_ = 0;              // where the tick's clock will be after the pushed segments
  int64_t reg_q8_ = 0, reg_add_ = 0;  // the tick's interval and add after the last segment
  // Trapezoid of the current move, in plot-path units (see planner.h).
  uint64_t vin_q8_ = 0, vtop_q8_ = 0, vtop2_ = 0, entry2_ = 0;
  uint64_t s_acc_q8_ = 0, s_dec_q8_ = 0, t_acc_q8_ = 0, t_dec_q8_ = 0;
  PrepCounters counters_{};
  // Feed hold: its state, the speed^2 the braking part ends at, the rest of the split move,
  // and whether the hold lifted the pen.
  Hold hold_ = Hold::kNone;
  uint64_t brake_exit2_ = 0, last_exit2_ = 0;  // last_exit2_: where the last move ended
  MotionItem rest_{};
  bool have_rest_ = false, lifted_ = false, pen_down_ = false, last_takeup_ = false;
};

}  // namespace haloplot
