// Sub-step units (geometry/units.h): a scene fitted in units of 2^-s steps is decided in units
// and drawn in steps. The references here are independent of the core's code:
//   - units_to_steps against a division written out, on every unit value of a range;
//   - a scene multiplied by 2^s (exact, so every crossing and every depth order is the same)
//     and plotted with s sub-step bits draws the spans of the whole-step plot within the
//     rounding bound: each end within 1/2 + 2^-(s+1) step of the exact position, so within
//     1 step of the whole-step plot's end, and the same spans in the same order;
//   - a halo given in steps cuts the same gaps in units (the job scales it);
//   - the protocol carries the units with the job's effects and refuses more than the maximum.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "check.h"
#include "demo/cube_array.h"
#include "demo/random_scene.h"
#include "haloplot/geometry/units.h"
#include "haloplot/job/job.h"
#include "haloplot/protocol/messages.h"
#include "haloplot/view/projection.h"

using namespace haloplot;

namespace {

std::vector<Edge3> scaled(std::vector<Edge3> edges, int s) {
  for (Edge3& e : edges) {
    e.a.x <<= s, e.a.y <<= s;
    e.b.x <<= s, e.b.y <<= s;
  }
  return edges;
}

struct Plot {
  Status status = Status::kOk;
  std::vector<Segment2> spans;
  std::vector<PathPoint> points;
};

Plot plot(const JobSpec& spec, const std::vector<Edge3>& edges) {
  Plot out;
  std::vector<uint64_t> buffer(4u << 20);
  PreparedJob job;
  JobCounters c;
  const uint32_t capacity = uint32_t(edges.size()) * 4 + 64;
  out.status = job_prepare(spec, Edges{edges.data(), uint32_t(edges.size())}, capacity,
                           buffer.data(), buffer.size() * 8, &job, &c);
  if (!ok(out.status)) return out;
  out.spans.assign(job.spans, job.spans + job.n_spans);
  out.points.assign(job.points, job.points + job.n_points);
  return out;
}

void expect_same_within_a_step(const char* name, const JobSpec& whole, const std::vector<Edge3>& e,
                               int s) {
  const Plot a = plot(whole, e);
  JobSpec fine = whole;
  fine.substep_bits = s;
  const Plot b = plot(fine, scaled(e, s));
  CHECK_MSG(ok(a.status) && ok(b.status), std::string(name) + ": a job failed");
  CHECK_MSG(a.spans.size() == b.spans.size() && !a.spans.empty(),
            std::string(name) + ": " + std::to_string(a.spans.size()) + " spans in steps, " +
                std::to_string(b.spans.size()) + " in units");
  int32_t worst = 0, off = 0;
  for (size_t i = 0; i < a.spans.size() && i < b.spans.size(); ++i) {
    const Segment2 &p = a.spans[i], &q = b.spans[i];
    for (int32_t d : {p.x0 - q.x0, p.y0 - q.y0, p.x1 - q.x1, p.y1 - q.y1}) {
      worst = std::max(worst, std::abs(d));
      off += d != 0;
    }
  }
  CHECK_MSG(worst <= 1, std::string(name) + ": an end moved " + std::to_string(worst) + " steps");
  // The path is in steps too: within the whole-step plot's bounds plus the rounding.
  int32_t a_most = 0, b_most = 0;
  for (const PathPoint& p : a.points) a_most = std::max({a_most, p.x, p.y});
  for (const PathPoint& p : b.points) b_most = std::max({b_most, p.x, p.y});
  CHECK_MSG(b_most <= a_most + 1, std::string(name) + ": the path is not in steps");
  std::printf("%-24s s=%d spans=%zu ends that moved a step: %d\n", name, s, a.spans.size(), off);
}

}  // namespace

