#include "haloplot/cut/cut.h"

#include "cut/near_miss.h"
#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/predicates.h"
#include "haloplot/geometry/rows.h"
#include "memory/carve.h"
#include "sort/in_place_sort.h"

namespace haloplot {

uint32_t cutset_capacity(uint32_t n_edges, size_t bytes) {
  const size_t index = (size_t{n_edges} + 1) * sizeof(uint32_t);
  if (bytes < index) return 0;
  const size_t cap = (bytes - index) / sizeof(Crossing);
  return cap > 0xffffffffu ? 0xffffffffu : static_cast<uint32_t>(cap);
}

namespace {

// What a cell list holds per (cell, edge) pair: the edge's index, or a compact copy of its
// projected endpoints with the index (CutParams::compact_cells). Both read like an edge.
struct IndexEntry {
  uint32_t edge;
  static IndexEntry make(const Edge3&, uint32_t i) { return IndexEntry{i}; }
};
struct Point2 {
  int32_t x, y;
};
struct CompactEntry {
  Point2 a, b;
  uint32_t edge;
  static CompactEntry make(const Edge3& e, uint32_t i) {
    return CompactEntry{{e.a.x, e.a.y}, {e.b.x, e.b.y}, i};
  }
};
inline const Edge3& geometry(const IndexEntry& x, const Edge3* edges) { return edges[x.edge]; }
inline const CompactEntry& geometry(const CompactEntry& x, const Edge3*) { return x; }

size_t entry_bytes(const CutParams& p) {
  return p.compact_cells ? sizeof(CompactEntry) : sizeof(IndexEntry);
}

// Scratch layout: cell_start[cells + 1], then the cell lists (cell_pairs entries). After the
// cell loop the same bytes hold next[n_edges] for grouping, so the scratch is the larger.
size_t scratch_for(uint32_t cells, uint32_t cell_pairs, uint32_t n_edges, size_t entry) {
  const size_t grid_part = carve_round((size_t{cells} + 1) * 4) + size_t{cell_pairs} * entry;
  const size_t group_part = size_t{n_edges} * 4;
  return grid_part > group_part ? grid_part : group_part;
}

struct Recorder {
  Crossing* out;
  uint32_t capacity;
  bool rows = false;  // CutParams::rows
  int32_t row_lo = 0, row_hi = 0;
  uint32_t stored = 0;
  bool overflow = false;

