// A drawing worked out in bands within an arena (plot --arena, sim of a job with an arena): the
// refusal when the arena is too small, and the bands' --stats lines.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "haloplot/band/conductor.h"

namespace haloplot::host {

// "CMD: arena of A bytes too small: a band one row high needs N where the plot stopped ...":
// N is the band where the plot stopped, not the job's least arena (what a band needs depends
// on what the band below hands it).
std::string arena_too_small(const std::string& cmd, uint64_t arena, uint64_t need_bytes);

void print_band_stats(const BandStats& b, size_t arena);

}  // namespace haloplot::host
