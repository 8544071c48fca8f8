// Hatching the regions of Franklin's step 11: each visible region is filled with its face's
// parallel lines, clipped exactly to the region.
//
// A face's lines are the levels n . p = k S (n the lines' normal, S the spacing) of a lattice
// anchored at the origin. Every boundary half-edge of a cycle naming the face has the region on
// its left, so walking along a line, crossing a half-edge from its right to its left enters the
// region and the other way leaves it: the union of the face's regions, holes included, is where
// the count is positive, and no region needs pairing with its holes. Whether a half-edge meets a
// level is decided exactly at its rational ends (w < level at one end and not at the other,
// half-open, so a line through a node counts each boundary passing through it once).
//
// Rounding: only where a line meets a half-edge is rounded, to 1/256 step for the order along
// the line and then to the nearest step for the stroke's ends (within 1/2 + 1/256 step of the
// exact boundary).
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/surface/hatch.h"
#include "haloplot/surface/regions.h"

namespace haloplot {

struct RegionHatchStats {
  uint32_t faces = 0;      // faces hatched (a face's regions share their lines)
  uint64_t crossings = 0;  // where lines meet region boundaries
  uint64_t strokes = 0;
};

size_t region_hatch_bytes(const SolidInput& in, const Regions& r, const HatchParams& params);

Status hatch_regions(const SolidInput& in, const Regions& r, const HatchParams& params,
                     void* buffer, size_t bytes, HatchSink sink, RegionHatchStats* stats);

}  // namespace haloplot
