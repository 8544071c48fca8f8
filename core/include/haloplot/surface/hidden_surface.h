// Franklin 1980 whole: hidden lines (steps 2-9), the regions of the visible segments and the
// face each shows (steps 10-11), and each face's regions hatched (a plotter's shading), in one
// caller buffer.
//
// Buffer: the visible segments first (segment_capacity of them), then Franklin's workspace,
// which the regions and the hatching reuse once the segments are in.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/surface/franklin.h"
#include "haloplot/surface/region_hatch.h"
#include "haloplot/surface/regions.h"

namespace haloplot {

struct HiddenSurfaceStats {
  FranklinStats franklin;
  RegionStats regions;
  RegionHatchStats hatch;
  uint32_t segments = 0;    // visible segments (the count a run needs on kSegmentCapacity)
  size_t bytes_needed = 0;  // on kWorkspaceTooSmall once the regions are known
};

// Bytes for everything but the hatching's list of line crossings (known once the regions are:
// a short buffer then answers kWorkspaceTooSmall with stats->bytes_needed).
size_t hidden_surface_bytes(const SolidInput& in, const FranklinParams& fp,
                            uint32_t crossing_capacity, uint32_t incidence_capacity,
                            uint32_t segment_capacity);

// `lines` receives the hidden-line pieces (runs of equal visibility, as franklin_hidden_lines
// gives them); `hatch` the strokes filling the visible regions. `buffer` starts on a
// kBufferAlignment (8) boundary, or the run returns kMisalignedBuffer (status/status.h).
Status hidden_surface(const SolidInput& in, const FranklinParams& fp, const HatchParams& hp,
                      uint32_t crossing_capacity, uint32_t incidence_capacity,
                      uint32_t segment_capacity, void* buffer, size_t bytes, FranklinSink lines,
                      HatchSink hatch, HiddenSurfaceStats* stats);

// hidden_surface() as a sized stage (memory/sized_stage.h): needs.crossings, .incidences and
// .segments are the capacities, needs.bytes what a short run reported.
struct HiddenSurfaceStage {
  const SolidInput* in;
  FranklinParams franklin;
  HatchParams hatch_params;
  FranklinSink lines;
  HatchSink hatch;
  HiddenSurfaceStats* stats;
  size_t bytes(const StageNeeds& needs) const {
    return hidden_surface_bytes(*in, franklin, needs.crossings, needs.incidences, needs.segments);
  }
  Status run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want);
};

}  // namespace haloplot
