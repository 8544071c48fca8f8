// Where a banded plot reads its edges from: any random-access reader of projected edges. The
// band conductor reads the whole scene once per band and keeps only the edges that meet the
// band, so the scene itself never has to sit in the arena: it may be an array in flash or on
// the host, a generator (the demo's cube array, built edge by edge on the chip), or a file.
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"
#include "haloplot/status/status.h"

namespace haloplot {

struct EdgeSource {
  void* ctx = nullptr;
  uint32_t n = 0;  // edges in the scene; edge i is the i-th of the scene's order
  // Copy edges [first, first + count) to out; count is at most kEdgeSourceChunk.
  Status (*read)(void* ctx, uint32_t first, uint32_t count, Edge3* out) = nullptr;
};

// The conductor reads this many edges per call (a small stack buffer).
inline constexpr uint32_t kEdgeSourceChunk = 32;

// Every edge of the source in order, visit(index, edge) for each; a read's failure stops it.
template <typename Visit>
Status for_each_edge(const EdgeSource& source, Visit visit) {  // visit returns false to stop
  Edge3 chunk[kEdgeSourceChunk];
  for (uint32_t first = 0; first < source.n; first += kEdgeSourceChunk) {
    const uint32_t count =
        source.n - first < kEdgeSourceChunk ? source.n - first : kEdgeSourceChunk;
    const Status s = source.read(source.ctx, first, count, chunk);
    if (!ok(s)) return s;
    for (uint32_t i = 0; i < count; ++i)
      if (!visit(first + i, chunk[i])) return Status::kOk;
  }
  return Status::kOk;
}

// A source over an edge array the caller keeps alive.
inline EdgeSource array_edge_source(const Edge3* edges, uint32_t n) {
  EdgeSource s;
  s.ctx = const_cast<Edge3*>(edges);
  s.n = n;
  s.read = [](void* ctx, uint32_t first, uint32_t count, Edge3* out) {
    const Edge3* e = static_cast<const Edge3*>(ctx) + first;
    for (uint32_t i = 0; i < count; ++i) out[i] = e[i];
    return Status::kOk;
  };
  return s;
}

}  // namespace haloplot
