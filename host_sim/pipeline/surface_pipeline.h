// Franklin 1980's hidden lines on the host: buffers from the core's own query, a retry when a
// first capacity guess was short, and the pieces collected.
#pragma once
#include <vector>

#include "pipeline/solid_pipeline.h"
#include "surface/franklin.h"
#include "surface/hatch.h"

namespace haloplot::host {

struct FranklinRun {
  std::vector<FranklinPiece> pieces;
  FranklinStats stats;
  size_t bytes = 0;
  double ms = 0;  // the core run alone (the last attempt)
};

Status run_franklin(const SolidScene& scene, const FranklinParams& params, FranklinRun* out);

struct HatchRun {
  std::vector<HatchStroke> strokes;
  HatchStats stats;
};

// The hatching of every visible face (core/surface/hatch.h), retried until the buffer fits.
Status run_hatch(const SolidScene& scene, const HatchParams& params, HatchRun* out);

}  // namespace haloplot::host
