// What cut, draw and plot write and report of a haloed drawing: the .cut file's statistics
// header, the SVG and spans, the --stats lines of CUT and DRAW, and the warning when the exact
// halo is wider than the near misses CUT kept.
#pragma once
#include <cstdint>
#include <string>

#include "cli/options.h"
#include "pipeline/host_pipeline.h"

namespace haloplot::host {

// The CUT statistics that do not depend on the machine, so a .cut file stays deterministic.
std::string cut_header(const HostCut& c);

// --stats: CUT's and DRAW's counters and times on stderr.
void print_cut_stats(const HostCut& c);
void print_draw_stats(const HostDraw& d);

// Writes the SVG and, if asked, the spans. `model`: the scene was a model the projection
// fitted (centred on the page). Returns 0 or 1 after reporting.
int write_drawing(const Options& o, const HostDraw& d, bool model);

// Warns when DRAW's exact halo reached past the near misses CUT kept (`reach`, in steps).
void warn_reach(const HostDraw& d, int32_t halo, int32_t reach);

}  // namespace haloplot::host
