#include "haloplot/view/facing.h"

#include "haloplot/geometry/wide.h"
#include "haloplot/view/trig.h"

namespace haloplot {
namespace {

static_assert(2 * (int64_t{2} * kWorldLimit) * (int64_t{2} * kWorldLimit) < (int64_t{1} << 44),
              "a world normal's component fits 44 bits");
static_assert((int64_t{2} * kWorldLimit << kTrigFractionBits) + (int64_t{kWorldLimit} << 30) <
                  (int64_t{1} << 53),
              "E - A in Q30 fits int64");

// round(a * b / 2^30) for |a|, |b| <= 2^30.
int64_t mul_q30(int64_t a, int64_t b) {
  const int64_t p = a * b;
  const int64_t half = int64_t{1} << (kTrigFractionBits - 1);
  return p >= 0 ? (p + half) >> kTrigFractionBits : -((-p + half) >> kTrigFractionBits);
}

bool in_world(const Point3& p) {
  return p.x >= -kWorldLimit && p.x <= kWorldLimit && p.y >= -kWorldLimit && p.y <= kWorldLimit &&
         p.z >= -kWorldLimit && p.z <= kWorldLimit;
}

}  // namespace

Status model_facing(const View& view, const Point3* world, uint32_t n_world,
                    const Triangle* triangles, uint32_t n_triangles, uint8_t* out) {
  const Status s = validate(view);
  if (!ok(s)) return s;
  const SinCos az = sin_cos_mdeg(view.azimuth_mdeg), el = sin_cos_mdeg(view.elevation_mdeg);
  // The direction to the viewer in world coordinates, Q2.30.
  const int64_t w[3] = {-mul_q30(az.sin, el.cos), -mul_q30(az.cos, el.cos), el.sin};
  const int64_t eye = view.perspective;
  for (uint32_t t = 0; t < n_triangles; ++t) {
    const uint32_t* v = triangles[t].v;
    if (v[0] >= n_world || v[1] >= n_world || v[2] >= n_world) return Status::kBadParameter;
    const Point3 &a = world[v[0]], &b = world[v[1]], &c = world[v[2]];
    if (!in_world(a) || !in_world(b) || !in_world(c)) return Status::kCoordinateOutOfRange;
    const int64_t u[3] = {int64_t{b.x} - a.x, int64_t{b.y} - a.y, int64_t{b.z} - a.z};
    const int64_t q[3] = {int64_t{c.x} - a.x, int64_t{c.y} - a.y, int64_t{c.z} - a.z};
    const int64_t n[3] = {u[1] * q[2] - u[2] * q[1], u[2] * q[0] - u[0] * q[2],
                          u[0] * q[1] - u[1] * q[0]};
    // Towards the viewer: w itself, or the eye E = D w less the corner A, both in Q30.
    const int64_t corner[3] = {a.x, a.y, a.z};
    Wide dot = Wide::from_i64(0);
    for (int k = 0; k < 3; ++k) {
      const int64_t to = eye > 0 ? eye * w[k] - corner[k] * kTrigOne : w[k];
      dot = dot + mul_i64(n[k], to);
    }
    out[t] = compare(dot, Wide::from_i64(0)) > 0 ? 1 : 0;
  }
  return Status::kOk;
}

}  // namespace haloplot
