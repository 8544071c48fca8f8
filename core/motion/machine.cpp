#include "haloplot/motion/machine.h"

#include "haloplot/geometry/fraction.h"

namespace haloplot {
namespace {

// round(v * num / den), halves up; |v| < 2^22, num <= 2^10: fits easily in int64.
int32_t scale_round(int64_t v, uint32_t num, uint32_t den) {
  return static_cast<int32_t>(floor_div(2 * v * num + den, 2 * int64_t{den}));
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
