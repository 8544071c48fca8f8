#include "haloplot/motion/step_prep.h"

#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/wide.h"

namespace haloplot {
namespace {

bool within_tick(int64_t a, int64_t b) { return (a > b ? a - b : b - a) <= 128; }  // Q8
// How far a ramp that goes on may let the time drift from the exact profile before it is
// re-aimed (Q8): an eighth of a tick, so a cruise stays symmetric to within a step.
constexpr int64_t kDrift = 32;
uint32_t abs32(int32_t v) { return v < 0 ? uint32_t(0) - uint32_t(v) : uint32_t(v); }
uint64_t speed_q8(uint64_t v2_q8) { return isqrt_u64(v2_q8 << 8); }  // sqrt(v^2 * 2^16)

// The bit budget of block_time_q8() (see step_prep.h): init() refuses tick_hz >= 2^24,
// validate() accel >= 2^22, and the planner keeps a move below 2^21 plot steps (Q16: 2^37).
constexpr uint64_t kTickHzLimit = uint64_t{1} << 24, kAccelLimit = uint64_t{1} << 22;
constexpr uint64_t kDistanceQ16Limit = uint64_t{1} << 37;
static_assert(kDistanceQ16Limit <= UINT64_MAX / kTickHzLimit, "distance * tick_hz fits");
static_assert(kDistanceQ16Limit <= UINT64_MAX / (2 * kAccelLimit), "2 * accel * distance fits");

}  // namespace

Status StepPrep::init(const Machine& m, const PlotterEffects& fx) {
  const Status s = validate(m);
  if (!ok(s)) return s;
  if (m.tick_hz >= kTickHzLimit) return Status::kBadParameter;
  *this = StepPrep{};
  m_ = m;
  fx_ = fx;
  return Status::kOk;
}

void StepPrep::advance_time(uint32_t events, int64_t interval, int64_t add) {
  // Exactly what the tick does: events times "time += interval; interval += add".
  const int64_t e = events;
  time_q8_ += uint64_t(e * interval + add * (e * (e - 1) / 2));
}

void StepPrep::begin_move(const MotionItem& it) {
  item_ = it;
  const uint32_t a0 = abs32(it.delta[0]), a1 = abs32(it.delta[1]);
  dominant_ = a0 >= a1 ? 0 : 1;
  n_ = dominant_ == 0 ? a0 : a1;
  minor_ = dominant_ == 0 ? a1 : a0;
  dir_bits_ = uint8_t((it.delta[0] < 0 ? 1 : 0) | (it.delta[1] < 0 ? 2 : 0));
  j_ = 0;
  first_segment_ = true;
  ++counters_.blocks;
  // Backlash: a motor that reverses first takes up its slack (the planner stopped there).
  for (uint8_t mo = 0; mo < 2; ++mo) {
    const bool moves = it.delta[mo] != 0, backward = it.delta[mo] < 0;
    takeup_pending_[mo] =
        fx_.backlash && moves && backward != last_backward_[mo] && m_.backlash[mo] > 0;
    if (moves) last_backward_[mo] = backward;
  }
  set_profile(it.entry_v2, it.top_v2, it.exit_v2, 0, n_);
}

// The speed profile over dominant steps [j0, j_end] of the move, timed from the tick's clock
// now: a trapezoid from entry to exit over that stretch's plot length (all of the move, or the
// braking stretch of a feed hold). With acceleration off it runs at its top speed throughout.
void StepPrep::set_profile(uint64_t entry_v2, uint64_t top_v2, uint64_t exit_v2, uint32_t j0,
                           uint32_t j_end) {
  prof_j0_ = j0;
  end_j_ = j_end;
  prof_s0_q16_ = distance_q16(j0);
  prof_exit2_ = exit_v2;
  block_start_q8_ = time_q8_;
  const uint64_t l = (distance_q16(j_end) - prof_s0_q16_ + 255) >> 8;  // Q8, rounded up
  const uint64_t a = item_.accel;
  entry2_ = entry_v2;
  vtop2_ = top_v2;
  if (a > 0) {
    const uint64_t two_a_l = 2ull * a * l;
    const uint64_t peak2 = (two_a_l + entry_v2 + exit_v2) / 2;
    if (peak2 < vtop2_) vtop2_ = peak2;
    if (vtop2_ < entry2_) vtop2_ = entry2_;
    vin_q8_ = speed_q8(entry2_);
    vtop_q8_ = speed_q8(vtop2_);
    s_acc_q8_ = (vtop2_ - entry2_) / (2ull * a);
    const uint64_t exit2 = exit_v2 < vtop2_ ? exit_v2 : vtop2_;
    const uint64_t brake = (vtop2_ - exit2) / (2ull * a);
    s_dec_q8_ = brake < l ? l - brake : 0;
    if (s_acc_q8_ > s_dec_q8_) s_acc_q8_ = s_dec_q8_;
    t_acc_q8_ = (vtop_q8_ - vin_q8_) * m_.tick_hz / a;
    t_dec_q8_ = t_acc_q8_ + (s_dec_q8_ - s_acc_q8_) * m_.tick_hz * 256 / vtop_q8_;
  } else {
    vtop_q8_ = speed_q8(vtop2_);
  }
}

uint64_t StepPrep::block_time_q8(uint32_t j) const {
  // Plot distance of dominant step j in Q16: a Q8 distance is off by up to 1/256 step, which
  // at 3,000 steps/s moves a step by 1.3 ticks and shows as one-step speed jitter; in Q16 the
  // time is off by well under a tick at any speed.
  const uint64_t s = distance_q16(j) - prof_s0_q16_;
  const uint64_t hz = m_.tick_hz;
  if (item_.accel == 0) return s * hz / vtop_q8_;
  const uint64_t a = item_.accel;
  const uint64_t s_acc = s_acc_q8_ << 8, s_dec = s_dec_q8_ << 8;
  if (s <= s_acc) return (speed_q8(entry2_ + ((2 * a * s + 128) >> 8)) - vin_q8_) * hz / a;
  if (s <= s_dec) return t_acc_q8_ + (s - s_acc) * hz / vtop_q8_;
  const uint64_t drop = (2 * a * (s - s_dec) + 128) >> 8;
  const uint64_t v2 = drop < vtop2_ ? vtop2_ - drop : 0;
  return t_dec_q8_ + (vtop_q8_ - speed_q8(v2)) * hz / a;
}

uint64_t StepPrep::distance_q16(uint32_t j) const {
  const uint64_t jl = uint64_t(j) * item_.length_q8;  // j <= n < 2^32, length < 2^32
  return ((jl / n_) << 8) + ((jl % n_) << 8) / n_;
}

// The same phases as block_time_q8(), as speeds: v^2 = v_in^2 + 2 a s while accelerating, the
// top speed while cruising, v_top^2 - 2 a (s - s_dec) while braking.
uint64_t StepPrep::speed2_at(uint32_t j) const {
  if (item_.accel == 0 || n_ == 0) return vtop2_;
  const uint64_t s = distance_q16(j) - prof_s0_q16_, a = item_.accel;
  const uint64_t s_acc = s_acc_q8_ << 8, s_dec = s_dec_q8_ << 8;
  if (s <= s_acc) return entry2_ + ((2 * a * s + 128) >> 8);
  if (s <= s_dec) return vtop2_;
  const uint64_t drop = (2 * a * (s - s_dec) + 128) >> 8;
  return drop < vtop2_ ? vtop2_ - drop : 0;
}

int64_t StepPrep::interval_at(uint32_t j) const {
  return int64_t(block_time_q8(j) - (j > prof_j0_ + 1 ? block_time_q8(j - 1) : 0));
}

// Does the ramp (first, add) from where the tick is to step j1 stay as close to the exact
// profile as an aimed segment would? Its end within kDrift (1/8 tick) of the exact time, so
// timing error cannot accumulate, and its first, middle and last intervals within half a tick
// of the exact ones.
bool StepPrep::fits(uint32_t j1, int64_t first, int64_t add) const {
  const int64_t k = j1 - j_, half = (k - 1) / 2;
  const int64_t end = int64_t(time_q8_) + k * first + add * (k * (k - 1) / 2);
  const int64_t exact_end = int64_t(block_start_q8_ + block_time_q8(j1));
  const int64_t drift = end > exact_end ? end - exact_end : exact_end - end;
  return drift <= kDrift && within_tick(first, interval_at(j_ + 1)) &&
         within_tick(first + half * add, interval_at(j_ + 1 + uint32_t(half))) &&
         within_tick(first + (k - 1) * add, interval_at(j1));
}

// Segment length: up to kSegmentSteps, halved until the tick's linear interval ramp follows
// the exact profile (near rest, where t grows like sqrt(j), segments shrink to single, exact
// steps). The ramp starts at the exact first interval and is aimed at the exact end time; it
// must also end within a tick of the exact last interval and pass within a tick of the exact
// middle one. Otherwise the next segment, which starts at its exact interval again, would
// jump: a short move that peaks inside one segment has equal first and last intervals, yet a
// V-shaped profile no ramp can follow.
//
// Two simpler ramps come first when they fit as well: the last segment's ramp going on (same
// interval register, same add), then, where the exact intervals are level (a cruise: they
// differ by a Q8 rounding at most), a flat one (add 0, the mean interval). A cruise at a
// fractional interval (67.5 ticks) is then one flat ramp going on for as long as its Q8
// interval keeps the time within 1/8 tick of the exact one (50 to 100 events), instead of a
// segment re-aimed at every boundary (67, 68, 67, ...), and a trace writes it as one line.
void StepPrep::choose_ramp(uint32_t* j1_out, int64_t* first_out, int64_t* add_out) const {
  uint32_t j1 = j_ + kSegmentSteps < end_j_ ? j_ + kSegmentSteps : end_j_;
  *j1_out = j1;
  if (!first_segment_ && fits(j1, reg_q8_, reg_add_)) {
    *first_out = reg_q8_, *add_out = reg_add_;
    return;
  }
  const int64_t k1 = j1 - j_;
  const int64_t span = int64_t(block_start_q8_ + block_time_q8(j1)) - int64_t(time_q8_);
  const int64_t mean = floor_div(2 * span + k1, 2 * k1);       // rounded
  const int64_t rise = interval_at(j1) - interval_at(j_ + 1);  // a cruise: at most 1 either way
  if (k1 == int64_t{kSegmentSteps} && rise >= -1 && rise <= 1 && fits(j1, mean, 0)) {
    *first_out = mean, *add_out = 0;
    return;
  }
  const int64_t first = int64_t(block_start_q8_ + block_time_q8(j_ + 1)) - int64_t(time_q8_);
  auto ramp_add = [&](uint32_t end) {  // the ramp's step from `first` to the end time
    const int64_t k = end - j_;
    const int64_t total = int64_t(block_start_q8_ + block_time_q8(end)) - int64_t(time_q8_);
    return k > 1 ? floor_div(2 * (total - k * first), k * (k - 1)) : 0;
  };
  int64_t add = ramp_add(j1);
  while (j1 > j_ + 1) {
    const int64_t k = j1 - j_, half = (k - 1) / 2;
    if (within_tick(first + (k - 1) * add, interval_at(j1)) &&
        within_tick(first + half * add, interval_at(j_ + 1 + uint32_t(half))))
      break;
    j1 = j_ + (j1 - j_) / 2;
    add = ramp_add(j1);
  }
  *j1_out = j1, *first_out = first, *add_out = add;
}

void StepPrep::hold() {
  if (hold_ == Hold::kNone && !done_) hold_ = Hold::kRequested;
}

void StepPrep::resume() {
  if (hold_ == Hold::kHeld) hold_ = Hold::kResume;
}

// Dominant steps (j0, j1] of the current move as a move of its own: the motor steps between
// the tick's Bresenham positions there (the other motor has made (n/2 + j * minor) / n steps
// after j events, engine's error starting at n/2), its plot length in proportion.
uint32_t StepPrep::minor_at(uint32_t j) const {
  return n_ == 0 ? 0 : uint32_t((n_ / 2 + uint64_t(j) * minor_) / n_);
}

MotionItem StepPrep::part(uint32_t j0, uint32_t j1) const {
  const int32_t major = int32_t(j1 - j0), minor = int32_t(minor_at(j1) - minor_at(j0));
  MotionItem it = item_;
  const int32_t d[2] = {dominant_ == 0 ? major : minor, dominant_ == 0 ? minor : major};
  for (uint8_t mo = 0; mo < 2; ++mo) it.delta[mo] = (dir_bits_ >> mo) & 1u ? -d[mo] : d[mo];
  const uint64_t len_q16 = distance_q16(j1) - distance_q16(j0);
  it.length_q8 = uint32_t((len_q16 + 255) >> 8);  // rounded up: never shorter than the braking
  return it;
}

// Brake from step j_ at speed^2 v2: the stopping distance v^2 / 2a, rounded up to the next
// dominant step. Within this move, the move splits there: a braking stretch from v to rest, and
// the rest (from rest, to the move's own exit) kept for resume(). Past its end, the whole move
// brakes and the next one goes on braking from where it ends (brake_exit2_). The braking
// stretch stays in the move's block, only its speed profile changes: the engine's Bresenham
// goes on, so the other motor keeps its rhythm (a block of its own would restart it at half a
// step and move that motor's next step by up to a step's time: a speed jump at one step).
void StepPrep::brake(uint64_t v2) {
  hold_ = Hold::kBraking;
  const uint32_t j0 = j_;
  uint32_t j_stop = j0;
  if (item_.accel > 0 && v2 > 0) {
    const uint64_t stop_q16 =
        distance_q16(j0) + (v2 * 256 + 2 * item_.accel - 1) / (2 * item_.accel);
    const uint64_t total_q16 = uint64_t{item_.length_q8} << 8;
    j_stop = stop_q16 >= total_q16 ? n_ : uint32_t((stop_q16 * n_ + total_q16 - 1) / total_q16);
    if (j_stop < j0) j_stop = j0;
  }
  have_rest_ = j_stop < n_;
  if (have_rest_) {
    rest_ = part(j_stop, n_);
    rest_.entry_v2 = 0;
  }
  if (j_stop == j0) {
    // At rest already, or no acceleration modelled: stop here. At the move's very end at
    // speed: go on braking in the next move.
    brake_exit2_ = item_.accel > 0 && j0 == n_ ? v2 : 0;
    if (j0 < n_) counters_.motor_steps[1 - dominant_] += minor_at(j0);
    in_move_ = false;
    return;
  }
  const uint64_t len_q8 = (distance_q16(j_stop) - distance_q16(j0) + 255) >> 8;
  const uint64_t fall = 2ull * item_.accel * len_q8;
  brake_exit2_ = have_rest_ || fall >= v2 ? 0 : v2 - fall;
  set_profile(v2, v2, brake_exit2_, j0, j_stop);
}

void StepPrep::pen_segment(bool down, StepSegment* out) {
  out->kind = StepSegment::kPen;
  out->pen_down = down;
  out->dwell_ticks = fx_.pen_servo ? m_.pen_travel_ticks + m_.pen_settle_ticks : 0;
  time_q8_ += uint64_t{out->dwell_ticks} * 256;
  pen_down_ = down;
  last_takeup_ = false;
  ++counters_.segments;
}

// Resume after a hold: the pen down where the hold lifted it, then the rest of the split move
// from rest. Its exit may be more than it can reach from rest: the planner's next entry is
// lowered to match (and so every later one that needs it).
void StepPrep::resume_move(MotionPlanner& planner, StepSegment* out, bool* have) {
  if (lifted_) {
    lifted_ = false;
    pen_segment(true, out);
    *have = true;
    return;
  }
  hold_ = Hold::kNone;
  if (have_rest_) {
    have_rest_ = false;
    const uint64_t reach = 2ull * rest_.accel * rest_.length_q8;
    if (rest_.exit_v2 > reach) rest_.exit_v2 = reach;
    planner.limit_next_entry(rest_.exit_v2);
    begin_move(rest_);
    in_move_ = true;
  } else {
    planner.limit_next_entry(0);
  }
}

// A pen-up travel by `delta` motor steps, at the travel speed, from rest to rest.
MotionItem StepPrep::travel(const int32_t delta[2]) const {
  MotionItem t;
  t.kind = MotionItem::kMove;
  t.pen_down = false;
  t.delta[0] = delta[0];
  t.delta[1] = delta[1];
  t.length_q8 = motor_move_length_q8(m_, delta);  // as the planner times its moves
  if (t.length_q8 < 256) t.length_q8 = 256;       // below a plot step: still a step's time
  const uint64_t top = uint64_t{m_.travel_speed} * m_.travel_speed * 256;
  t.top_v2 = top;
  t.accel = fx_.acceleration ? m_.accel : 0;
  t.entry_v2 = t.exit_v2 = fx_.acceleration ? 0 : top;
  return t;
}

void StepPrep::restart_at(uint32_t remaining, const int32_t motors[2]) {
  // The rest of the move the stop was in: from dominant step j_ - remaining (a take-up was run
  // out first by skip_events(), so it is the move's start then). At a move's end, none.
  have_rest_ = false;
  if (in_move_ && remaining <= j_ && j_ - remaining < n_) {
    rest_ = part(j_ - remaining, n_);
    rest_.entry_v2 = 0;
    have_rest_ = true;
  }
  in_move_ = false;
  lifted_ = pen_down_;  // lowered again once there
  pen_down_ = false;
  // The travel's target is where the plan had the carriage: the motors less the slack they
  // took up (a motor that last ran backwards is a slack behind it; the prep adds take-ups to
  // the planned motion, so the travel, and the rest of the move after it, take up whatever
  // their own directions need).
  int32_t target[2] = {motors[0], motors[1]};
  if (fx_.backlash)
    for (uint8_t mo = 0; mo < 2; ++mo)
      if (last_backward_[mo]) target[mo] += int32_t(m_.backlash[mo]);
  // From a reset: the slack as at any start (taken up for + moves), the pen up.
  last_backward_[0] = last_backward_[1] = false;
  takeup_pending_[0] = takeup_pending_[1] = false;
  last_takeup_ = false;
  hold_ = Hold::kTravel;
  if (target[0] != 0 || target[1] != 0) {
    begin_move(travel(target));
    in_move_ = true;
  }
}

// A pen change the planner asked for: its dwell is the planner's, on the tick's clock too.
inline void StepPrep::planned_pen(const MotionItem& it, StepSegment* out) {
  out->kind = StepSegment::kPen;
  out->pen_down = it.pen_down;
  out->dwell_ticks = it.dwell_ticks;
  time_q8_ += uint64_t{it.dwell_ticks} * 256;
  pen_down_ = it.pen_down;
  last_takeup_ = false;
  ++counters_.segments;
}

// Slack take-up from rest, one motor only, at the rate whose first step from rest needs the
// motor's acceleration: interval = sqrt(2 / a_motor).
inline Status StepPrep::takeup_segment(uint8_t mo, StepSegment* out) {
  takeup_pending_[mo] = false;
  const uint64_t a_motor = uint64_t{m_.accel} * m_.steps_num / m_.steps_den + 1;
  const uint64_t root_q8 = isqrt_u64(a_motor * 65536 / 2);  // sqrt(a / 2) * 256
  int64_t interval = int64_t(uint64_t{m_.tick_hz} * 65536 / root_q8);
  if (interval < int64_t{m_.min_interval} * 256) interval = int64_t{m_.min_interval} * 256;
  out->kind = StepSegment::kSteps;
  out->new_block = true;
  out->dominant = mo;
  out->dir_bits =
      uint8_t((dir_bits_ & (1u << mo)) | (last_backward_[1 - mo] ? (1u << (1 - mo)) : 0));
  out->major = m_.backlash[mo];
  out->minor = 0;
  out->count = uint16_t(m_.backlash[mo]);
  if (interval > INT32_MAX) return Status::kIntervalTooLong;
  out->interval_q8 = int32_t(interval);
  out->add_q8 = 0;
  advance_time(out->count, interval, 0);
  counters_.motor_steps[mo] += m_.backlash[mo];
  ++counters_.backlash_takeups;
  ++counters_.segments;
  block_start_q8_ = time_q8_;
  last_takeup_ = true;
  return Status::kOk;
}

// The move's next stretch of steps as one linear ramp (choose_ramp()), refused where the timer
// cannot run it: faster than its floor, or an interval beyond the tick's 32 bits.
inline Status StepPrep::steps_segment(StepSegment* out) {
  uint32_t j1 = 0;
  int64_t first = 0, add = 0;
  choose_ramp(&j1, &first, &add);
  const int64_t m = j1 - j_;
  const int64_t floor_q8 = int64_t{m_.min_interval} * 256;
  if (first < floor_q8 || first + (m - 1) * add < floor_q8) return Status::kTimerFloor;
  // The tick runs in 32 bits: every interval of the segment (linear, so its two ends) and
  // the step between them must fit.
  if (first > INT32_MAX || first + (m - 1) * add > INT32_MAX || add > INT32_MAX || add < INT32_MIN)
    return Status::kIntervalTooLong;
  out->kind = StepSegment::kSteps;
  out->new_block = first_segment_;
  out->dominant = dominant_;
  out->dir_bits = dir_bits_;
  out->major = n_;
  out->minor = minor_;
  out->count = uint16_t(m);
  out->interval_q8 = int32_t(first);
  out->add_q8 = int32_t(add);
  first_segment_ = false;
  advance_time(uint32_t(m), first, add);
  reg_q8_ = first + m * add;  // the tick's interval register after the segment
  reg_add_ = add;
  counters_.motor_steps[dominant_] += uint64_t(m);
  ++counters_.segments;
  last_takeup_ = false;
  j_ = j1;
  if (j_ >= end_j_) counters_.motor_steps[1 - dominant_] += minor_at(end_j_);
  return Status::kOk;
}

Status StepPrep::next_segment(MotionPlanner& planner, StepSegment* out, bool* have) {
  *have = false;
  for (;;) {
    if (hold_ == Hold::kHeld) return Status::kOk;  // at rest, waiting for resume()
    if (hold_ == Hold::kTravel && !in_move_) hold_ = Hold::kResume;  // restart_at()'s travel
    if (hold_ == Hold::kResume) {
      resume_move(planner, out, have);
      if (*have) return Status::kOk;
    }
    if (!in_move_ && (hold_ == Hold::kBraking || hold_ == Hold::kRequested) &&
        (hold_ == Hold::kBraking ? brake_exit2_ : last_exit2_) == 0) {
      // At rest: held. Lift the pen first if it is down.
      hold_ = Hold::kHeld;
      ++counters_.holds;
      if (pen_down_) {
        lifted_ = true;
        pen_segment(false, out);
        *have = true;
      }
      return Status::kOk;
    }
    if (!in_move_) {
      if (done_) return Status::kOk;
      MotionItem it;
      if (!planner.next(&it)) {
        if (planner.waiting()) return Status::kOk;  // points on their way: nothing yet
        done_ = true;
        return planner.status();  // kOk, or why the point feed stopped
      }
      if (it.kind == MotionItem::kPen) {
        planned_pen(it, out);
        *have = true;
        return Status::kOk;
      }
      begin_move(it);
      in_move_ = true;
      if (hold_ == Hold::kBraking) brake(brake_exit2_);  // a hold that runs on past a move
      continue;
    }
    for (uint8_t mo = 0; mo < 2; ++mo) {
      if (!takeup_pending_[mo]) continue;
      const Status s = takeup_segment(mo, out);
      *have = ok(s);
      return s;
    }
    // A hold starts once the move's take-ups are done (they run from rest): from step j_.
    if (hold_ == Hold::kRequested) {
      brake(j_ == 0 ? entry2_ : speed2_at(j_));
      continue;
    }
    if (j_ >= end_j_) {
      in_move_ = false;
      last_exit2_ = item_.accel > 0 && prof_exit2_ < vtop2_ ? prof_exit2_ : vtop2_;
      if (item_.accel == 0) last_exit2_ = 0;  // no acceleration modelled: a hold stops at once
      continue;
    }
    const Status s = steps_segment(out);
    *have = ok(s);
    return s;
  }
}

}  // namespace haloplot