  void add(uint32_t behind, uint32_t front, uint32_t t) {
    if (stored == capacity) {
      overflow = true;  // keep counting so the caller learns the size it needs
      return;
    }
    out[stored++] = Crossing{behind, front, t};
  }
};

// The cell being scanned: its index and its half-open extent [x0, x0 + side) x [y0, y0 + side).
struct CellBox {
  uint32_t index;
  int64_t x0, y0, side;
};

// Does the cell hold the crossing point a + d * n / den (per axis)? Exact, and division-free:
// x0 <= a + d n / den < x0 + side  <=>  (x0 - a) den <= d n < (x0 + side - a) den, den > 0.
// Every product stays below 2^21 * 2^41 = 2^62.
inline bool owns(const CellBox& cb, int32_t ax, int32_t dx, int32_t ay, int32_t dy, int64_t n,
                 int64_t den) {
  const int64_t px = int64_t{dx} * n, py = int64_t{dy} * n;
  return (cb.x0 - ax) * den <= px && px < (cb.x0 + cb.side - ax) * den &&
         (cb.y0 - ay) * den <= py && py < (cb.y0 + cb.side - ay) * den;
}

// C6.2-C6.5 for one pair inside a cell whose boxes overlap; edge ei < edge ej. The projected
// test runs on the cell entries; depths and near misses go back to the full edges.
template <typename Entry>
void test_pair(const Grid& g, const CellBox& cb, const Edge3* edges, const Entry& ei,
               const Entry& ej, int32_t reach, Recorder& rec, CutStats& st) {
  const auto& p = geometry(ei, edges);
  const auto& q = geometry(ej, edges);
  const uint32_t ep = ei.edge, eq = ej.edge;
  const CrossingTest x = test_crossing(p, q);
  if (x.crosses) {
    // C6.3: report the crossing only in the cell that holds it, decided exactly.
    if (!owns(cb, p.a.x, p.b.x - p.a.x, p.a.y, p.b.y - p.a.y, x.tn, x.den)) {
      ++st.rejected;
      return;
    }
    const int depth = compare_depth_at_crossing(edges[ep], edges[eq], x);  // C6.4
    if (depth == 0) {
      ++st.equal_depth;
      return;
    }
    const uint32_t behind = depth < 0 ? ep : eq, front = depth < 0 ? eq : ep;
    const uint32_t t = frac_q32_small(depth < 0 ? x.tn : x.un, x.den);
    if (rec.rows && !position_in_rows(edges[behind], t, rec.row_lo, rec.row_hi)) {
      ++st.outside_rows;
      return;
    }
    ++st.crossings;
    rec.add(behind, front, t);
    return;
  }
  if (reach <= 0) return;
  const NearMiss m = test_near_miss(edges[ep], edges[eq], reach);
  if (!m.found || g.cell_of(m.ex, m.ey) != cb.index) return;
  ++st.near_misses;
  if (m.p_behind)
    rec.add(ep, eq | Crossing::kNearBit, m.t_behind);
  else
    rec.add(eq, ep | Crossing::kNearBit, m.t_behind);
}

// C3-C6 for one kind of cell entry.
//
// C3-C5 are a two-pass counting sort: count edges per cell, turn counts into end offsets,
// then drop each edge into its cell from the back. Edges are walked in descending order so
// every cell's list comes out ascending. No comparison sort, no linked lists.
template <typename Entry>
void fill_and_test(const CutPlan& plan, const Edge3* edges, void* scratch, Recorder& rec,
                   CutStats& st) {
  const uint32_t n = plan.n_edges;
  const Grid& g = plan.grid;
  const uint32_t cells = g.cells();
  uint32_t* cell_start = static_cast<uint32_t*>(scratch);
  Entry* list = reinterpret_cast<Entry*>(cell_start + ((size_t{cells} + 1 + 1) & ~size_t{1}));
  for (uint32_t c = 0; c <= cells; ++c) cell_start[c] = 0;
  for (uint32_t i = 0; i < n; ++i)
    for_each_cell(g, edges[i], plan.params.cover, plan.params.reach,
                  [&](uint32_t c) { ++cell_start[c + 1]; });
  for (uint32_t c = 0; c < cells; ++c) cell_start[c + 1] += cell_start[c];
  const uint32_t total = cell_start[cells];
  for (uint32_t i = n; i-- > 0;) {
    const Entry e = Entry::make(edges[i], i);
    for_each_cell(g, edges[i], plan.params.cover, plan.params.reach,
                  [&](uint32_t c) { list[--cell_start[c + 1]] = e; });
  }
  // Each cell_start[c + 1] now holds the start of cell c; shift back into place.
  for (uint32_t c = 0; c < cells; ++c) cell_start[c] = cell_start[c + 1];
  cell_start[cells] = total;
  st.cell_pairs = cell_start[cells];  // the exact count (the plan's is an upper bound)
  if (plan.params.phase) plan.params.phase(plan.params.phase_context, CutPhase::kCellsFilled);

  // C6: every pair inside every cell.
  const int32_t r = plan.params.reach;
  uint32_t col = 0, row = 0;
  for (uint32_t c = 0; c < cells; ++c) {
    const uint32_t begin = cell_start[c], end = cell_start[c + 1];
    const uint64_t k = end - begin;
    st.pairs_tested += k * (k - 1) / 2;
    const CellBox cb{c, g.ox + int64_t{col} * g.cell, g.oy + int64_t{row} * g.cell, g.cell};
    for (uint32_t i = begin; i + 1 < end; ++i) {
      // P's box once per row, then Q's box against it: a cheap reject before the exact
      // test, since most pairs sharing a cell do not even overlap.
      const auto& p = geometry(list[i], edges);
      const int32_t px0 = min_i32(p.a.x, p.b.x) - r, px1 = max_i32(p.a.x, p.b.x) + r;
      const int32_t py0 = min_i32(p.a.y, p.b.y) - r, py1 = max_i32(p.a.y, p.b.y) + r;
      for (uint32_t j = i + 1; j < end; ++j) {
        const auto& q = geometry(list[j], edges);
        const int32_t qx0 = min_i32(q.a.x, q.b.x), qx1 = max_i32(q.a.x, q.b.x);
        const int32_t qy0 = min_i32(q.a.y, q.b.y), qy1 = max_i32(q.a.y, q.b.y);
        // One branch on all four (not four that each mispredict): most pairs are rejected.
        if ((qx1 < px0) | (qx0 > px1) | (qy1 < py0) | (qy0 > py1)) continue;
        test_pair(g, cb, edges, list[i], list[j], r, rec, st);
      }
    }
    if (plan.params.progress && (c & 0x3ffu) == 0)
      plan.params.progress(plan.params.progress_context, c, cells);
    if (++col == g.nx) {
      col = 0;
      ++row;
    }
  }
}

// Moves the records into their behind edge's group ([first[e], first[e + 1]), next[e] its
// first free slot). When the scratch holds a copy of the records beside `next` (it does when
// the cell lists were the larger, as on big scenes), they are scattered from the copy: the
// writes do not wait on one another. Otherwise in place (an American-flag permutation), so
// the records never need a second buffer; there each move waits on the read before it, a
// cache miss apiece on a big scene. Either way the groups hold the same records (their order
// inside a group is the sort's business below).
void group_records(Crossing* records, uint32_t stored, uint32_t n, const uint32_t* first,
                   uint32_t* next, void* scratch, size_t scratch_bytes) {
  const size_t copy_at = carve_round(size_t{n} * sizeof(uint32_t));
  if (scratch_bytes >= copy_at + size_t{stored} * sizeof(Crossing)) {
    Crossing* copy = reinterpret_cast<Crossing*>(static_cast<uint8_t*>(scratch) + copy_at);
    for (uint32_t i = 0; i < stored; ++i) copy[i] = records[i];
    for (uint32_t i = 0; i < stored; ++i) records[next[copy[i].behind]++] = copy[i];
    return;
  }
  for (uint32_t e = 0; e < n; ++e) {
    while (next[e] < first[e + 1]) {
      Crossing x = records[next[e]];
      while (x.behind != e) {  // park x in its own bucket, pick up what was there
        const uint32_t j = next[x.behind]++;
        const Crossing y = records[j];
        records[j] = x;
        x = y;
      }
      records[next[e]++] = x;
    }
  }
}

}  // namespace

Status plan_cut(const Edge3* edges, uint32_t n, const CutParams& params, CutPlan* plan) {
  if (n > kMaxEdges) return Status::kTooManyEdges;
  if (params.reach < 0 || params.reach > kCoordMax || params.grid.lambda_q8 == 0)
    return Status::kBadParameter;
  for (uint32_t i = 0; i < n; ++i)
    if (!in_range(edges[i])) return Status::kCoordinateOutOfRange;
  CutPlan p;
  p.params = params;
  p.n_edges = n;
  p.grid = choose_grid(edges, n, params.grid);
  // An upper bound on the (cell, edge) pairs from each edge's (dilated) bounding box: pure
  // arithmetic, no walk. The exact cover visits a subset of these cells, so the scratch sized
  // from the bound always suffices; run_cut() reports the exact count in its stats.
  uint64_t pairs = 0;
  const Grid& g = p.grid;
  const int32_t xmax = g.ox + static_cast<int32_t>(g.nx) * g.cell - 1;
  const int32_t ymax = g.oy + static_cast<int32_t>(g.ny) * g.cell - 1;
  const int32_t r = params.reach;
  for (uint32_t i = 0; i < n; ++i) {
    const Edge3& e = edges[i];
    const uint32_t c0 = g.col(max_i32(min_i32(e.a.x, e.b.x) - r, g.ox));
    const uint32_t c1 = g.col(min_i32(max_i32(e.a.x, e.b.x) + r, xmax));
    const uint32_t r0 = g.row(max_i32(min_i32(e.a.y, e.b.y) - r, g.oy));
    const uint32_t r1 = g.row(min_i32(max_i32(e.a.y, e.b.y) + r, ymax));
    pairs += uint64_t{c1 - c0 + 1} * (r1 - r0 + 1);
  }
  if (pairs > 0xffffffffu) return Status::kCellPairOverflow;
  p.cell_pairs = static_cast<uint32_t>(pairs);
  p.scratch_bytes = scratch_for(p.grid.cells(), p.cell_pairs, n, entry_bytes(params));
  *plan = p;
  return Status::kOk;
}

Status run_cut(const CutPlan& plan, const Edge3* edges, void* scratch, size_t scratch_bytes,
               void* cutset_storage, size_t cutset_storage_bytes, CutSet* out, CutStats* stats) {
  CutStats st;
  const uint32_t n = plan.n_edges;
  const uint32_t cells = plan.grid.cells();
  if (buffer_misaligned(scratch) || buffer_misaligned(cutset_storage))
    return Status::kMisalignedBuffer;
  if (scratch_bytes < plan.scratch_bytes) return Status::kWorkspaceTooSmall;
  if (cutset_storage_bytes < cutset_bytes(n, 0)) return Status::kCutsetStorageTooSmall;

  uint32_t* first = static_cast<uint32_t*>(cutset_storage);
  Crossing* records = reinterpret_cast<Crossing*>(first + n + 1);
  Recorder rec{records, cutset_capacity(n, cutset_storage_bytes), plan.params.rows,
               plan.params.row_lo, plan.params.row_hi};
  if (plan.params.compact_cells)
    fill_and_test<CompactEntry>(plan, edges, scratch, rec, st);
  else
    fill_and_test<IndexEntry>(plan, edges, scratch, rec, st);
  if (plan.params.progress) plan.params.progress(plan.params.progress_context, cells, cells);
  if (plan.params.phase) plan.params.phase(plan.params.phase_context, CutPhase::kPairsTested);

  if (stats) *stats = st;
  if (rec.overflow) {
    *out = CutSet{};
    return Status::kCrossingCapacity;
  }

  // C7-C9: group by behind edge with a counting sort. `next` reuses the scratch: the cell
  // lists are no longer needed.
  uint32_t* next = static_cast<uint32_t*>(scratch);
  for (uint32_t e = 0; e <= n; ++e) first[e] = 0;
  for (uint32_t i = 0; i < rec.stored; ++i) ++first[records[i].behind + 1];
  for (uint32_t e = 0; e < n; ++e) first[e + 1] += first[e];
  for (uint32_t e = 0; e < n; ++e) next[e] = first[e];
  group_records(records, rec.stored, n, first, next, scratch, scratch_bytes);
  // Order each group along its edge; ties (several edges through one point) by front index
  // so the output never depends on cell order.
  for (uint32_t e = 0; e < n; ++e) {
    const uint32_t k = first[e + 1] - first[e];
    if (k > st.max_per_edge) st.max_per_edge = k;
    sort_in_place(records + first[e], k, [](const Crossing& a, const Crossing& b) {
      return a.t != b.t ? a.t < b.t : a.front < b.front;
    });
  }

  out->edges = edges;
  out->n_edges = n;
  out->first = first;
  out->crossings = records;
  out->n_crossings = rec.stored;
  out->reach = plan.params.reach;
  if (stats) *stats = st;
  return Status::kOk;
}

size_t CutStage::bytes(const StageNeeds& needs) const {
  return carve_round(cutset_bytes(plan->n_edges, needs.crossings)) +
         carve_round(plan->scratch_bytes);
}

Status CutStage::run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want) {
  const size_t cutset = carve_round(cutset_bytes(plan->n_edges, needs.crossings));
  const size_t scratch = carve_round(plan->scratch_bytes);
  if (bytes < cutset + scratch) {
    want->bytes = cutset + scratch;
    return Status::kWorkspaceTooSmall;
  }
  uint8_t* base = static_cast<uint8_t*>(buffer);
  const Status s = run_cut(*plan, edges, base + cutset, bytes - cutset, base, cutset, out, stats);
  if (s == Status::kCrossingCapacity)
    want->crossings = need_count(stats->crossings + stats->near_misses);
  return s;
}

}  // namespace haloplot
