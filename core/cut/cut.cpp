#include "cut/cut.h"

#include "cut/near_miss.h"
#include "geometry/fraction.h"
#include "geometry/predicates.h"
#include "sort/in_place_sort.h"

namespace haloplot {

size_t cutset_bytes(uint32_t n_edges, uint32_t capacity) {
  return (size_t{n_edges} + 1) * sizeof(uint32_t) + size_t{capacity} * sizeof(Crossing);
}

uint32_t cutset_capacity(uint32_t n_edges, size_t bytes) {
  const size_t index = (size_t{n_edges} + 1) * sizeof(uint32_t);
  if (bytes < index) return 0;
  const size_t cap = (bytes - index) / sizeof(Crossing);
  return cap > 0xffffffffu ? 0xffffffffu : static_cast<uint32_t>(cap);
}

namespace {

size_t align8(size_t v) { return (v + 7) & ~size_t{7}; }

// Scratch layout: cell_start[cells + 1], then cell_edges[cell_pairs]. After the cell loop the
// same bytes hold next[n_edges] for grouping, so the scratch is the larger of the two.
size_t scratch_for(uint32_t cells, uint32_t cell_pairs, uint32_t n_edges) {
  const size_t grid_part = align8((size_t{cells} + 1) * 4) + size_t{cell_pairs} * 4;
  const size_t group_part = size_t{n_edges} * 4;
  return grid_part > group_part ? grid_part : group_part;
}

bool boxes_overlap(const Edge3& p, const Edge3& q, int32_t reach) {
  return min_i32(p.a.x, p.b.x) <= max_i32(q.a.x, q.b.x) + reach &&
         min_i32(q.a.x, q.b.x) <= max_i32(p.a.x, p.b.x) + reach &&
         min_i32(p.a.y, p.b.y) <= max_i32(q.a.y, q.b.y) + reach &&
         min_i32(q.a.y, q.b.y) <= max_i32(p.a.y, p.b.y) + reach;
}

struct Recorder {
  Crossing* out;
  uint32_t capacity;
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

// C6.2-C6.5 for one pair inside cell c; ep < eq.
void test_pair(const Grid& g, uint32_t c, const Edge3* edges, uint32_t ep, uint32_t eq,
               int32_t reach, Recorder& rec, CutStats& st) {
  const Edge3& p = edges[ep];
  const Edge3& q = edges[eq];
  if (!boxes_overlap(p, q, reach)) return;
  const CrossingTest x = test_crossing(p, q);
  if (x.crosses) {
    // C6.3: report the crossing only in the cell that holds it. The floor of the exact
    // crossing point decides the cell exactly, because cell borders lie on integers.
    const int32_t fx = floor_along(p.a.x, p.b.x - p.a.x, x.tn, x.den);
    const int32_t fy = floor_along(p.a.y, p.b.y - p.a.y, x.tn, x.den);
    if (g.cell_of(fx, fy) != c) {
      ++st.rejected;
      return;
    }
    const int depth = compare_depth_at_crossing(p, q, x);  // C6.4
    if (depth == 0) {
      ++st.equal_depth;
      return;
    }
    ++st.crossings;
    if (depth < 0)
      rec.add(ep, eq, frac_q32_small(x.tn, x.den));
    else
      rec.add(eq, ep, frac_q32_small(x.un, x.den));
    return;
  }
  if (reach <= 0) return;
  const NearMiss m = test_near_miss(p, q, reach);
  if (!m.found || g.cell_of(m.ex, m.ey) != c) return;
  ++st.near_misses;
  if (m.p_behind)
    rec.add(ep, eq | Crossing::kNearBit, m.t_behind);
  else
    rec.add(eq, ep | Crossing::kNearBit, m.t_behind);
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
  uint64_t pairs = 0;
  for (uint32_t i = 0; i < n; ++i)
    for_each_cell(p.grid, edges[i], params.cover, params.reach, [&](uint32_t) { ++pairs; });
  if (pairs > 0xffffffffu) return Status::kCellPairOverflow;
  p.cell_pairs = static_cast<uint32_t>(pairs);
  p.scratch_bytes = scratch_for(p.grid.cells(), p.cell_pairs, n);
  *plan = p;
  return Status::kOk;
}

Status run_cut(const CutPlan& plan, const Edge3* edges, void* scratch, size_t scratch_bytes,
               void* cutset_storage, size_t cutset_storage_bytes, CutSet* out, CutStats* stats) {
  CutStats st;
  const uint32_t n = plan.n_edges;
  const Grid& g = plan.grid;
  const uint32_t cells = g.cells();
  if (scratch_bytes < plan.scratch_bytes) return Status::kWorkspaceTooSmall;
  if (cutset_storage_bytes < cutset_bytes(n, 0)) return Status::kCutsetStorageTooSmall;

  // C3-C5 as a two-pass counting sort: count edges per cell, turn counts into end offsets,
  // then drop each edge into its cell from the back. Edges are walked in descending order so
  // every cell's list comes out ascending. No comparison sort, no linked lists.
  uint32_t* cell_start = static_cast<uint32_t*>(scratch);
  uint32_t* cell_edges = cell_start + ((size_t{cells} + 1 + 1) & ~size_t{1});
  for (uint32_t c = 0; c <= cells; ++c) cell_start[c] = 0;
  for (uint32_t i = 0; i < n; ++i)
    for_each_cell(g, edges[i], plan.params.cover, plan.params.reach,
                  [&](uint32_t c) { ++cell_start[c + 1]; });
  for (uint32_t c = 0; c < cells; ++c) cell_start[c + 1] += cell_start[c];
  for (uint32_t i = n; i-- > 0;)
    for_each_cell(g, edges[i], plan.params.cover, plan.params.reach,
                  [&](uint32_t c) { cell_edges[--cell_start[c + 1]] = i; });
  // Each cell_start[c + 1] now holds the start of cell c; shift back into place.
  for (uint32_t c = 0; c < cells; ++c) cell_start[c] = cell_start[c + 1];
  cell_start[cells] = plan.cell_pairs;
  st.cell_pairs = plan.cell_pairs;

  uint32_t* first = static_cast<uint32_t*>(cutset_storage);
  Crossing* records = reinterpret_cast<Crossing*>(first + n + 1);
  Recorder rec{records, cutset_capacity(n, cutset_storage_bytes)};

  // C6: every pair inside every cell.
  for (uint32_t c = 0; c < cells; ++c) {
    const uint32_t begin = cell_start[c], end = cell_start[c + 1];
    for (uint32_t i = begin; i < end; ++i)
      for (uint32_t j = i + 1; j < end; ++j) {
        ++st.pairs_tested;
        test_pair(g, c, edges, cell_edges[i], cell_edges[j], plan.params.reach, rec, st);
      }
    if (plan.params.progress && (c & 0x3ffu) == 0)
      plan.params.progress(plan.params.progress_context, c, cells);
  }
  if (plan.params.progress) plan.params.progress(plan.params.progress_context, cells, cells);

  if (stats) *stats = st;
  if (rec.overflow) {
    *out = CutSet{};
    return Status::kCrossingCapacity;
  }

  // C7-C9: group by behind edge with a counting sort, in place (American-flag permutation),
  // so the records never need a second buffer. `next` reuses the scratch: the cell lists
  // are no longer needed.
  uint32_t* next = static_cast<uint32_t*>(scratch);
  for (uint32_t e = 0; e <= n; ++e) first[e] = 0;
  for (uint32_t i = 0; i < rec.stored; ++i) ++first[records[i].behind + 1];
  for (uint32_t e = 0; e < n; ++e) first[e + 1] += first[e];
  for (uint32_t e = 0; e < n; ++e) next[e] = first[e];
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

}  // namespace haloplot
