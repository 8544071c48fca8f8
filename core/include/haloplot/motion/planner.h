// The motion planner: path points in, committed motion items out (moves with their entry,
// top and exit speeds, and pen changes), with a fixed look-ahead buffer of blocks.
//
// Speeds live in path units (plot steps per second) so junction speeds compare across blocks;
// squares are kept as Q8 (v^2 * 256) in uint64_t. Budget: v < 2^16, a < 2^22, block length
// < 2^21 plot steps (Q8: 2^29): 2 * a * L_q8 < 2^52, v^2 Q8 < 2^40.
//
// Acceleration (grbl's scheme, in integers): each block gets a maximum entry speed from the
// junction deviation at its start; a backward pass makes every block able to stop by the end
// of the buffer, a forward pass keeps every entry reachable. The oldest block is committed
// when the buffer is full; its exit speed then becomes the fixed entry of the next.
// Without the acceleration effect no pass runs and no buffer exists: every move runs at its
// top speed from end to end.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/motion/machine.h"
#include "haloplot/motion/path_plan.h"
#include "haloplot/status/status.h"

namespace haloplot {

struct MotionItem {
  enum Kind : uint8_t { kMove, kPen };
  Kind kind = kMove;
  bool pen_down = false;      // kPen: the state after the change; kMove: the state during the move
  int32_t delta[2] = {0, 0};  // motor steps
  uint32_t length_q8 = 0;     // plot steps * 256
  uint32_t accel = 0;         // plot steps / s^2; 0: constant speed
  uint64_t entry_v2 = 0, top_v2 = 0, exit_v2 = 0;  // (plot steps / s)^2 * 256
  uint32_t dwell_ticks = 0;                        // kPen: servo travel + settle
};

struct PlannerCounters {
  uint64_t moves = 0;
  uint64_t junctions = 0;  // junction speeds computed (acceleration effect)
  uint64_t replans = 0;    // backward/forward passes (acceleration effect)
  uint64_t pen_changes = 0;
  uint64_t dwell_ticks = 0;  // pen servo time added (pen servo effect)
};

// Where more path points come from once the planner has used up the ones it holds (the band
// conductor, band by band): more() hands over the next batch, n == 0 when the path is done.
// The planner copies each point into its look-ahead blocks before it asks again, so a feed may
// reuse the memory of the previous batch.
// more() may answer kBusy: nothing yet (the next band is still arriving); the planner then
// holds and asks again on its next call.
struct PointFeed {
  Status (*more)(void* ctx, const PathPoint** points, uint32_t* n) = nullptr;
  void* ctx = nullptr;
};

class MotionPlanner {
 public:
  static constexpr uint32_t kDefaultLookahead = 16;
  // Workspace for the look-ahead buffer: zero without the acceleration effect (then null will
  // do). It starts on a kBufferAlignment (8) boundary, or init() returns kMisalignedBuffer.
  // constexpr, so a firmware sizes its static workspace with it:
  //   alignas(8) static uint8_t ws[MotionPlanner::workspace_bytes(PlotterEffects{})];
  static constexpr size_t workspace_bytes(const PlotterEffects& fx,
                                          uint32_t lookahead = kDefaultLookahead);

  Status init(const Machine& m, const PlotterEffects& fx, const PathPoint* points, uint32_t n,
              void* workspace, size_t workspace_bytes, uint32_t lookahead = kDefaultLookahead);
  // Set after init(): points past the initial ones come from the feed.
  void set_feed(PointFeed feed) { feed_ = feed; }
  // Set after init(): once the path is done, travel pen up to the origin (a job's
  // `finish home`), so the next job and the user find the pen where plots start.
  void set_finish_home(bool home) { home_pending_ = home; }
  // The next committed item; false when the path is done (the pen ends up), or when the feed
  // failed: status() then says why.
  bool next(MotionItem* out);
  Status status() const { return feed_status_; }
  bool waiting() const { return waiting_; }  // next() returned false: the feed said kBusy
  // After a feed hold (step_prep.h): the next move may enter at most this fast (v^2, Q8), as
  // the motion before it now ends slower than planned; later entries follow (the forward
  // pass). 0 with no block buffered: the next block starts from rest.
  void limit_next_entry(uint64_t v2);
  const PlannerCounters& counters() const { return counters_; }

 private:
  struct Block {
    int32_t delta[2];
    int32_t dx, dy;  // plot steps
    uint32_t length_q8;
    uint64_t nominal_v2, max_entry_v2, entry_v2;
  };
  bool make_move(const PathPoint& p, Block* b);
  bool point_ready();  // a point is waiting (asks the feed when the current batch is used up)
  bool home_point();   // the travel home as the last point, when asked for and not yet made
  uint64_t junction_v2(const Block& prev, const Block& next) const;
  void replan();
  void forward_pass();
  Block& at(uint32_t i) { return ring_[(head_ + i) % capacity_]; }

  Machine m_ = kUnsetMachine;  // init() sets both; zero until then (machine.h)
  PlotterEffects fx_ = kUnsetEffects;
  const PathPoint* points_ = nullptr;
  uint32_t n_ = 0, next_point_ = 0;
  int32_t x_ = 0, y_ = 0;       // plot position after the last block made
  int32_t motors_[2] = {0, 0};  // motor position after the last block made
  bool pen_down_ = false;       // pen state of the blocks in the buffer
  Block* ring_ = nullptr;
  uint32_t capacity_ = 0, head_ = 0, count_ = 0;
  bool head_fixed_ = false;                 // the head's entry speed is committed
  bool have_prev_ = false;                  // the last block made, for the next junction
  bool last_backward_[2] = {false, false};  // backlash: each motor's last direction
  Block prev_{};
  PlannerCounters counters_{};
  PointFeed feed_{};
  Status feed_status_ = Status::kOk;
  bool waiting_ = false;
  bool home_pending_ = false;  // the travel home is still to come
  PathPoint home_{0, 0, 0};    // where it goes: the origin, pen up
};

constexpr size_t MotionPlanner::workspace_bytes(const PlotterEffects& fx, uint32_t lookahead) {
  return fx.acceleration ? size_t{lookahead} * sizeof(Block) : 0;
}

}  // namespace haloplot
