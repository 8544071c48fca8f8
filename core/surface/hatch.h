// Hatching for a plotter: the visible part of every face filled with parallel lines, clipped
// exactly to what the viewer sees of that face (the paper's Figure 4 shades squares with lines
// at an angle proportional to their distance).
//
// How: each face's hatch lines are laid on a lattice anchored at the origin (so the two halves
// of a split quad share their lines), clipped to the triangle, and each becomes a segment
// lying on the face. Its visible pieces are then found as an edge's would be: cut wherever it
// passes behind a face side (CUT's crossings against every triangle side), and the middle of
// each piece tested against the faces of its grid cell (solid/cover.h), the face's own polygon
// left out. A hatch line never crosses a visible edge of a nearer face: there it is behind it.
//
// Rounding: a hatch line's ends are where the exact line meets the triangle, rounded to steps
// (at most 1/2 step off the triangle's side); its depth is the face's plane there, rounded.
// This is the regions step of Franklin 1980 (steps 10-11) done per face instead of by building
// the planar graph of visible segments: each visible region of a face is exactly where its
// hatch lines are visible.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "memory/sized_stage.h"
#include "solid/mesh.h"
#include "status/status.h"
#include "view/trig.h"

namespace haloplot {

struct HatchParams {
  int32_t spacing = 120;           // steps between lines (1.5 mm at 80 steps/mm)
  int32_t angle_mdeg = 45000;      // the lines' angle for a face at depth 0
  int32_t mdeg_per_depth = 90000;  // added across the whole depth range (2^20): nearer, steeper
  bool front_only = true;          // hatch only faces facing the viewer (closed solids)
};

// The lines' direction for triangle t's polygon: its angle grows with the polygon's mean
// depth (Franklin's Figure 4). The polygon is the run of consecutive triangles with its id,
// so both halves of a quad agree.
SinCos hatch_direction(const SolidInput& in, uint32_t t, const HatchParams& params);

struct HatchStroke {
  uint32_t face;  // triangle
  uint32_t polygon;
  Edge3 line;  // the visible piece, ends rounded to steps
};

struct HatchSink {
  Status (*emit)(void* context, const HatchStroke& stroke);
  void* context;
};

struct HatchStats {
  uint32_t lines = 0;      // hatch segments laid (per triangle)
  uint64_t crossings = 0;  // where a hatch line passes behind a face side
  uint64_t pieces = 0, visible_pieces = 0, midpoint_tests = 0;
  size_t bytes_needed = 0;  // on kWorkspaceTooSmall: what the run had reached, plus the request
};

// A first estimate of the bytes (counts the hatch lines: O(faces + lines)); CUT's scratch
// depends on the lines' cells, so a short buffer answers kWorkspaceTooSmall with
// stats->bytes_needed, and a retry with that much succeeds.
size_t hatch_bytes(const SolidInput& in, const HatchParams& params, uint32_t crossing_capacity);

// kCrossingCapacity: stats->crossings says the count a retry needs.
Status hatch_faces(const SolidInput& in, const HatchParams& params, uint32_t crossing_capacity,
                   void* buffer, size_t bytes, HatchSink sink, HatchStats* stats);

// The per-face hatching as a sized stage (memory/sized_stage.h): needs.crossings is the
// capacity, needs.bytes what a short run reported.
struct HatchStage {
  const SolidInput* in;
  HatchParams params;
  HatchSink sink;
  HatchStats* stats;
  size_t bytes(const StageNeeds& needs) const { return hatch_bytes(*in, params, needs.crossings); }
  Status run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want) {
    const Status s = hatch_faces(*in, params, needs.crossings, buffer, bytes, sink, stats);
    if (s == Status::kCrossingCapacity) want->crossings = need_count(stats->crossings);
    if (s == Status::kWorkspaceTooSmall) want->bytes = stats->bytes_needed;
    return s;
  }
};

}  // namespace haloplot
