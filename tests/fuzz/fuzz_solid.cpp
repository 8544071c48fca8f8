// Hidden lines under heavy degeneracy: triangular prisms with corners on a coarse lattice, each
// in its own depth slab (so no two solids pierce each other, whatever their overlap on paper),
// seen straight on or from a view the input picks. Coarse corners make vertices land on edges
// and on each other, edges overlap, faces go edge-on: every singular rule fires. The property:
// QI propagation meets no conflict and agrees with the topology-free fallback at the middle of
// every piece; Kira's shortcuts and Franklin 1980 (blocking faces, c from 1 to 4) see the same
// visibility; Franklin's regions (steps 10-11) meet Euler's relation. Any disagreement aborts.
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "pipeline/surface_pipeline.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;
using namespace solid_scenes;

namespace {

int32_t qi_at(const std::vector<SolidPiece>& p, uint32_t e, int64_t m) {
  for (const SolidPiece& x : p)
    if (x.edge == e && x.t0 <= m && m < x.t1) return x.q;
  return kQiUnknown;
}

bool hidden_at(const std::vector<SolidPiece>& p, uint32_t e, int64_t m) {
  for (const SolidPiece& x : p)
    if (x.edge == e && x.t0 <= m && m < x.t1) return x.hidden;
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const bool straight_on = data[0] & 1;
  const int32_t az = int32_t(data[0] >> 1) * 2835, el = int32_t(data[1]) * 706 - 90000;
  Mesh m;
  size_t i = 2;
  for (int k = 0; k < 6 && i + 6 <= size; ++k, i += 6) {
    std::vector<std::pair<int32_t, int32_t>> tri;
    for (int c = 0; c < 3; ++c)
      tri.push_back({int32_t(data[i + 2 * c] % 9) * 1000, int32_t(data[i + 2 * c + 1] % 9) * 1000});
    // Counter-clockwise, and not flat (a flat prism is not a solid).
    const int64_t area = int64_t(tri[1].first - tri[0].first) * (tri[2].second - tri[0].second) -
                         int64_t(tri[1].second - tri[0].second) * (tri[2].first - tri[0].first);
    if (area == 0) continue;
    if (area < 0) std::swap(tri[1], tri[2]);
    prism(&m, tri, k * 3000, k * 3000 + 1000 + int32_t(data[i] % 3) * 500);
  }
  if (m.faces.empty()) return 0;
  SolidScene s;
  if (straight_on) {
    s.vertices = m.v;
    s.edge_pairs = polygon_edges(m);
    s.triangles = triangulate(m.v, m.faces, nullptr);
  } else if (!project(m, view(az, el), &s)) {
    return 0;
  }
  SolidRun qi, fb, kira;
  if (run_hidden_lines(s, HiddenMethod::kQi, FallbackParams{}, &qi, true) != Status::kOk)
    std::abort();
  if (run_hidden_lines(s, HiddenMethod::kFallback, FallbackParams{}, &fb) != Status::kOk)
    std::abort();
  FallbackParams k;
  k.use_classes = k.use_vc = true;
  if (run_hidden_lines(s, HiddenMethod::kFallback, k, &kira) != Status::kOk) std::abort();
  if (qi.qi.conflicts != 0) std::abort();
  FranklinParams fp;
  fp.c_q8 = 256u + data[1] % 4u * 256u;  // c from 1 to 4: more cells, more blocking faces
  FranklinRun fr;
  if (run_franklin(s, fp, &fr) != Status::kOk) std::abort();
  for (const SolidPiece& p : fb.pieces) {
    if (p.t1 - p.t0 < 2) continue;
    const int64_t mid = p.t0 + (p.t1 - p.t0) / 2;
    if (qi_at(qi.pieces, p.edge, mid) != p.q) std::abort();
    if (hidden_at(kira.pieces, p.edge, mid) != (p.q != 0)) std::abort();
    bool fh = false, found = false;
    for (const FranklinPiece& x : fr.pieces)
      if (x.edge == p.edge && x.t0 <= mid && mid < x.t1) fh = x.hidden, found = true;
    if (!found || fh != (p.q != 0)) std::abort();
  }
  // Franklin's regions: consistent half-edges and Euler's relation, V - E + bounded cycles =
  // connected pieces = hole cycles (pieces counted here by union-find).
  RegionsRun rr;
  if (run_regions(s, fp, &rr) != Status::kOk || rr.stats.overlaps != 0) std::abort();
  std::vector<uint32_t> parent(rr.n_nodes), used(rr.n_nodes, 0);
  for (uint32_t v = 0; v < rr.n_nodes; ++v) parent[v] = v;
  auto find = [&](uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  int64_t edges = 0, nodes = 0, pieces = 0;
  for (size_t g = 0; g < rr.segments.size(); ++g) {
    if (!rr.kept[g]) continue;
    ++edges;
    used[rr.node[2 * g]] = used[rr.node[2 * g + 1]] = 1;
    parent[find(rr.node[2 * g])] = find(rr.node[2 * g + 1]);
  }
  for (uint32_t v = 0; v < rr.n_nodes; ++v) {
    nodes += used[v];
    pieces += used[v] && find(v) == v;
  }
  if (int64_t{rr.stats.holes} != pieces || nodes - edges + int64_t{rr.stats.bounded} != pieces)
    std::abort();
  return 0;
}
