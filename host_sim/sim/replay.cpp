#include "sim/replay.h"

#include "geometry/wide.h"

namespace haloplot::host {

std::vector<std::vector<PathPoint>> replay_strokes(const Trace& t, ReplayStats* st) {
  std::vector<std::vector<PathPoint>> strokes;
  ReplayStats s;
  int32_t motor[2] = {0, 0};
  // Dead band: slack[m] in [0, backlash[m]] is how far the motor is ahead of the carriage. The
  // machine starts pushed forward (slack full), as the step prep assumes.
  int32_t slack[2] = {int32_t(t.machine.backlash[0]), int32_t(t.machine.backlash[1])};
  int32_t carriage[2] = {-slack[0], -slack[1]};
  bool down = false;
  int32_t px = 0, py = 0, lift_x = 0, lift_y = 0;
  auto position = [&](int32_t* x, int32_t* y) {
    const int32_t logical[2] = {carriage[0] + int32_t(t.machine.backlash[0]),
                                carriage[1] + int32_t(t.machine.backlash[1])};
    plot_position(t.machine, logical, x, y);
  };
  for (const StepEvent& e : t.events) {
    if (e.motor == 2) {
      position(&px, &py);
      if (down && !e.flag) {
        ++s.pen_lifts;
        lift_x = px;
        lift_y = py;
      }
      if (!down && e.flag) {
        s.pen_up_length += isqrt_u64(uint64_t(int64_t(px - lift_x) * (px - lift_x) + int64_t(py - lift_y) * (py - lift_y)));
        strokes.push_back({PathPoint{px, py, 0}});
      }
      down = e.flag;
      continue;
    }
    const int m = e.motor, b = int32_t(t.machine.backlash[m]);
    motor[m] += e.flag ? -1 : 1;
    if (e.flag) {
      if (slack[m] > 0) --slack[m]; else --carriage[m];
    } else {
      if (slack[m] < b) ++slack[m]; else ++carriage[m];
    }
    (down ? s.pen_down_steps : s.pen_up_steps) += 1;
    int32_t x, y;
    position(&x, &y);
    if (x == px && y == py) continue;
    px = x;
    py = y;
    if (down) strokes.back().push_back(PathPoint{x, y, 1});
  }
  s.final_motors[0] = motor[0];
  s.final_motors[1] = motor[1];
  if (st) *st = s;
  return strokes;
}

std::vector<PathPoint> simplify(const std::vector<PathPoint>& p, int32_t tol) {
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
      // squared distance * l2 (or * 1 for a degenerate chord), compared exactly
      const Wide d = l2 == 0 ? Wide::from_i64(wx * wx + wy * wy) : mul_i64(dx * wy - dy * wx, dx * wy - dy * wx);
      if (worst_d < d) {
        worst_d = d;
        worst = i;
      }
    }
    const Wide limit = mul_i64(int64_t(tol) * tol, l2 == 0 ? 1 : l2);
    if (worst != a && limit < worst_d) {
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
