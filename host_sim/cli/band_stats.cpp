#include "cli/band_stats.h"

#include <cstdio>

namespace haloplot::host {

std::string arena_too_small(const std::string& cmd, uint64_t arena, uint64_t need_bytes) {
  return cmd + ": arena of " + std::to_string(arena) + " bytes too small: a band one row " +
         "high needs " + std::to_string(need_bytes) +
         " where the plot stopped (bands further on may need more)";
}

void print_band_stats(const BandStats& b, size_t arena) {
  std::fprintf(stderr,
               "arena=%zu\nbands=%u\nband_splits=%u\nmargin_bands=%u\nband_margin=%d\n"
               "band_peak_bytes=%zu\nband_most_edges=%u\nband_most_pieces=%u\n"
               "band_most_carry=%u\nband_edge_reads=%llu\nband_cut_runs=%llu\nband_edges=%llu\n"
               "band_deferred=%llu\nband_turned=%d\n",
               arena, b.bands, b.splits, b.margin_bands, b.margin, b.peak_bytes, b.most_edges,
               b.most_pieces, b.most_carry, (unsigned long long)b.edge_reads,
               (unsigned long long)b.cut_runs, (unsigned long long)b.band_edges,
               (unsigned long long)b.deferred, b.turned ? 1 : 0);
}

}  // namespace haloplot::host
