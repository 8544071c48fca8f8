#include "haloplot/motion/machine.h"

#include "haloplot/geometry/contract.h"
#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/wide.h"

namespace haloplot {
namespace {

// round(v * num / den), halves up; |v| < 2^22, num <= 2^10: fits easily in int64.
int32_t scale_round(int64_t v, uint32_t num, uint32_t den) {
  return static_cast<int32_t>(floor_div(2 * v * num + den, 2 * int64_t{den}));
}

// round(v * num / den) in 64 bits, halves up; |v| < 2^36, num <= 2^11.
int64_t scale_round64(int64_t v, uint32_t num, uint32_t den) {
  return floor_div(2 * v * num + den, 2 * int64_t{den});
}

}  // namespace

Status validate(const Machine& m) {
  if (m.steps_num == 0 || m.steps_den == 0 || m.steps_num > 16 * m.steps_den ||
      64 * m.steps_num < m.steps_den || m.steps_num > 1024 || m.steps_den > 1024)
    return Status::kBadParameter;
  if (m.tick_hz == 0 || m.tick_hz > (1u << 28) || m.min_interval == 0) return Status::kBadParameter;
  if (m.draw_speed == 0 || m.travel_speed == 0 || m.draw_speed >= (1u << 16) ||
      m.travel_speed >= (1u << 16) || m.accel == 0 || m.accel >= (1u << 22) ||
      m.junction_deviation >= (1u << 16))
    return Status::kBadParameter;
  // The fastest motor runs at speed * ratio, times sqrt(2) on CoreXY (a diagonal move turns
  // one motor at |vx| + |vy|). Compare squares to stay in integers.
  const uint32_t fastest = m.draw_speed > m.travel_speed ? m.draw_speed : m.travel_speed;
  const uint64_t motor = uint64_t{fastest} * m.steps_num;  // times 1 / steps_den
  const uint64_t lhs = motor * motor * (m.kinematics == Kinematics::kCoreXY ? 2 : 1);
  const uint64_t rhs = uint64_t{m.max_step_rate} * m.steps_den * m.max_step_rate * m.steps_den;
  if (lhs > rhs) return Status::kStepRateExceeded;
  if (uint64_t{m.max_step_rate} * m.min_interval > m.tick_hz) return Status::kTimerFloor;
  return Status::kOk;
}

void motor_position(const Machine& m, int32_t x, int32_t y, int32_t motors[2]) {
  if (m.kinematics == Kinematics::kCoreXY) {
    motors[0] = scale_round(int64_t{x} + y, m.steps_num, m.steps_den);
    motors[1] = scale_round(int64_t{x} - y, m.steps_num, m.steps_den);
  } else {
    motors[0] = scale_round(x, m.steps_num, m.steps_den);
    motors[1] = scale_round(y, m.steps_num, m.steps_den);
  }
}

// Bit budget: |delta| < 2^27 (plot differences below 2^21, two of them summed on CoreXY, at most
// 16 motor steps a plot step), so (a + b) * 256 < 2^36 and times 2 * 2^11 below 2^48. Back in
// plot steps the move is the plot segment's to within 64 steps (a motor step is at most 64 plot
// steps, and the motor ends lie within half of one of the plot's): each coordinate in Q8 below
// (2^21 + 64) * 2^8 < 2^30, the sum of their squares below 2^61.
static_assert(16 * (2 * (2 * int64_t{kCoordLimit})) <= (int64_t{1} << 27), "motor delta bound");
static_assert(2 * ((int64_t{1} << 30) * (int64_t{1} << 30)) < (int64_t{1} << 62), "Q8 squares");

uint32_t motor_move_length_q8(const Machine& m, const int32_t delta[2]) {
  const int64_t a = delta[0], b = delta[1];
  int64_t x_q8 = 0, y_q8 = 0;
  if (m.kinematics == Kinematics::kCoreXY) {
    x_q8 = scale_round64((a + b) * 256, m.steps_den, 2 * m.steps_num);
    y_q8 = scale_round64((a - b) * 256, m.steps_den, 2 * m.steps_num);
  } else {
    x_q8 = scale_round64(a * 256, m.steps_den, m.steps_num);
    y_q8 = scale_round64(b * 256, m.steps_den, m.steps_num);
  }
  return isqrt_u64(uint64_t(x_q8 * x_q8) + uint64_t(y_q8 * y_q8));
}

void plot_position(const Machine& m, const int32_t motors[2], int32_t* x, int32_t* y) {
  int64_t a = motors[0], b = motors[1];
  if (m.kinematics == Kinematics::kCoreXY) {
    // x = (A + B) / 2, y = (A - B) / 2 in motor steps, then back to plot steps.
    *x = scale_round(a + b, m.steps_den, 2 * m.steps_num);
    *y = scale_round(a - b, m.steps_den, 2 * m.steps_num);
  } else {
    *x = scale_round(a, m.steps_den, m.steps_num);
    *y = scale_round(b, m.steps_den, m.steps_num);
  }
}

}  // namespace haloplot
