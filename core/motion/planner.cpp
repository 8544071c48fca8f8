#include "haloplot/motion/planner.h"

#include "haloplot/geometry/wide.h"

namespace haloplot {
namespace {

uint64_t min_u64(uint64_t a, uint64_t b) { return a < b ? a : b; }
uint64_t speed_v2(uint32_t v) { return uint64_t{v} * v * 256; }

}  // namespace

Status MotionPlanner::init(const Machine& m, const PlotterEffects& fx, const PathPoint* points,
                           uint32_t n, void* workspace, size_t workspace_bytes_given,
                           uint32_t lookahead) {
  const Status s = validate(m);
  if (!ok(s)) return s;
  if (fx.acceleration && lookahead < 2) return Status::kBadParameter;
  if (buffer_misaligned(workspace)) return Status::kMisalignedBuffer;
  if (workspace_bytes_given < workspace_bytes(fx, lookahead)) return Status::kWorkspaceTooSmall;
  *this = MotionPlanner{};
  m_ = m;
  fx_ = fx;
  points_ = points;
  n_ = n;
  ring_ = static_cast<Block*>(workspace);
  capacity_ = fx.acceleration ? lookahead : 0;
  return Status::kOk;
}

bool MotionPlanner::make_move(const PathPoint& p, Block* b) {
  int32_t motors[2];
  motor_position(m_, p.x, p.y, motors);  // absolute: rounding never drifts
  b->delta[0] = motors[0] - motors_[0];
  b->delta[1] = motors[1] - motors_[1];
  b->dx = p.x - x_;
  b->dy = p.y - y_;
  b->length_q8 = motor_move_length_q8(m_, b->delta);  // what the motors travel (machine.h)
  x_ = p.x;
  y_ = p.y;
  motors_[0] = motors[0];
  motors_[1] = motors[1];
  b->nominal_v2 = speed_v2(p.pen_down ? m_.draw_speed : m_.travel_speed);
  b->max_entry_v2 = 0;
  b->entry_v2 = 0;
  return b->delta[0] != 0 || b->delta[1] != 0;  // a move below one motor step is dropped
}

// grbl's junction deviation: v^2 = a * delta * s / (1 - s), s = sin(theta / 2), theta the
// angle between the reversed incoming direction and the outgoing one. In Q16 integers.
uint64_t MotionPlanner::junction_v2(const Block& a, const Block& b) const {
  const int64_t la = a.length_q8 >> 8, lb = b.length_q8 >> 8;
  if (la == 0 || lb == 0) return 0;
  const int64_t d = int64_t{a.dx} * b.dx + int64_t{a.dy} * b.dy;  // |d| <= la * lb (+ rounding)
  int64_t p = la * lb;
  int64_t num = p + d;  // (1 - cos(theta)) * p, cos(theta) = -d / p
  if (num < 0) num = 0;
  if (num > 2 * p) num = 2 * p;
  const uint64_t s2_q16 = (uint64_t(num) << 16) / uint64_t(2 * p);  // sin^2(theta / 2)
  const uint64_t s_q16 = isqrt_u64(s2_q16 << 16);
  if (s_q16 >= 65535) return ~uint64_t{0};                         // straight on: no junction limit
  const uint64_t ad = uint64_t{m_.accel} * m_.junction_deviation;  // < 2^38
  return ad * s_q16 / (65536 - s_q16) * 256;
}

void MotionPlanner::replan() {
  ++counters_.replans;
  // Backward: every block can still stop by the end of the buffer.
  uint64_t exit = 0;
  for (uint32_t i = count_; i-- > 0;) {
    Block& b = at(i);
    if (i == 0 && head_fixed_) break;
    const uint64_t reachable = exit + 2ull * m_.accel * b.length_q8;
    b.entry_v2 = min_u64(b.max_entry_v2, reachable);
    exit = b.entry_v2;
  }
  forward_pass();
}

// Forward: no entry faster than the previous block can accelerate to.
void MotionPlanner::forward_pass() {
  for (uint32_t i = 0; i + 1 < count_; ++i) {
    const uint64_t reachable = at(i).entry_v2 + 2ull * m_.accel * at(i).length_q8;
    if (at(i + 1).entry_v2 > reachable) at(i + 1).entry_v2 = reachable;
  }
}

void MotionPlanner::limit_next_entry(uint64_t v2) {
  if (count_ == 0) {
    if (v2 == 0) have_prev_ = false;  // no junction speed into the next block: from rest
    return;
  }
  if (at(0).entry_v2 > v2) at(0).entry_v2 = v2;
  forward_pass();
}

bool MotionPlanner::point_ready() {
  if (next_point_ < n_) return true;
  if (feed_.more == nullptr || !ok(feed_status_)) return home_point();
  const PathPoint* points = nullptr;
  uint32_t n = 0;
  const Status s = feed_.more(feed_.ctx, &points, &n);
  waiting_ = s == Status::kBusy;  // on their way (a band still arriving): ask again later
  if (waiting_) return false;
  feed_status_ = s;
  if (!ok(feed_status_) || n == 0) {
    feed_.more = nullptr;  // done (or failed): never ask again
    return home_point();
  }
  points_ = points;
  n_ = n;
  next_point_ = 0;
  return true;
}

// The path is done: the travel home, once, as one more pen-up point (not after a failed feed:
// the plot stops where it failed).
bool MotionPlanner::home_point() {
  if (!home_pending_ || !ok(feed_status_)) return false;
  home_pending_ = false;
  points_ = &home_;
  n_ = 1;
  next_point_ = 0;
  return true;
}

bool MotionPlanner::next(MotionItem* out) {
  for (;;) {
    // Fill the buffer with moves of the current pen state.
    const uint32_t room = fx_.acceleration ? capacity_ : 1;
    while (count_ < room && point_ready() && (points_[next_point_].pen_down != 0) == pen_down_) {
      Block b;
      if (!make_move(points_[next_point_++], &b)) continue;
      ++counters_.moves;
      if (fx_.acceleration) {
        b.max_entry_v2 = 0;  // from rest after a pen change or at the start
        if (have_prev_) {
          ++counters_.junctions;
          b.max_entry_v2 = min_u64(min_u64(junction_v2(prev_, b), b.nominal_v2), prev_.nominal_v2);
        }
        // Backlash take-up needs the motor at rest: stop wherever a motor reverses.
        for (int mo = 0; mo < 2; ++mo) {
          if (b.delta[mo] == 0) continue;
          if (fx_.backlash && (b.delta[mo] < 0) != last_backward_[mo]) b.max_entry_v2 = 0;
          last_backward_[mo] = b.delta[mo] < 0;
        }
        prev_ = b;
        have_prev_ = true;
        ring_[(head_ + count_++) % capacity_] = b;
        replan();
      } else {
        // Constant speed: the move is committed as it is made.
        out->kind = MotionItem::kMove;
        out->pen_down = pen_down_;
        out->delta[0] = b.delta[0];
        out->delta[1] = b.delta[1];
        out->length_q8 = b.length_q8;
        out->accel = 0;
        out->entry_v2 = out->top_v2 = out->exit_v2 = b.nominal_v2;
        return true;
      }
    }
    // Waiting for points with room in the buffer: hold. Committing now would plan a stop the
    // uninterrupted plan does not make; the step queue runs dry instead and the plot resumes
    // with the same steps at the same ticks.
    if (waiting_ && count_ < room) return false;
    const bool barrier = !point_ready() || (points_[next_point_].pen_down != 0) != pen_down_;
    if (count_ > 0 && (count_ == capacity_ || barrier)) {
      Block& b = at(0);
      out->kind = MotionItem::kMove;
      out->pen_down = pen_down_;
      out->delta[0] = b.delta[0];
      out->delta[1] = b.delta[1];
      out->length_q8 = b.length_q8;
      out->accel = m_.accel;
      out->entry_v2 = b.entry_v2;
      out->top_v2 = b.nominal_v2;
      out->exit_v2 = count_ > 1 ? at(1).entry_v2 : 0;
      head_ = (head_ + 1) % capacity_;
      --count_;
      head_fixed_ = count_ > 0;
      return true;
    }
    if (count_ > 0) continue;
    // The buffer is empty at a pen change, or at the end (the pen ends up).
    const bool want_down = point_ready() && points_[next_point_].pen_down != 0;
    if (want_down == pen_down_) {
      if (!point_ready()) return false;
      continue;
    }
    pen_down_ = want_down;
    have_prev_ = false;
    head_fixed_ = false;
    ++counters_.pen_changes;
    out->kind = MotionItem::kPen;
    out->pen_down = pen_down_;
    out->dwell_ticks = fx_.pen_servo ? m_.pen_travel_ticks + m_.pen_settle_ticks : 0;
    counters_.dwell_ticks += out->dwell_ticks;
    return true;
  }
}

}  // namespace haloplot
