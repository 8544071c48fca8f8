// The hidden-line options `plot` and the .job file share: the mode, the dash in mm, the
// outline pass and the method, parsed exactly (millimetres to thousandths, no floating point).
#pragma once
#include <string>

#include "cli/options.h"
#include "haloplot/surface/hatch.h"
#include "pipeline/drawing_modes.h"

namespace haloplot::host {

struct SolidOptions {
  ModeSpec spec;
  HiddenMethod method = HiddenMethod::kAuto;
  uint32_t steps_per_mm = 80;
  bool hatch = false;  // --hatch SPACING[,ANGLE[,DEGREES_ACROSS_DEPTH]] (mm, degrees)
  HatchParams hatch_params;
  const Parts* parts = nullptr;  // the threads CUT's parts run on (none: one thread)
};

// Options: --mode, --dash LEN,GAP (mm), --steps-per-mm N, --method auto|qi|fallback, --outline,
// --hatch SPACING[,ANGLE[,DEGREES_ACROSS_DEPTH]].
bool parse_solid_options(const Options& o, SolidOptions* out, std::string* error);

// "2", "0.5", "1.25" mm to plot steps, rounded to the nearest; false if not such a number.
bool mm_to_steps(const std::string& text, uint32_t steps_per_mm, int32_t* steps);

// Runs the hidden-line stages as the options say (Kira's shortcuts on for the fallback).
Status run_solid_options(const SolidScene& scene, const SolidOptions& so, SolidRun* run);

}  // namespace haloplot::host
