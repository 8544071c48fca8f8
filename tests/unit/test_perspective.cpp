// Perspective plots against the true 3-D scene: for every crossing CUT records in a
// perspective projection, the edge it puts in front must be the one nearer the eye in 3-D.
// The reference works from the world segments in long double: it takes the crossing's screen
// point, finds on each edge the 3-D point that projects there (a projective equation in the
// edge's parameter) and compares their depths. Crossings whose two depths differ by less than
// what the rounding of the projected endpoints can move are skipped (and counted).
#include <cmath>
#include <random>
#include <vector>

#include "../check.h"
#include "haloplot/view/projection.h"
#include "pipeline/host_pipeline.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

using LD = long double;
constexpr LD kPi = 3.14159265358979323846264338327950288L;

struct ViewPoint {
  LD x, y, d;  // after the rotation, before perspective and fit
};

ViewPoint rotate(const View& v, const Point3& p) {
  const LD az = v.azimuth_mdeg * kPi / 180000.0L, el = v.elevation_mdeg * kPi / 180000.0L;
  const LD xs = p.x * std::cos(az) - p.y * std::sin(az);
  const LD y1 = p.x * std::sin(az) + p.y * std::cos(az);
  return {xs, p.z * std::cos(el) + y1 * std::sin(el), p.z * std::sin(el) - y1 * std::cos(el)};
}

struct Checked {
  size_t records = 0, skipped = 0, wrong = 0;
};

Checked check_scene(const View& view, const std::vector<Point3>& world) {
  const size_t n = world.size() / 2;
  std::vector<Point3> screen(world.size());
  CHECK(ok(project_points(view, world.data(), uint32_t(world.size()), screen.data())));
  std::vector<Edge3> edges(n);
  for (size_t e = 0; e < n; ++e) edges[e] = Edge3{screen[2 * e], screen[2 * e + 1]};
  // The fit, as the core makes it, in long double: perspective first, then uniform scale.
  const LD D = view.perspective;
  std::vector<ViewPoint> vp(world.size());
  LD xl = 1e30L, xh = -1e30L, yl = 1e30L, yh = -1e30L, dl = 1e30L, dh = -1e30L;
  for (size_t i = 0; i < world.size(); ++i) {
    vp[i] = rotate(view, world[i]);
    const LD k = D / (D - vp[i].d);
    xl = std::min(xl, vp[i].x * k), xh = std::max(xh, vp[i].x * k);
    yl = std::min(yl, vp[i].y * k), yh = std::max(yh, vp[i].y * k);
    dl = std::min(dl, vp[i].d), dh = std::max(dh, vp[i].d);
  }
  const LD scale = std::min(view.width / (xh - xl), view.height / (yh - yl));
  HostCut cut;
  CHECK(ok(host_cut(edges, CutParams{}, &cut)));
  Checked c;
  // The world depth on edge e where it projects to the screen point (sx, sy), in plot steps.
  auto depth_at = [&](size_t e, LD sx, LD sy) {
    const ViewPoint a = vp[2 * e], b = vp[2 * e + 1];
    const LD X = (sx - view.margin) / scale + xl, Y = (sy - view.margin) / scale + yl;
    // x(s) D / (D - d(s)) = X, linear in s: s (dx D + X dd) = X (D - d0) - x0 D.
    const LD ex = (b.x - a.x) * D + X * (b.d - a.d), ey = (b.y - a.y) * D + Y * (b.d - a.d);
    const LD s = std::fabs(ex) >= std::fabs(ey) ? (X * (D - a.d) - a.x * D) / ex
                                                : (Y * (D - a.d) - a.y * D) / ey;
    return a.d + s * (b.d - a.d);
  };
  for (uint32_t e = 0; e < cut.set.n_edges; ++e)
    for (uint32_t k = 0; k < cut.set.count(e); ++k) {
      const Crossing& r = cut.set.begin(e)[k];
      if (r.near_miss()) continue;
      ++c.records;
      const Edge3& g = edges[r.behind];
      const LD t = LD(r.t) / 4294967296.0L;
      const LD sx = g.a.x + t * (g.b.x - g.a.x), sy = g.a.y + t * (g.b.y - g.a.y);
      const LD behind = depth_at(r.behind, sx, sy), front = depth_at(r.front_edge(), sx, sy);
      // A step of rounding on the screen moves a depth by at most its slope per step; 1e-3 of
      // the depth range covers that for these scenes.
      if (std::fabs(front - behind) < 1e-3L * (dh - dl)) {
        ++c.skipped;
        continue;
      }
      if (front < behind) ++c.wrong;
    }
  return c;
}

}  // namespace

