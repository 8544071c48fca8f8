// Franklin 1980's hidden lines on the host: buffers by the core's sized-stage protocol
// (memory/sized_stage.h), and the pieces collected.
#pragma once
#include <vector>

#include "haloplot/surface/franklin.h"
#include "haloplot/surface/hatch.h"
#include "haloplot/surface/hidden_surface.h"
#include "pipeline/solid_pipeline.h"

namespace haloplot::host {

struct FranklinRun {
  std::vector<FranklinPiece> pieces;
  FranklinStats stats;
  size_t bytes = 0;
  double ms = 0;  // the core run alone (the last round)
};

Status run_franklin(const SolidScene& scene, const FranklinParams& params, FranklinRun* out);

// Steps 10-11 on their own, copied out of the core's buffer (for tests and --stats).
struct RegionsRun {
  std::vector<RegionSegment> segments;
  std::vector<uint32_t> node, cycle, cycle_face;
  std::vector<uint8_t> kept, cycle_bounded;
  uint32_t n_nodes = 0;
  RegionStats stats;
};

Status run_regions(const SolidScene& scene, const FranklinParams& params, RegionsRun* out);

// kRegions: Franklin's steps 10-11 (the regions of the visible segments, each hatched as the
// face it shows: core/include/haloplot/surface/hidden_surface.h). kLines: every face's own lines,
// what shows of each decided like an edge's (core/include/haloplot/solid/hatch_lines.h, in the
// hidden-line run: what the job, the bands and the controller draw). The tests compare the two.
enum class HatchMethod { kRegions, kLines };

struct HatchRun {
  std::vector<HatchStroke> strokes;
  HatchLineStats lines;        // kLines
  HiddenSurfaceStats surface;  // kRegions
  double ms = 0;               // the core run alone (the last round)
};

// The hatching of every visible face, in buffers sized by the sized-stage protocol.
Status run_hatch(const SolidScene& scene, const HatchParams& params, HatchRun* out,
                 HatchMethod method = HatchMethod::kRegions, FranklinParams franklin = {});

}  // namespace haloplot::host