int main() {
  // units_to_steps: the nearest step, ties upward, for every unit value near 0 and near the top.
  for (int s = 0; s <= kMaxSubstepBits; ++s) {
    const int64_t k = int64_t{1} << s;
    bool all = true;
    for (int64_t u = 0; u < 5000; ++u)
      for (int64_t v : {u, int64_t{kCoordMax} - u})
        all = all && units_to_steps(int32_t(v), s) == int32_t((2 * v + k) / (2 * k));
    CHECK_MSG(all, "units_to_steps with " + std::to_string(s) + " bits");
    CHECK(steps_to_units(3, s) == 3 * k);
  }
  // Lengths beyond the range clamp where the stages refuse them (no overflow).
  CHECK(steps_to_units(kCoordMax, kMaxSubstepBits) == kCoordLimit);
  CHECK(steps_to_units(INT32_MIN, kMaxSubstepBits) == -kCoordLimit);

  // Figure 4 and random edges, haloed (paper and exact halo) and whole, 1 to 5 sub-step bits.
  const std::vector<Edge3> fig4 = host::cube_array(CubeArrayParams{});
  // Random edges on a plot 16,384 steps wide (the generator fills 2^20: shrunk to steps).
  std::vector<Edge3> random = host::paper_random(3000, 20000, 20261202);
  for (Edge3& e : random) {
    e.a.x >>= 6, e.a.y >>= 6;
    e.b.x >>= 6, e.b.y >>= 6;
  }
  JobSpec haloed;
  haloed.draw.halo = 50;
  JobSpec exact = haloed;
  exact.draw.mode = HaloMode::kExact;
  exact.cut.reach = 50;
  JobSpec all;
  all.drawing = DrawingEffect::kAllEdges;
  for (int s : {1, 3, 5}) {
    expect_same_within_a_step("figure4_haloed", haloed, fig4, s);
    expect_same_within_a_step("random_exact_halo", exact, random, s);
    expect_same_within_a_step("figure4_all_edges", all, fig4, s);
  }
  // The check sees a halo left in steps: in units it cuts gaps 8 times too short, and spans
  // that should be gaps come back.
  {
    JobSpec fine = haloed;
    fine.substep_bits = 3;
    const Plot right = plot(fine, scaled(fig4, 3));
    fine.substep_bits = 0;  // the halo taken as units: 50 units, not 400
    fine.draw.halo = 50;
    const Plot wrong = plot(fine, scaled(fig4, 3));
    CHECK(ok(right.status) && ok(wrong.status));
    CHECK_MSG(right.spans.size() != wrong.spans.size(), "a halo in the wrong units went unseen");
  }
  // Bad units are refused by name, not clamped.
  {
    JobSpec bad = haloed;
    bad.substep_bits = kMaxSubstepBits + 1;
    CHECK(plot(bad, fig4).status == Status::kBadParameter);
    bad.substep_bits = -1;
    CHECK(plot(bad, fig4).status == Status::kBadParameter);
    View v;
    v.substep_bits = 6;  // 20,400 steps times 64 leaves 2^20
    CHECK(validate(v) == Status::kBadParameter);
    v.substep_bits = 5;
    CHECK(ok(validate(v)));
  }
  // The protocol: the units travel with the effects; more than the maximum is malformed.
  {
    JobSpec spec;
    spec.substep_bits = 5;
    uint8_t buf[kEffectsBytes];
    encode_effects(spec, buf);
    JobSpec got;
    CHECK(ok(decode_effects(buf, sizeof buf, &got)) && got.substep_bits == 5);
    buf[2] = uint8_t(kMaxSubstepBits + 1);
    CHECK(decode_effects(buf, sizeof buf, &got) == Status::kMalformedRequest);
  }
  // The path's clean-up travels with the effects too; a host that sends none (3 bytes) gets
  // dots and overlaps cleaned and no minimum stroke.
  {
    JobSpec spec;
    spec.clean = PathClean{false, 24, 9};
    uint8_t buf[kEffectsBytes];
    encode_effects(spec, buf);
    JobSpec got;
    CHECK(ok(decode_effects(buf, sizeof buf, &got)) && !got.clean.on &&
          got.clean.min_stroke == 24 && got.clean.simplify == 9);
    CHECK(ok(decode_effects(buf, kEffectsNoSimplifyBytes, &got)) && got.clean.min_stroke == 24 &&
          got.clean.simplify == 0);
    CHECK(ok(decode_effects(buf, kEffectsShortBytes, &got)) && !got.clean.on &&
          got.clean.min_stroke == 0);
    buf[1] = 0;
    CHECK(ok(decode_effects(buf, kEffectsShortBytes, &got)) && got.clean.on);
    CHECK(decode_effects(buf, kEffectsBytes - 1, &got) == Status::kMalformedRequest);
  }
  return check::finish("units");
}
