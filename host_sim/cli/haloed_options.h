// The options of a haloed drawing's two stages, shared by cut, draw and plot: CUT's grid and
// near-miss reach (--lambda, --cell, --cover, --reach) and DRAW's halo (--halo, --exact-halo).
#pragma once
#include <cstdint>
#include <set>
#include <string>

#include "cli/options.h"
#include "haloplot/haloplot.h"

namespace haloplot::host {

// The valued options of CUT, with -o: cut's whole list and a part of plot's.
extern const std::set<std::string> kCutValued;

// CUT's counter on a terminal: "CUT:  42% of N cells", rewritten in place.
void cut_progress(void*, uint32_t done, uint32_t total);

// CUT's settings from the options (the counter only when stderr is a terminal); false with
// *error naming the option.
bool cut_params(const Options& o, CutParams* p, std::string* error);
// DRAW's settings: --halo W is required.
bool draw_params(const Options& o, DrawParams* p, std::string* error);

}  // namespace haloplot::host
