// CUTSET (paper C8-C10): for every edge, the places where it passes behind another edge,
// ordered along it. Edges with no crossing keep an empty group (C9), so DRAW sees every edge.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/geometry/contract.h"

namespace haloplot {

// One place where `behind` passes behind `front` (paper C6.5's triple). 12 bytes.
struct Crossing {
  uint32_t behind;
  uint32_t front;  // bit 31 set: a near miss (closest approach within reach), not a crossing
  uint32_t t;      // position along `behind`: floor(t * 2^32), t from its first endpoint

  static constexpr uint32_t kNearBit = 0x80000000u;
  uint32_t front_edge() const { return front & ~kNearBit; }
  bool near_miss() const { return (front & kNearBit) != 0; }
};

// Edge indices use 31 bits so the near-miss flag fits in the record.
inline constexpr uint32_t kMaxEdges = 0x7fffffffu;

struct CutSet {
  const Edge3* edges = nullptr;
  uint32_t n_edges = 0;
  // Crossings of edge e are crossings[first[e] .. first[e + 1]), sorted by (t, front).
  const uint32_t* first = nullptr;
  const Crossing* crossings = nullptr;
  uint32_t n_crossings = 0;
  int32_t reach = 0;  // near misses up to this distance (steps) were recorded; 0: none

  uint32_t count(uint32_t e) const { return first[e + 1] - first[e]; }
  const Crossing* begin(uint32_t e) const { return crossings + first[e]; }
};

// Bytes of caller storage a CUTSET with room for `capacity` records needs: the per-edge index
// (4 bytes per edge + 4) followed by the records (12 bytes each). constexpr, so static storage
// can be sized with it.
constexpr size_t cutset_bytes(uint32_t n_edges, uint32_t capacity) {
  return (size_t{n_edges} + 1) * sizeof(uint32_t) + size_t{capacity} * sizeof(Crossing);
}
// The record capacity that `bytes` of storage gives for n_edges (0 if even the index won't fit).
uint32_t cutset_capacity(uint32_t n_edges, size_t bytes);

}  // namespace haloplot
