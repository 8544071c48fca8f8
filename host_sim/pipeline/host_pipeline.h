// The core's CUT and DRAW on the host: buffers sized by the core's sized-stage protocol
// (memory/sized_stage.h), and timings that cover CUT or DRAW alone.
#pragma once
#include <cstdint>
#include <vector>

#include "haloplot/band/conductor.h"
#include "haloplot/haloplot.h"
#include "pipeline/host_memory.h"
#include "pipeline/parted_memory.h"

namespace haloplot::host {

struct HostCut {
  std::vector<Edge3> edges;  // owned copy: the CUTSET points into it
  PartedWords storage;       // the CUTSET at its start (8-byte aligned), then CUT's scratch
  CutPlan plan;
  CutSet set;
  CutStats stats;
  double cut_ms = 0;  // plan and every run, no I/O
  int retries = 0;    // runs after the first (each reruns CUT with the count it reported)
  size_t scratch_bytes = 0;
};

// Runs CUT on `edges`; returns the core's status (kOk, or the reason it failed).
Status host_cut(std::vector<Edge3> edges, const CutParams& params, HostCut* out);

struct HostDraw {
  std::vector<Span> spans;
  DrawStats stats;
  double draw_ms = 0;
  size_t scratch_bytes = 0;
};

Status host_draw(const CutSet& set, const DrawParams& params, HostDraw* out);

// CUT and DRAW in bands in an arena of `arena_bytes`, as a controller with that arena runs
// them (band/conductor.h): the same visible pieces as host_cut + host_draw, in the same order
// (by edge, then along it). draw_ms covers the whole banded run. `cut` and `draw` in the
// edges' units, 2^-substep_bits steps; the spans' segments come out in units too.
Status host_banded_draw(const std::vector<Edge3>& edges, const CutParams& cut,
                        const DrawParams& draw, size_t arena_bytes, HostDraw* out, BandStats* bands,
                        int32_t substep_bits = 0);

}  // namespace haloplot::host
