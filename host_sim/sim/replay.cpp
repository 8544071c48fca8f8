#include "sim/replay.h"

#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/wide.h"

namespace haloplot::host {

Replay replay(const Trace& t) {
  Replay r;
  const Machine& m = t.machine;
  const bool corexy = m.kinematics == Kinematics::kCoreXY;
  r.scale = int64_t(m.steps_num) * (corexy ? 2 : 1);
  int32_t motor[2] = {0, 0};
  // Dead band: slack[k] in [0, backlash[k]] is how far the motor is ahead of the carriage. The
  // machine starts pushed forward (slack full), as the step prep assumes, so the logical
  // position is carriage + backlash.
  int32_t slack[2] = {int32_t(m.backlash[0]), int32_t(m.backlash[1])};
  int32_t carriage[2] = {-slack[0], -slack[1]};
  auto position = [&]() {
    const int64_t a = carriage[0] + int64_t(m.backlash[0]),
                  b = carriage[1] + int64_t(m.backlash[1]);
    return corexy ? ExactPoint{(a + b) * m.steps_den, (a - b) * m.steps_den}
                  : ExactPoint{a * m.steps_den, b * m.steps_den};
  };
  bool down = false;
  ExactPoint lift = position();
  const auto& ev = t.events;
  for (size_t i = 0; i < ev.size();) {
    const uint64_t tick = ev[i].tick;
    bool stepped = false;
    for (; i < ev.size() && ev[i].tick == tick && ev[i].motor != 2; ++i) {
      const int k = ev[i].motor, b = int32_t(m.backlash[k]);
      const bool back = ev[i].flag;
      motor[k] += back ? -1 : 1;
      if (back) {
        if (slack[k] > 0)
          --slack[k];
        else
          --carriage[k];
      } else {
        if (slack[k] < b)
          ++slack[k];
        else
          ++carriage[k];
      }
      (down ? r.pen_down_steps : r.pen_up_steps) += 1;
      stepped = true;
    }
    const ExactPoint p = position();
    if (stepped && down) {
      auto& s = r.strokes.back();
      if (s.back().x != p.x || s.back().y != p.y) s.push_back(p);
    }
    for (; i < ev.size() && ev[i].tick == tick && ev[i].motor == 2; ++i) {
      const bool now_down = ev[i].flag;
      if (down && !now_down) {
        ++r.pen_lifts;
        lift = p;
      }
      if (!down && now_down) {
        const int64_t dx = (p.x - lift.x) / r.scale, dy = (p.y - lift.y) / r.scale;
        r.pen_up_length += isqrt_u64(uint64_t(dx * dx + dy * dy));
        r.strokes.push_back({p});
      }
      down = now_down;
    }
  }
  r.final_motors[0] = motor[0];
  r.final_motors[1] = motor[1];
  return r;
}

std::vector<PathPoint> simplify(const std::vector<ExactPoint>& stroke, int64_t scale, int32_t tol) {
  std::vector<PathPoint> p;
  for (const ExactPoint& e : stroke)
    p.push_back(PathPoint{int32_t(floor_div(2 * e.x + scale, 2 * scale)),
                          int32_t(floor_div(2 * e.y + scale, 2 * scale)), 1});
  if (p.size() < 3) return p;
  std::vector<uint8_t> keep(p.size(), 0);
  keep.front() = keep.back() = 1;
  std::vector<std::pair<size_t, size_t>> stack = {{0, p.size() - 1}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const int64_t dx = p[b].x - p[a].x, dy = p[b].y - p[a].y, l2 = dx * dx + dy * dy;
    size_t worst = a;
    Wide worst_d = Wide::from_i64(-1);
    for (size_t i = a + 1; i < b; ++i) {
      const int64_t wx = p[i].x - p[a].x, wy = p[i].y - p[a].y;
      const Wide d = l2 == 0 ? Wide::from_i64(wx * wx + wy * wy)
                             : mul_i64(dx * wy - dy * wx, dx * wy - dy * wx);
      if (worst_d < d) {
        worst_d = d;
        worst = i;
      }
    }
    if (worst != a && mul_i64(int64_t(tol) * tol, l2 == 0 ? 1 : l2) < worst_d) {
      keep[worst] = 1;
      stack.push_back({a, worst});
      stack.push_back({worst, b});
    }
  }
  std::vector<PathPoint> out;
  for (size_t i = 0; i < p.size(); ++i)
    if (keep[i]) out.push_back(p[i]);
  return out;
}

}  // namespace haloplot::host
