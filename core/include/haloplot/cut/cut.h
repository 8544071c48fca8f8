// CUT (paper C1-C10): find every place where one projected edge passes behind another,
// using the adaptive uniform grid, and group the results by behind edge into a CUTSET.
//
// Memory: nothing is allocated. plan_cut() measures the scene and says how many scratch
// bytes run_cut() needs; the caller also hands run_cut() the storage the CUTSET lives in
// (cutset_bytes()). Scratch can be reused once run_cut() returns; the CUTSET storage must
// live as long as DRAW runs on it (it is what lets DRAW rerun with a new halo width). Both
// buffers start on a kBufferAlignment (8) boundary, or run_cut() returns kMisalignedBuffer and
// touches neither (status/status.h); the sizes asked are exact for aligned buffers.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/cut/cutset.h"
#include "haloplot/cut/grid.h"
#include "haloplot/memory/parts.h"
#include "haloplot/memory/sized_stage.h"
#include "haloplot/status/status.h"

namespace haloplot {

// Called now and then from the cell loop; the host tool draws a progress line with it.
using ProgressFn = void (*)(void* context, uint32_t cells_done, uint32_t cells_total);

// Phase boundaries inside run_cut(), for benchmarks that split the time as the paper's
// table does (T1: preprocessing = plan + cell lists; T2: intersections = pairs + grouping).
enum class CutPhase : uint8_t { kCellsFilled, kPairsTested };
using PhaseFn = void (*)(void* context, CutPhase phase);

struct CutParams {
  GridParams grid;
  CellCover cover = CellCover::kExact;
  // Cell lists hold a copy of each edge's projection beside its index (20 bytes per (cell,
  // edge) pair; on a 64-bit host 28, the depths too) instead of its index (4 bytes), so the
  // pair loop reads memory in order rather than jumping through the edge array: faster, at 16
  // (24) more bytes per pair. Off for tight RAM.
  bool compact_cells = true;
  // Record (and count) only the crossings whose position on the behind edge lies in rows
  // [row_lo, row_hi) (geometry/rows.h): a solid's band needs no cut outside its rows, and a
  // band one row high would otherwise store every crossing of the faces that meet it. (Beside
  // the other flags, where it fills padding: the params' copies on a controller's stack.)
  bool rows = false;
  int32_t reach = 0;  // also record near misses up to this many steps apart (exact halo); 0: off
  int32_t row_lo = 0, row_hi = 0;
  // A runner for the cell loop's and the grouping's parts (memory/parts.h), or null: the
  // CUTSET is the same with or without one. Progress is then reported by one part, from its
  // thread. A pointer, so the params stay as small as they were on a controller.
  const Parts* parts = nullptr;
  // Test only the pairs with at least one marked edge (bit e % 32 of marked[e / 32]); null:
  // every pair. The hidden lines mark the edges a crossing behind which can change a QI (folds,
  // contours on paper, irregular edges: solid/hidden_lines.cpp); a crossing behind any other
  // edge changes nothing, and on a smooth mesh those are all but a few of them.
  const uint32_t* marked = nullptr;
  ProgressFn progress = nullptr;
  void* progress_context = nullptr;
  PhaseFn phase = nullptr;  // optional
  void* phase_context = nullptr;
};

struct CutPlan {
  Grid grid;
  uint32_t n_edges = 0;
  uint32_t cell_pairs = 0;   // upper bound on (cell, edge) pairs (bounding boxes); sizes scratch
  size_t scratch_bytes = 0;  // what run_cut() needs as scratch
  CutParams params;
};

struct CutStats {
  uint32_t cell_pairs = 0;    // (cell, edge) pairs: the paper's CEPAIR size, exact
  uint64_t pairs_tested = 0;  // edge pairs examined inside cells (C6.1)
  uint64_t crossings = 0;     // crossings found, owned once each (also past capacity)
  uint64_t near_misses = 0;   // near-miss records found
  uint64_t rejected = 0;      // crossings seen in a cell that does not own them (C6.3)
  uint64_t equal_depth = 0;   // crossings where both edges have the same depth: not cut
  uint64_t outside_rows = 0;  // crossings outside CutParams' rows: not recorded, not counted
  uint32_t max_per_edge = 0;  // the largest group, which sizes DRAW's scratch
};

// Check the scene, choose the grid and bound the (cell, edge) pairs: O(N), no cell walk.
Status plan_cut(const Edge3* edges, uint32_t n, const CutParams& params, CutPlan* plan);

// Run CUT. On kCrossingCapacity, stats->crossings + stats->near_misses is the record count a
// retry needs; the CUTSET is left empty (never half-filled).
Status run_cut(const CutPlan& plan, const Edge3* edges, void* scratch, size_t scratch_bytes,
               void* cutset_storage, size_t cutset_storage_bytes, CutSet* out, CutStats* stats);

// CUT as a sized stage (memory/sized_stage.h): the CUTSET with needs.crossings records at the
// buffer's start (it outlives CUT), the scratch after it.
struct CutStage {
  const CutPlan* plan;
  const Edge3* edges;
  CutSet* out;
  CutStats* stats;
  size_t bytes(const StageNeeds& needs) const;
  Status run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want);
};

}  // namespace haloplot