int main() {
  // The case from issue 18: edge 0 runs through the origin (depth 0 there), edge 1 lies at
  // depth -60000 behind it; with the eye at 1.5 model sizes the linear depth put edge 1 in
  // front.
  {
    View v;
    v.azimuth_mdeg = 0;
    v.elevation_mdeg = 0;
    v.perspective = 786432;
    const std::vector<Point3> w = {
        {-400000, -400000, 0}, {400000, 400000, 0}, {0, 60000, -200000}, {0, 60000, 200000}};
    const Checked c = check_scene(v, w);
    CHECK_EQ(c.records, size_t{1});
    CHECK_EQ(c.wrong, size_t{0});
  }
  // Random segments in random perspective views, the eye from near to far.
  std::mt19937_64 rng(18);
  Checked total;
  for (int trial = 0; trial < 24; ++trial) {
    View v;
    v.azimuth_mdeg = int32_t(rng() % 360000);
    v.elevation_mdeg = int32_t(rng() % 170000) - 85000;
    v.perspective = int32_t(kWorldLimit + 1000 + rng() % uint64_t(kWorldLimit));
    std::vector<Point3> w;
    for (int i = 0; i < 300; ++i) {
      const int32_t cx = int32_t(rng() % 800001) - 400000, cy = int32_t(rng() % 800001) - 400000,
                    cz = int32_t(rng() % 800001) - 400000;
      auto off = [&] { return int32_t(rng() % 200001) - 100000; };
      w.push_back({cx + off(), cy + off(), cz + off()});
      w.push_back({cx + off(), cy + off(), cz + off()});
    }
    const Checked c = check_scene(v, w);
    total.records += c.records, total.skipped += c.skipped, total.wrong += c.wrong;
  }
  // Haloed wire frames of the cube array and linked tori (their polygon sides), the eye at 3
  // and 1.5 times the model's size from its centre.
  {
    using namespace solid_scenes;
    Mesh cubes, tori;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        box(&cubes, i * 100000 - 180000, j * 100000 - 180000, -30000, i * 100000 - 120000,
            j * 100000 - 120000, 30000);
    torus(&tori, -60000, 0, 0, 120000, 42000, 24, 12);
    torus(&tori, 60000, 0, 0, 120000, 42000, 24, 12, true);
    const std::pair<const Mesh*, int32_t> models[] = {{&cubes, 360000}, {&tori, 444000}};
    Checked meshes;
    for (const auto& [mesh, size] : models)
      for (const int32_t az : {30000, -50000, 200000})
        for (const int tenths : {30, 15}) {
          View v;
          v.azimuth_mdeg = az;
          v.elevation_mdeg = az == 200000 ? -15000 : 25000;
          v.perspective = size * tenths / 10;
          std::vector<Point3> w;
          const std::vector<uint32_t> pairs = polygon_edges(*mesh);
          for (uint32_t id : pairs) w.push_back(mesh->v[id]);
          const Checked c = check_scene(v, w);
          meshes.records += c.records, meshes.skipped += c.skipped, meshes.wrong += c.wrong;
        }
    std::printf("perspective wire frames: %zu crossings, %zu too close to call, %zu wrong\n",
                meshes.records, meshes.skipped, meshes.wrong);
    CHECK(meshes.records > 1000);
    CHECK(meshes.skipped * 20 < meshes.records);
    CHECK_EQ(meshes.wrong, size_t{0});
  }
  std::printf(
      "perspective: %zu crossings, %zu too close to call, %zu with the wrong edge in front\n",
      total.records, total.skipped, total.wrong);
  CHECK(total.records > 1000);
  CHECK(total.skipped * 20 < total.records);
  CHECK_EQ(total.wrong, size_t{0});
  return check::finish("perspective");
}
