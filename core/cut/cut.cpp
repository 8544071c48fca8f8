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

// A host (a 64-bit target) spends memory and code for speed where a controller (a 32-bit
// one) keeps its RAM and flash as they were: there the compact cell entries carry the depths
// too, the cell walk is logged so each edge is walked once, the fill splits into parts, and
// the pair loop decides every pair without a branch (test_cells).
constexpr bool kHost = UINTPTR_MAX > 0xffffffffu;

template <bool kFirst, typename A, typename B>
struct Pick {
  using type = A;
};
template <typename A, typename B>
struct Pick<false, A, B> {
  using type = B;
};

// What a cell list holds per (cell, edge) pair: the edge's index, or a copy of the edge's
// projection beside it (CutParams::compact_cells), so the pair loop never leaves the cell
// list. Each gives the pair loop an edge-like segment, and the edge that holds its depths.
struct IndexEntry {
  uint32_t edge;
  static IndexEntry make(const Edge3&, uint32_t i) { return IndexEntry{i}; }
  const Edge3& segment(const Edge3* edges) const { return edges[edge]; }
  const Edge3& depths(const Edge3* edges) const { return edges[edge]; }
};
struct Point2 {
  int32_t x, y;
};
struct ProjectionEntry {  // 20 bytes: a controller's compact entry
  Point2 a, b;
  uint32_t edge;
  static ProjectionEntry make(const Edge3& e, uint32_t i) {
    return ProjectionEntry{{e.a.x, e.a.y}, {e.b.x, e.b.y}, i};
  }
  const ProjectionEntry& segment(const Edge3*) const { return *this; }
  const Edge3& depths(const Edge3* edges) const { return edges[edge]; }
};
struct EdgeEntry {  // 28 bytes: a host's, the depths beside the projection
  Edge3 copy;
  uint32_t edge;
  static EdgeEntry make(const Edge3& e, uint32_t i) { return EdgeEntry{e, i}; }
  const Edge3& segment(const Edge3*) const { return copy; }
  const Edge3& depths(const Edge3*) const { return copy; }
};
using CompactEntry = Pick<kHost, EdgeEntry, ProjectionEntry>::type;

bool is_marked(const uint32_t* marked, uint32_t e) { return (marked[e >> 5] >> (e & 31)) & 1u; }

size_t entry_bytes(const CutParams& p) {
  return p.compact_cells ? sizeof(CompactEntry) : sizeof(IndexEntry);
}

// The most parts a stage splits into, whatever the caller's count: enough for the cores a
// host has, few enough that the parts' bookkeeping stays small on a stack.
constexpr uint32_t kMaxParts = 16;

// Fewer parts where each would get less than Parts::min_work (pair tests in the cell loop, 16
// a record in the sorting); `per_thread` parts for each of the caller's threads.
// More parts than threads are a multiple of the threads where they can be, so that parts of
// equal work end together.
uint32_t part_count(const CutParams& p, uint64_t work, uint32_t per_thread = 1) {
  if (p.parts == nullptr) return 1;
  const uint32_t threads = p.parts->split();
  uint32_t n = threads > kMaxParts / per_thread ? kMaxParts : threads * per_thread;
  const uint64_t worth = p.parts->min_work == 0 ? n : work / p.parts->min_work;
  if (worth < n) n = worth < 1 ? 1 : uint32_t(worth);
  if (per_thread > 1 && n > threads) n -= n % threads;
  return n;
}

// The parts the cell lists are filled in (each walks its share of the edges): a walk costs
// about as much as a few pair tests per cell it visits.
uint32_t fill_part_count(const CutParams& p, uint32_t n_edges) {
  return kHost ? part_count(p, uint64_t{n_edges} * 8) : 1;
}

// The cell loop's work: the pairs each cell tests, and the cell itself.
uint64_t cell_work(const uint32_t* cell_start, uint32_t c) {
  const uint64_t k = cell_start[c + 1] - cell_start[c];
  return k * (k - 1) / 2 + k + 1;
}

// The cell loop's running work at every stride-th cell, noted (on a host) as the work is
// summed, so that the split finds each part's first cell by scanning one stride from the mark
// below it rather than every cell again.
constexpr uint32_t kWorkMarks = kHost ? 64 : 1;
struct WorkMarks {
  uint32_t stride = 0, count = 0;    // count 0: none noted
  uint64_t at[kWorkMarks + 1] = {};  // at[m]: the work of cells [0, m * stride)
};

// The cell loop's work in all, its marks noted (a host's) as it sums.
uint64_t sum_cell_work(const uint32_t* cell_start, uint32_t cells, WorkMarks* marks) {
  uint64_t work = 0;
  if (!kHost) {
    for (uint32_t c = 0; c < cells; ++c) work += cell_work(cell_start, c);
    return work;
  }
  marks->stride = cells / kWorkMarks + 1;
  marks->count = 0;
  for (uint32_t c0 = 0; c0 < cells; c0 += marks->stride) {
    marks->at[marks->count++] = work;
    const uint32_t c1 = cells - c0 > marks->stride ? c0 + marks->stride : cells;
    for (uint32_t c = c0; c < c1; ++c) work += cell_work(cell_start, c);
  }
  return work;
}

// One cell a walk visited, and for which edge.
struct Visit {
  uint32_t cell, edge;
};

// A log's spare slots: the branch-free block walk writes four visits' slots per edge, of
// which only the visited ones are kept.
constexpr uint32_t kLogSpare = 4;
// Each part's log slot count when the lists are filled in `parts` from logs of at most
// `cell_pairs` visits in all (a part whose visits outgrow its share walks again instead).
uint32_t log_slots(uint32_t cell_pairs, uint32_t parts) { return cell_pairs / parts + kLogSpare; }

// Scratch layout: cell_start[cells + 1], then the fill's own bytes, then the cell lists
// (cell_pairs entries). The fill's bytes: each part's cursor into every cell (parts * cells)
// when the lists are filled in parts; and with compact entries, each part's log of its walk's
// visits, so each edge is walked once rather than twice (both on a host only; not with index
// entries, where the logs would double the scratch). After the cell loop the same bytes hold
// next[n_edges] for grouping, so the scratch is the larger.
size_t cursor_bytes(uint32_t cells, uint32_t fill_parts) {
  return fill_parts > 1 ? carve_round(size_t{fill_parts} * cells * 4) : 0;
}
size_t fill_bytes(const CutParams& p, uint32_t cells, uint32_t cell_pairs, uint32_t fill_parts) {
  const size_t logs = kHost && p.compact_cells
                          ? size_t{fill_parts} * log_slots(cell_pairs, fill_parts) * sizeof(Visit)
                          : 0;
  return cursor_bytes(cells, fill_parts) + logs;
}
size_t scratch_for(const CutParams& p, uint32_t cells, uint32_t cell_pairs, uint32_t n_edges) {
  const uint32_t fill_parts = fill_part_count(p, n_edges);
  const size_t grid_part = carve_round((size_t{cells} + 1) * 4) +
                           fill_bytes(p, cells, cell_pairs, fill_parts) +
                           size_t{cell_pairs} * entry_bytes(p);
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
// (The cell's offsets from a are below 2^21 in magnitude, int32_t: 32 x 64 products.)
inline bool owns(const CellBox& cb, int32_t ax, int32_t dx, int32_t ay, int32_t dy, int64_t n,
                 int64_t den) {
  const int64_t px = mul_32x64(dx, n), py = mul_32x64(dy, n);
  const int32_t x0 = int32_t(cb.x0 - ax), x1 = int32_t(cb.x0 + cb.side - ax);
  const int32_t y0 = int32_t(cb.y0 - ay), y1 = int32_t(cb.y0 + cb.side - ay);
  return mul_32x64(x0, den) <= px && px < mul_32x64(x1, den) && mul_32x64(y0, den) <= py &&
         py < mul_32x64(y1, den);
}

// floor(num * 2^32 / den) for 0 <= num < den < 2^41: frac_q32_small's value. Where 64-bit
// division is one instruction (64-bit targets) and den < 2^32 (every crossing of edges
// shorter than 2^16 steps), a single division gives it: num * 2^32 < den * 2^32 <= 2^64.
inline uint32_t crossing_position(int64_t num, int64_t den) {
#if UINTPTR_MAX > 0xffffffffu
  if (den <= 0xffffffff) return uint32_t((uint64_t(num) << 32) / uint64_t(den));
#endif
  return frac_q32_small(num, den);
}

// C6.3-C6.5 for a pair whose projections cross at x (test_crossing()'s result).
template <typename Entry>
void record_crossing(const Grid&, const CellBox& cb, const Edge3* edges, const Entry& ei,
                     const Entry& ej, const CrossingTest& x, Recorder& rec, CutStats& st) {
  const auto& p = ei.segment(edges);
  const uint32_t ep = ei.edge, eq = ej.edge;
  // C6.3: report the crossing only in the cell that holds it, decided exactly.
  if (!owns(cb, p.a.x, p.b.x - p.a.x, p.a.y, p.b.y - p.a.y, x.tn, x.den)) {
    ++st.rejected;
    return;
  }
  const int depth = compare_depth_at_crossing(ei.depths(edges), ej.depths(edges), x);  // C6.4
  if (depth == 0) {
    ++st.equal_depth;
    return;
  }
  const uint32_t behind = depth < 0 ? ep : eq, front = depth < 0 ? eq : ep;
  const uint32_t t = crossing_position(depth < 0 ? x.tn : x.un, x.den);
  if (rec.rows && !position_in_rows(edges[behind], t, rec.row_lo, rec.row_hi)) {
    ++st.outside_rows;
    return;
  }
  ++st.crossings;
  rec.add(behind, front, t);
}

// C6.2-C6.5 for one pair inside a cell whose boxes overlap (or that crosses, by
// crossing_mask); edge ei < edge ej. Near misses go back to the full edges.
template <typename Entry>
void test_pair(const Grid& g, const CellBox& cb, const Edge3* edges, const Entry& ei,
               const Entry& ej, int32_t reach, Recorder& rec, CutStats& st) {
  const uint32_t ep = ei.edge, eq = ej.edge;
  const CrossingTest x = test_crossing(ei.segment(edges), ej.segment(edges));
  if (x.crosses) {
    record_crossing(g, cb, edges, ei, ej, x, rec, st);
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

// C3-C5 for one kind of cell entry: a two-pass counting sort. Count edges per cell, turn
// counts into end offsets, then drop each edge into its cell from the back. Edges are walked
// in descending order so every cell's list comes out ascending. No comparison sort, no linked
// lists. Fills list; cell_start[c] .. cell_start[c + 1] are cell c's.
template <typename Entry>
void fill_cells(const CutPlan& plan, const Edge3* edges, uint32_t* cell_start, Entry* list) {
  const uint32_t n = plan.n_edges;
  const Grid& g = plan.grid;
  const uint32_t cells = g.cells();
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
}

// A walk of edges [e0, e1) that adds each visit to count[cell] and, while they fit, logs the
// visits in order into log[0 .. slots) (null: no log). Returns how many it logged, or slots + 1
// when they did not all fit (the fill then walks again). The exact cover lies inside the
// boxes, so a log with the plan's cell_pairs + kLogSpare slots always fits.
uint32_t count_and_log(const CutPlan& plan, const Edge3* edges, uint32_t e0, uint32_t e1,
                       uint32_t* count, Visit* log, uint32_t slots) {
  uint32_t logged = 0;
  bool fits = log != nullptr;
  // Copies: the counts and the log are uint32_t stores, which the compiler must otherwise
  // assume may change the plan's grid, and so reload it and redo its sums for every edge.
  const Grid g = plan.grid;
  const CellCover cover = plan.params.cover;
  const int32_t reach = plan.params.reach;
  for (uint32_t i = e0; i < e1; ++i) {
    CellBlock b;
    if (cells_in_block(g, edges[i], cover, reach, &b)) {
      fits = fits && logged + kLogSpare <= slots;
      // Weighted, so no branch per cell: a cell of weight 0 is written to the log's next slot
      // (overwritten by the next visit, or a spare slot) and counted 0 times.
      for (int q = 0; q < 4; ++q) {
        count[b.cell[q]] += b.weight[q];
        if (fits) {
          log[logged] = Visit{b.cell[q], i};
          logged += b.weight[q];
        }
      }
      continue;
    }
    for_each_cell(g, edges[i], cover, reach, [&](uint32_t c) {
      ++count[c];
      fits = fits && logged < slots;
      if (fits) log[logged++] = Visit{c, i};
    });
  }
  return fits ? logged : slots + 1;
}

// With the log, the lists are filled in two passes: the visits drop their edges' indices
// (4 bytes) where the entries go, then the entries (a copy of each edge, 28 bytes) are written
// in list order, reading the edges those indices name. Dropping the entries themselves would
// scatter 28-byte writes over lists far larger than a cache; the indices' scatter spans a
// seventh of that, and the copy reads where the one before scattered writes (reads overlap;
// a write waits for its line).
//
// The indices of lists with `total` entries can lie in the last 4 * total bytes of the lists
// themselves: entry k ends at byte s (k + 1) (s = sizeof(Entry) >= 4), index k + 1 starts at
// (s - 4) total + 4 (k + 1), not before it while k + 1 <= total. So copying in ascending order
// overwrites only indices already read. Parts drop their entries directly (FillParts):
// copying at once, they would overwrite indices another part has yet to read, and moving the
// indices out of the way first cost more on two threads than the scatter it saves.
template <typename Entry>
uint32_t* index_after_lists(Entry* list, uint32_t total) {
  return reinterpret_cast<uint32_t*>(reinterpret_cast<uint8_t*>(list) +
                                     size_t{total} * (sizeof(Entry) - sizeof(uint32_t)));
}

// Drops the logged visits' edge indices at cursor[cell], moving each cursor on.
void place_from_log(const Visit* log, uint32_t logged, uint32_t* cursor, uint32_t* index) {
  for (uint32_t v = 0; v < logged; ++v) index[cursor[log[v].cell]++] = log[v].edge;
}

// list[k] = the entry of edge index[k], for k in [k0, k1), in ascending order.
template <typename Entry>
void copy_entries(const Edge3* edges, const uint32_t* index, uint32_t k0, uint32_t k1,
                  Entry* list) {
  // The reads jump over the edges: ask for each one's line a few entries ahead.
  constexpr uint32_t kAhead = 16;
  for (uint32_t k = k0; k < k1; ++k) {
    if (k + kAhead < k1) __builtin_prefetch(&edges[index[k + kAhead]]);
    const uint32_t e = index[k];
    list[k] = Entry::make(edges[e], e);
  }
}

// Drops the logged visits' entries into the lists at cursor[cell], moving each cursor on.
template <typename Entry>
void fill_from_log(const Edge3* edges, const Visit* log, uint32_t logged, uint32_t* cursor,
                   Entry* list) {
  // The writes scatter over every cell's list: ask for each one's line a few visits ahead.
  constexpr uint32_t kAhead = 16;
  for (uint32_t v = 0; v < logged; ++v) {
    if (v + kAhead < logged) __builtin_prefetch(&list[cursor[log[v + kAhead].cell]], 1);
    list[cursor[log[v].cell]++] = Entry::make(edges[log[v].edge], log[v].edge);
  }
}

// The same with one walk, for compact entries: it logs every visit (in edge order) as it
// counts, and the fill reads the log instead of walking again. cell_start[c + 1] holds cell
// c's start, then moves on with each entry dropped there to c's end, which is c + 1's start.
template <typename Entry>
void fill_cells_logged(const CutPlan& plan, const Edge3* edges, uint32_t* cell_start, Visit* log,
                       Entry* list) {
  const uint32_t cells = plan.grid.cells();
  for (uint32_t c = 0; c <= cells; ++c) cell_start[c] = 0;
  const uint32_t logged = count_and_log(plan, edges, 0, plan.n_edges, cell_start + 1, log,
                                        log_slots(plan.cell_pairs, 1));
  uint32_t at = 0;
  for (uint32_t c = 0; c < cells; ++c) {
    const uint32_t count = cell_start[c + 1];
    cell_start[c + 1] = at;
    at += count;
  }
  uint32_t* index = index_after_lists(list, at);
  place_from_log(log, logged, cell_start + 1, index);
  copy_entries(edges, index, 0, at, list);
}

// The same counting sort in parts of the edges, each with its own cursor into every cell (and
// its own log, with compact entries): part j counts its edges per cell, one pass over the
// counts gives each part its place in every cell's list (after the parts before it), and part
// j drops its edges there in ascending order, from its log if that holds all its visits, else
// walking again. Every cell's list comes out as the one-part fill makes it, entry for entry.
template <typename Entry>
struct FillParts {
  const CutPlan* plan;
  const Edge3* edges;
  uint32_t* cursor;  // part j's are cursor[j * cells .. (j + 1) * cells)
  Visit* logs;       // part j's are logs[j * slots .. (j + 1) * slots), or null
  uint32_t slots;
  Entry* list;
  uint32_t n;
  uint32_t logged[kMaxParts] = {};

  uint32_t first_edge(uint32_t j) const { return uint32_t(uint64_t{plan->n_edges} * j / n); }
  static void count(void* arg, uint32_t j) {
    FillParts* self = static_cast<FillParts*>(arg);
    const uint32_t cells = self->plan->grid.cells();
    uint32_t* mine = self->cursor + size_t{j} * cells;
    for (uint32_t c = 0; c < cells; ++c) mine[c] = 0;
    Visit* log = self->logs ? self->logs + size_t{j} * self->slots : nullptr;
    self->logged[j] = count_and_log(*self->plan, self->edges, self->first_edge(j),
                                    self->first_edge(j + 1), mine, log, self->slots);
  }
  static void fill(void* arg, uint32_t j) {
    const FillParts* self = static_cast<const FillParts*>(arg);
    const CutPlan& plan = *self->plan;
    uint32_t* mine = self->cursor + size_t{j} * plan.grid.cells();
    if (self->logs != nullptr && self->logged[j] <= self->slots) {
      fill_from_log(self->edges, self->logs + size_t{j} * self->slots, self->logged[j], mine,
                    self->list);
      return;
    }
    for (uint32_t i = self->first_edge(j); i < self->first_edge(j + 1); ++i) {
      const Entry e = Entry::make(self->edges[i], i);
      for_each_cell(plan.grid, self->edges[i], plan.params.cover, plan.params.reach,
                    [&](uint32_t c) { self->list[mine[c]++] = e; });
    }
  }
};

// The pass that gives each part its place in every cell's list (after the parts before it)
// and cell_start, from the parts' counts in their cursors; kParts: the parts' count where the
// compiler is to know it (the common two threads), 0 where it is n_parts. Returns the cell
// loop's work (cell_work summed) and notes its marks, so no pass of their own stands alone
// before the loop.
template <uint32_t kParts>
uint64_t place_parts(uint32_t* cursor, uint32_t cells, uint32_t n_parts, uint32_t* cell_start,
                     WorkMarks* marks) {
  const uint32_t parts = kParts != 0 ? kParts : n_parts;
  uint32_t at = 0;
  uint64_t work = 0;
  marks->stride = cells / kWorkMarks + 1;
  marks->count = 0;
  for (uint32_t c0 = 0; c0 < cells; c0 += marks->stride) {
    marks->at[marks->count++] = work;
    const uint32_t c1 = cells - c0 > marks->stride ? c0 + marks->stride : cells;
    for (uint32_t c = c0; c < c1; ++c) {
      const uint32_t start = at;
      cell_start[c] = start;
      for (uint32_t j = 0; j < parts; ++j) {
        uint32_t& k = cursor[size_t{j} * cells + c];
        const uint32_t count = k;
        k = at;
        at += count;
      }
      const uint64_t k = at - start;  // cell_work's count
      work += k * (k - 1) / 2 + k + 1;
    }
  }
  cell_start[cells] = at;
  return work;
}

// Out of line, as test_in_parts. Returns the cell loop's work, with its marks.
template <typename Entry>
__attribute__((noinline)) uint64_t fill_in_parts(const CutPlan& plan, const Edge3* edges,
                                                 uint32_t n_parts, uint32_t* cell_start,
                                                 uint8_t* fill_at, Entry* list, WorkMarks* marks) {
  const uint32_t cells = plan.grid.cells();
  uint32_t* cursor = reinterpret_cast<uint32_t*>(fill_at);
  Visit* logs = plan.params.compact_cells
                    ? reinterpret_cast<Visit*>(fill_at + cursor_bytes(cells, n_parts))
                    : nullptr;
  FillParts<Entry> fp{&plan, edges,  cursor, logs, log_slots(plan.cell_pairs, n_parts),
                      list,  n_parts};
  run_parts(*plan.params.parts, n_parts, &FillParts<Entry>::count, &fp);
  const uint64_t work = n_parts == 2 ? place_parts<2>(cursor, cells, n_parts, cell_start, marks)
                                     : place_parts<0>(cursor, cells, n_parts, cell_start, marks);
  run_parts(*plan.params.parts, n_parts, &FillParts<Entry>::fill, &fp);
  return work;
}

// Where a 64-bit multiply is one instruction (64-bit targets), deciding a pair outright is
// cheaper than the branches that would skip the work: the box test passes about half the
// pairs sharing a cell, unpredictably, and the side tests after it again. So there the pair
// loop (C6.2, without near misses) computes all four side values of every pair, branch-free,
// into a mask of the pairs that properly cross, and only those take the branches after it.
// Elsewhere (a Cortex-M has no such multiply) the boxes go first.
constexpr bool kDecideEveryPair = kHost;

// Bit (j - j0) set for every j in [j0, j1) (at most 64) whose segment properly crosses P:
// test_crossing()'s strict sign rule, on the side values it computes, relative to P's start.
// Q's ends relative to P's start are differences of in-range coordinates (|.| < 2^kDiffBits,
// int32_t), so every side value is a difference of two 32 x 32 -> 64 products.
static_assert(kCrossBits + 2 <= 62, "side values, and s4 = s3 + s1 - s2, must fit int64_t");
// The four side values of a pair: s1, s2 (Q's ends against P's line) and s3, s4 (P's ends
// against Q's line), all relative to P's start; s3 and s4 as test_crossing() has them.
struct Sides {
  int64_t s1, s2, s3, s4;
};
template <typename Segment>
inline Sides sides(const Segment& q, int32_t pax, int32_t pay, int32_t pdx, int32_t pdy) {
  const int32_t qax = q.a.x - pax, qay = q.a.y - pay, qbx = q.b.x - pax, qby = q.b.y - pay;
  const int64_t s1 = mul_32x32(pdx, qay) - mul_32x32(pdy, qax);
  const int64_t s2 = mul_32x32(pdx, qby) - mul_32x32(pdy, qbx);
  // cross(dq, P.a - Q.a) = (qby - qay) qax - (qbx - qax) qay: the qax qay terms cancel.
  const int64_t s3 = mul_32x32(qax, qby) - mul_32x32(qay, qbx);
  // P's end: s4 = s3 + cross(dq, dp), and cross(dp, dq) = s2 - s1 (all below 2^44).
  return Sides{s1, s2, s3, s3 + s1 - s2};
}
// Sign bit set exactly when a and b are nonzero with opposite signs (|a|, |b| < 2^62): then
// one of a & -b, -a & b has both operands negative; if either is 0, or both share a sign, no
// operand pair is negative together.
inline int64_t strictly_apart(int64_t a, int64_t b) { return (a & -b) | (-a & b); }

template <typename Entry>
uint64_t crossing_mask(const Entry* list, const Edge3* edges, int32_t pax, int32_t pay, int32_t pdx,
                       int32_t pdy, uint32_t j0, uint32_t j1) {
  uint64_t mask = 0;
  for (uint32_t j = j1; j-- > j0;) {  // downwards, so j0's bit is shifted last, into bit 0
    const Sides s = sides(list[j].segment(edges), pax, pay, pdx, pdy);
    const int64_t both = strictly_apart(s.s1, s.s2) & strictly_apart(s.s3, s.s4);
    mask = (mask << 1) | (uint64_t(both) >> 63);
  }
  return mask;
}

// test_crossing()'s result for a pair the mask found crossing, from the same side values
// (its tn, un and den, each made positive the same way), without testing the signs again.
inline CrossingTest crossing_from(const Sides& s) {
  CrossingTest r;
  r.crosses = true;
  r.den = s.s3 - s.s4;
  r.tn = r.den < 0 ? -s.s3 : s.s3;
  r.den = r.den < 0 ? -r.den : r.den;
  r.un = s.s1 - s.s2 < 0 ? -s.s1 : s.s1;
  return r;
}

// C6: every pair inside cells [c_begin, c_end). The part that reports progress maps its own
// cells onto `progress` of the whole grid's cells (its share of the wall time: all of them for
// one part); 0: it does not report.
template <typename Entry>
void test_cells(const CutPlan& plan, const Edge3* edges, const uint32_t* cell_start,
                const Entry* list, uint32_t c_begin, uint32_t c_end, uint32_t progress,
                Recorder& rec, CutStats& st) {
  const Grid& g = plan.grid;
  const uint32_t cells = g.cells();
  const int32_t r = plan.params.reach;
  const uint32_t* marked = plan.params.marked;
  uint32_t col = c_begin % g.nx, row = c_begin / g.nx;
  for (uint32_t c = c_begin; c < c_end; ++c) {
    const uint32_t begin = cell_start[c], end = cell_start[c + 1];
    const uint64_t k = end - begin;
    st.pairs_tested += mul_u32x32(uint32_t(k), uint32_t(k) - 1) / 2;  // 0 for k = 0 too
    // col, row and the cell side below 2^21: 32 x 32 -> 64 products (geometry/product.h)
    const CellBox cb{c, g.ox + mul_32x32(int32_t(col), g.cell),
                     g.oy + mul_32x32(int32_t(row), g.cell), g.cell};
    for (uint32_t i = begin; i + 1 < end; ++i) {
      const bool p_marked = marked == nullptr || is_marked(marked, list[i].edge);
      // An unmarked P (CutParams::marked) pairs only with the few marked Q: the loop below asks
      // each Q's mark first, a branch that seldom goes the other way, and decides no more.
      if (kDecideEveryPair && r == 0 && p_marked) {
        const auto& p = list[i].segment(edges);
        const int32_t pdx = p.b.x - p.a.x, pdy = p.b.y - p.a.y;
        for (uint32_t j0 = i + 1; j0 < end; j0 += 64) {
          const uint32_t j1 = end - j0 > 64 ? j0 + 64 : end;
          for (uint64_t m = crossing_mask(list, edges, p.a.x, p.a.y, pdx, pdy, j0, j1); m != 0;
               m &= m - 1) {
            const Entry& q = list[j0 + uint32_t(__builtin_ctzll(m))];
            const Sides sv = sides(q.segment(edges), p.a.x, p.a.y, pdx, pdy);
            record_crossing(g, cb, edges, list[i], q, crossing_from(sv), rec, st);
          }
        }
        continue;
      }
      // P's box once per row, then Q's box against it: a cheap reject before the exact
      // test, since most pairs sharing a cell do not even overlap.
      const auto& p = list[i].segment(edges);
      const int32_t px0 = min_i32(p.a.x, p.b.x) - r, px1 = max_i32(p.a.x, p.b.x) + r;
      const int32_t py0 = min_i32(p.a.y, p.b.y) - r, py1 = max_i32(p.a.y, p.b.y) + r;
      for (uint32_t j = i + 1; j < end; ++j) {
        if (!p_marked && !is_marked(marked, list[j].edge)) continue;
        const auto& q = list[j].segment(edges);
        const int32_t qx0 = min_i32(q.a.x, q.b.x), qx1 = max_i32(q.a.x, q.b.x);
        const int32_t qy0 = min_i32(q.a.y, q.b.y), qy1 = max_i32(q.a.y, q.b.y);
        // One branch on all four (not four that each mispredict): most pairs are rejected.
        if ((qx1 < px0) | (qx0 > px1) | (qy1 < py0) | (qy0 > py1)) continue;
        test_pair(g, cb, edges, list[i], list[j], r, rec, st);
      }
    }
    if (progress && plan.params.progress && (c & 0x3ffu) == 0)
      plan.params.progress(plan.params.progress_context,
                           uint32_t(uint64_t{c - c_begin} * progress / (c_end - c_begin)), cells);
    if (++col == g.nx) {
      col = 0;
      ++row;
    }
  }
}

// The cell loop's parts for each thread. More than one a thread lets the runner hand them out
// as threads come free (a thread that starts late leaves parts to the others), but it showed
// no gain in wall time on the paper's scene, and at 4 a thread the 1M-triangle torus's plot
// peaked 10 MB higher on 2 threads (179 against 169 MB), so one a thread it is.
constexpr uint32_t kCellPartsPerThread = 1;

void add_stats(const CutStats& a, CutStats* sum) {
  sum->pairs_tested += a.pairs_tested;
  sum->crossings += a.crossings;
  sum->near_misses += a.near_misses;
  sum->rejected += a.rejected;
  sum->equal_depth += a.equal_depth;
  sum->outside_rows += a.outside_rows;
}

// The grouping in parts (group_in_parts) splits the behind edges into buckets of 2^shift
// edges, at most kMaxParts of them: a bucket's records are grouped and sorted by one part.
uint32_t bucket_shift(uint32_t n_edges) {
  uint32_t shift = 0;
  while (n_edges > 0 && ((n_edges - 1) >> shift) + 1 > kMaxParts) ++shift;
  return shift;
}

// The cell loop's records as its parts left them, each part's in its slice of the records
// (part order), with each part's count of them per bucket: grouped from there in parts
// (group_in_parts) without first being joined.
struct RecordPieces {
  uint32_t n = 0;  // 0: the records lie joined in [0, stored)
  uint32_t shift = 0;
  const Crossing* at[kMaxParts] = {};
  uint32_t count[kMaxParts] = {};
  uint32_t in_bucket[kMaxParts][kMaxParts] = {};  // [part][bucket]
};

// C6 split into parts of the cells, each cut at cells of about equal pair work and recording
// into its own equal slice of the records. The records are then joined in part order (on a
// host they stay in their slices when all fit, and are grouped from there: RecordPieces); a
// part that outgrew its slice runs again here into what the others left, so a run stores
// every record exactly when one part would have (the total fits), and the CUTSET, grouped and
// sorted by (behind, t, front), is the same whatever the split.
template <typename Entry>
struct CellParts {
  const CutPlan* plan;
  const Edge3* edges;
  const uint32_t* cell_start;
  const Entry* list;
  uint32_t n = 1;
  RecordPieces* pieces = nullptr;  // counted into per bucket (a host's), or null
  uint32_t begin[kMaxParts + 1] = {};
  Recorder rec[kMaxParts] = {};
  CutStats st[kMaxParts] = {};

  // The first part reports progress: while it runs, the threads run its share of the parts
  // (all of them where there are as many parts as threads, as on a controller).
  void test(uint32_t j, Recorder& r, CutStats& s) const {
    const uint32_t threads = plan->params.parts->split();
    const uint32_t share = kCellPartsPerThread == 1 || threads >= n
                               ? plan->grid.cells()
                               : uint32_t(uint64_t{plan->grid.cells()} * threads / n);
    test_cells(*plan, edges, cell_start, list, begin[j], begin[j + 1], j == 0 ? share : 0, r, s);
  }
  // Each part counts its records per bucket as it ends, while they are in its cache. A part
  // records and counts into its own copies, stored once it ends: the parts' recorders, stats
  // and counts lie side by side, and parts running at once on two cores would otherwise pass
  // their shared cache lines to and fro at every record.
  static void run_one(void* arg, uint32_t j) {
    CellParts* self = static_cast<CellParts*>(arg);
    if (!kHost) {  // a controller's, with no cores to share lines between: in place
      self->test(j, self->rec[j], self->st[j]);
      return;
    }
    Recorder rec = self->rec[j];
    CutStats st;
    self->test(j, rec, st);
    self->rec[j] = rec;
    self->st[j] = st;
    if (self->pieces == nullptr || rec.overflow) return;
    uint32_t in_bucket[kMaxParts] = {};
    const uint32_t shift = self->pieces->shift;
    for (uint32_t i = 0; i < rec.stored; ++i) ++in_bucket[rec.out[i].behind >> shift];
    for (uint32_t b = 0; b < kMaxParts; ++b) self->pieces->in_bucket[j][b] = in_bucket[b];
  }
  // Cuts [0, cells) where the running sum of each cell's pair work reaches j / n of `total`:
  // from the marks where there are some, else in one pass over the cells.
  void split(uint32_t cells, uint64_t total, const WorkMarks* marks) {
    if (kHost && marks != nullptr && marks->count > 0) {
      for (uint32_t j = 1; j < n; ++j) {
        const uint64_t at = total / n * j;
        uint32_t m = 0;
        while (m + 1 < marks->count && marks->at[m + 1] < at) ++m;
        uint32_t c = m * marks->stride;
        for (uint64_t acc = marks->at[m]; c < cells && acc < at; ++c)
          acc += cell_work(cell_start, c);
        begin[j] = c;
      }
      begin[n] = cells;
      return;
    }
    uint32_t j = 1;
    uint64_t acc = 0;
    for (uint32_t c = 0; c < cells && j < n; ++c) {
      while (j < n && acc >= total / n * j) begin[j++] = c;
      acc += cell_work(cell_start, c);
    }
    while (j <= n) begin[j++] = cells;
  }
};

// Out of line: its bookkeeping takes stack only where a runner splits the loop (never on the
// controller). With `pieces` (a host's), records that all fit their slices stay there.
template <typename Entry>
__attribute__((noinline)) void test_in_parts(const CutPlan& plan, const Edge3* edges,
                                             const uint32_t* cell_start, const Entry* list,
                                             uint32_t n_parts, uint64_t work,
                                             const WorkMarks* marks, Recorder& rec, CutStats& st,
                                             RecordPieces* pieces) {
  CellParts<Entry> cp{&plan, edges, cell_start, list, n_parts, pieces};
  if (kHost && pieces != nullptr) pieces->shift = bucket_shift(plan.n_edges);
  cp.split(plan.grid.cells(), work, marks);
  for (uint32_t j = 0; j < n_parts; ++j) {
    const uint32_t lo = uint32_t(uint64_t{rec.capacity} * j / n_parts);
    const uint32_t hi = uint32_t(uint64_t{rec.capacity} * (j + 1) / n_parts);
    cp.rec[j] = Recorder{rec.out + lo, hi - lo, rec.rows, rec.row_lo, rec.row_hi};
  }
  run_parts(*plan.params.parts, n_parts, &CellParts<Entry>::run_one, &cp);
  uint64_t need = 0;
  for (uint32_t j = 0; j < n_parts; ++j) {
    add_stats(cp.st[j], &st);
    need += cp.st[j].crossings + cp.st[j].near_misses;
  }
  if (need > rec.capacity) {
    rec.overflow = true;
    return;
  }
  bool all_fit = true;
  for (uint32_t j = 0; j < n_parts; ++j) all_fit = all_fit && !cp.rec[j].overflow;
  if (kHost && pieces != nullptr && all_fit) {
    pieces->n = n_parts;
    for (uint32_t j = 0; j < n_parts; ++j) {
      pieces->at[j] = cp.rec[j].out;
      pieces->count[j] = cp.rec[j].stored;
    }
    rec.stored = uint32_t(need);
    return;
  }
  // Slices lie in part order, so each part's records move down (or stay): copied forward.
  uint32_t at = 0;
  for (uint32_t j = 0; j < n_parts; ++j) {
    if (cp.rec[j].overflow) continue;
    for (uint32_t i = 0; i < cp.rec[j].stored; ++i) rec.out[at + i] = cp.rec[j].out[i];
    at += cp.rec[j].stored;
  }
  for (uint32_t j = 0; j < n_parts; ++j) {
    if (!cp.rec[j].overflow) continue;
    Recorder again{rec.out + at, rec.capacity - at, rec.rows, rec.row_lo, rec.row_hi};
    CutStats counted;  // the same counts as the first run's, already added
    cp.test(j, again, counted);
    at += again.stored;
  }
  rec.stored = at;
}

// C3-C6 for one kind of cell entry.
template <typename Entry>
void fill_and_test(const CutPlan& plan, const Edge3* edges, void* scratch, Recorder& rec,
                   CutStats& st, RecordPieces* pieces) {
  const uint32_t cells = plan.grid.cells();
  const uint32_t fill_parts = fill_part_count(plan.params, plan.n_edges);
  uint32_t* cell_start = static_cast<uint32_t*>(scratch);
  uint8_t* fill_at = static_cast<uint8_t*>(scratch) + carve_round((size_t{cells} + 1) * 4);
  Entry* list = reinterpret_cast<Entry*>(
      fill_at + fill_bytes(plan.params, cells, plan.cell_pairs, fill_parts));
  uint64_t work = 0;
  WorkMarks marks;
  const bool counted = kHost && fill_parts > 1;
  if (counted)
    work = fill_in_parts(plan, edges, fill_parts, cell_start, fill_at, list, &marks);
  else if (kHost && plan.params.compact_cells)
    fill_cells_logged(plan, edges, cell_start, reinterpret_cast<Visit*>(fill_at), list);
  else
    fill_cells(plan, edges, cell_start, list);
  st.cell_pairs = cell_start[cells];  // the exact count (the plan's is an upper bound)
  if (plan.params.phase) plan.params.phase(plan.params.phase_context, CutPhase::kCellsFilled);
  if (!counted && plan.params.parts != nullptr && plan.params.parts->split() > 1)
    work = sum_cell_work(cell_start, cells, &marks);
  const uint32_t n_parts = part_count(plan.params, work, kCellPartsPerThread);
  if (n_parts == 1)
    test_cells(plan, edges, cell_start, list, 0, cells, cells, rec, st);
  else
    test_in_parts(plan, edges, cell_start, list, n_parts, work, kHost ? &marks : nullptr, rec, st,
                  pieces);
}

// C9's order inside each group of edges [e0, e1); returns the largest group. Ties (several
// edges through one point) by front index, so the output never depends on cell order.
uint32_t sort_range(Crossing* records, const uint32_t* first, uint32_t e0, uint32_t e1) {
  uint32_t most = 0;
  for (uint32_t e = e0; e < e1; ++e) {
    const uint32_t k = first[e + 1] - first[e];
    if (k > most) most = k;
    sort_in_place(records + first[e], k, [](const Crossing& a, const Crossing& b) {
      return a.t != b.t ? a.t < b.t : a.front < b.front;
    });
  }
  return most;
}

// The same in parts of the edges holding about equal shares of the records.
struct SortParts {
  Crossing* records;
  const uint32_t* first;
  uint32_t begin[kMaxParts + 1] = {};
  uint32_t largest[kMaxParts] = {};

  static void run_one(void* arg, uint32_t j) {
    SortParts* self = static_cast<SortParts*>(arg);
    self->largest[j] = sort_range(self->records, self->first, self->begin[j], self->begin[j + 1]);
  }
};

// Out of line, as test_in_parts.
__attribute__((noinline)) uint32_t sort_in_parts(const Parts& parts, uint32_t n_parts,
                                                 Crossing* records, const uint32_t* first,
                                                 uint32_t n) {
  SortParts sp{records, first};
  const uint64_t total = first[n];
  sp.begin[0] = 0;
  for (uint32_t j = 1; j < n_parts; ++j) {  // the first edge whose records start at j / n
    const uint64_t target = total * j / n_parts;
    uint32_t lo = sp.begin[j - 1], hi = n;
    while (lo < hi) {
      const uint32_t mid = lo + (hi - lo) / 2;
      if (first[mid] < target)
        lo = mid + 1;
      else
        hi = mid;
    }
    sp.begin[j] = lo;
  }
  sp.begin[n_parts] = n;
  run_parts(parts, n_parts, &SortParts::run_one, &sp);
  uint32_t most = 0;
  for (uint32_t j = 0; j < n_parts; ++j)
    if (sp.largest[j] > most) most = sp.largest[j];
  return most;
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

// The records of RecordPieces joined in [0, stored), as test_in_parts joins them: each piece
// lies at or after the joined ones' end, so they move down (or stay), copied forward. Out of
// line: seldom run (the scratch has no room for group_in_parts).
__attribute__((noinline)) void join_pieces(RecordPieces* pieces, Crossing* records) {
  uint32_t at = 0;
  for (uint32_t j = 0; j < pieces->n; ++j) {
    for (uint32_t i = 0; i < pieces->count[j]; ++i) records[at + i] = pieces->at[j][i];
    at += pieces->count[j];
  }
  pieces->n = 0;
}

// C7-C9 in parts. First one part per piece of the cell loop's records moves them into the
// scratch by bucket (bucket by bucket, each in part order), then one part per bucket groups
// its records by behind edge with a counting sort into their place in the records (the
// buckets' records lie in bucket order, as the groups do) and sorts its groups. The order a
// group's records arrive in does not matter: C9's order is a total one on the records (two
// that compare equal are equal).
struct GroupParts {
  const RecordPieces* pieces;
  uint32_t n_edges, buckets;
  uint32_t* next;  // next[n_edges]: the counting sort's cursors, each bucket its edges'
  Crossing* copy;  // the records, bucket by bucket
  Crossing* records;
  uint32_t* first;
  uint32_t bucket_at[kMaxParts + 1] = {};  // where each bucket's records start
  uint32_t to[kMaxParts][kMaxParts] = {};  // [part][bucket]: the part's next slot there
  uint32_t largest[kMaxParts] = {};

  static void move(void* arg, uint32_t j) {
    GroupParts* self = static_cast<GroupParts*>(arg);
    uint32_t to[kMaxParts];  // a copy of the part's cursors (see CellParts::run_one)
    for (uint32_t b = 0; b < kMaxParts; ++b) to[b] = self->to[j][b];
    const uint32_t shift = self->pieces->shift;
    const Crossing* from = self->pieces->at[j];
    for (uint32_t i = 0, k = self->pieces->count[j]; i < k; ++i)
      self->copy[to[from[i].behind >> shift]++] = from[i];
  }
  static void group(void* arg, uint32_t b) {
    GroupParts* self = static_cast<GroupParts*>(arg);
    const uint32_t shift = self->pieces->shift;
    const uint32_t e0 = b << shift;
    const uint32_t e1 = b + 1 == self->buckets ? self->n_edges : (b + 1) << shift;
    uint32_t* next = self->next;
    for (uint32_t e = e0; e < e1; ++e) next[e] = 0;
    const Crossing* from = self->copy + self->bucket_at[b];
    const uint32_t k = self->bucket_at[b + 1] - self->bucket_at[b];
    for (uint32_t i = 0; i < k; ++i) ++next[from[i].behind];
    // first[e0] and first[e1] are the buckets' starts, set before the parts run.
    uint32_t at = self->bucket_at[b];
    for (uint32_t e = e0; e < e1; ++e) {
      if (e > e0) self->first[e] = at;
      const uint32_t count = next[e];
      next[e] = at;
      at += count;
    }
    for (uint32_t i = 0; i < k; ++i) self->records[next[from[i].behind]++] = from[i];
    self->largest[b] = sort_range(self->records, self->first, e0, e1);
  }
};

// Whether the scratch holds group_in_parts' cursors and copy.
bool groups_in_parts_fit(const RecordPieces& pieces, uint32_t n, uint32_t stored,
                         size_t scratch_bytes) {
  return pieces.n > 1 && scratch_bytes >= carve_round(size_t{n} * sizeof(uint32_t)) +
                                              size_t{stored} * sizeof(Crossing);
}

// Out of line, as test_in_parts. Fills first[0 .. n] and the groups; returns the largest.
__attribute__((noinline)) uint32_t group_in_parts(const Parts& parts, const RecordPieces& pieces,
                                                  Crossing* records, uint32_t* first, uint32_t n,
                                                  void* scratch) {
  uint8_t* base = static_cast<uint8_t*>(scratch);
  const uint32_t buckets = n == 0 ? 0 : ((n - 1) >> pieces.shift) + 1;
  GroupParts gp{&pieces,
                n,
                buckets,
                reinterpret_cast<uint32_t*>(base),
                reinterpret_cast<Crossing*>(base + carve_round(size_t{n} * sizeof(uint32_t))),
                records,
                first};
  uint32_t at = 0;
  for (uint32_t b = 0; b < buckets; ++b) {
    gp.bucket_at[b] = at;
    first[b << pieces.shift] = at;
    for (uint32_t j = 0; j < pieces.n; ++j) {
      gp.to[j][b] = at;
      at += pieces.in_bucket[j][b];
    }
  }
  gp.bucket_at[buckets] = at;
  first[n] = at;
  run_parts(parts, pieces.n, &GroupParts::move, &gp);
  run_parts(parts, buckets, &GroupParts::group, &gp);
  uint32_t most = 0;
  for (uint32_t b = 0; b < buckets; ++b)
    if (gp.largest[b] > most) most = gp.largest[b];
  return most;
}

}  // namespace

namespace {

// The plan's bound on the (cell, edge) pairs of edges [e0, e1), from each edge's (dilated)
// bounding box: pure arithmetic, no walk.
uint64_t pair_bound(const Grid& g, const Edge3* edges, uint32_t e0, uint32_t e1, int32_t r) {
  const int32_t xmax = g.ox + static_cast<int32_t>(g.nx) * g.cell - 1;
  const int32_t ymax = g.oy + static_cast<int32_t>(g.ny) * g.cell - 1;
  uint64_t pairs = 0;
  for (uint32_t i = e0; i < e1; ++i) {
    const Edge3& e = edges[i];
    const uint32_t c0 = g.col(max_i32(min_i32(e.a.x, e.b.x) - r, g.ox));
    const uint32_t c1 = g.col(min_i32(max_i32(e.a.x, e.b.x) + r, xmax));
    const uint32_t r0 = g.row(max_i32(min_i32(e.a.y, e.b.y) - r, g.oy));
    const uint32_t r1 = g.row(min_i32(max_i32(e.a.y, e.b.y) + r, ymax));
    pairs += mul_u32x32(c1 - c0 + 1, r1 - r0 + 1);
  }
  return pairs;
}

// The plan's passes over the edges in parts of the edges (a host's, on a big scene, where they
// would otherwise run alone before the fill): the range check with the extent and the sampled
// lengths, then, on the grid chosen from those, the bound. Extremes and integer sums: the same
// plan as one part's, whatever the split.
struct PlanParts {
  const Edge3* edges = nullptr;
  uint32_t n = 0, parts = 1;
  const CutPlan* plan = nullptr;  // its grid, once chosen, for the bound
  bool ranged[kMaxParts] = {};
  Extent extent[kMaxParts];
  uint64_t length_sum[kMaxParts] = {}, lengths[kMaxParts] = {}, pairs[kMaxParts] = {};

  uint32_t first_edge(uint32_t j) const { return uint32_t(uint64_t{n} * j / parts); }
  static void scan(void* arg, uint32_t j) {
    PlanParts* self = static_cast<PlanParts*>(arg);
    const uint32_t e0 = self->first_edge(j), e1 = self->first_edge(j + 1);
    bool all = true;
    Extent x;
    for (uint32_t i = e0; i < e1; ++i) {
      all = all && in_range(self->edges[i]);
      x.add(self->edges[i]);
    }
    self->ranged[j] = all;
    self->extent[j] = x;
    // average_length's sample: every stride-th edge from edge 0.
    // Summed here and stored once: the parts' sums share cache lines, which parts running at
    // once on two cores would pass to and fro at every edge.
    const uint32_t stride = length_stride(self->n);
    uint64_t sum = 0, count = 0;
    for (uint32_t i = (e0 + stride - 1) / stride * stride; i < e1; i += stride) {
      sum += projected_length(self->edges[i]);
      ++count;
    }
    self->length_sum[j] = sum;
    self->lengths[j] = count;
  }
  static void bound(void* arg, uint32_t j) {
    PlanParts* self = static_cast<PlanParts*>(arg);
    self->pairs[j] = pair_bound(self->plan->grid, self->edges, self->first_edge(j),
                                self->first_edge(j + 1), self->plan->params.reach);
  }
};

// Out of line, as test_in_parts. Fills p's grid; returns the bound, or kCoordinateOutOfRange.
__attribute__((noinline)) Status plan_in_parts(const Edge3* edges, uint32_t n, uint32_t parts,
                                               CutPlan* p, uint64_t* pairs) {
  PlanParts pp;
  pp.edges = edges;
  pp.n = n;
  pp.parts = parts;
  pp.plan = p;
  run_parts(*p->params.parts, parts, &PlanParts::scan, &pp);
  Extent x;
  uint64_t sum = 0, count = 0;
  for (uint32_t j = 0; j < parts; ++j) {
    if (!pp.ranged[j]) return Status::kCoordinateOutOfRange;
    x.xmin = min_i32(x.xmin, pp.extent[j].xmin);
    x.xmax = max_i32(x.xmax, pp.extent[j].xmax);
    x.ymin = min_i32(x.ymin, pp.extent[j].ymin);
    x.ymax = max_i32(x.ymax, pp.extent[j].ymax);
    sum += pp.length_sum[j];
    count += pp.lengths[j];
  }
  p->grid = grid_for(x, n, static_cast<uint32_t>(sum / count), p->params.grid);
  run_parts(*p->params.parts, parts, &PlanParts::bound, &pp);
  *pairs = 0;
  for (uint32_t j = 0; j < parts; ++j) *pairs += pp.pairs[j];
  return Status::kOk;
}

}  // namespace

Status plan_cut(const Edge3* edges, uint32_t n, const CutParams& params, CutPlan* plan) {
  if (n > kMaxEdges) return Status::kTooManyEdges;
  if (params.reach < 0 || params.reach > kCoordMax || params.grid.lambda_q8 == 0)
    return Status::kBadParameter;
  CutPlan p;
  p.params = params;
  p.n_edges = n;
  // An upper bound on the (cell, edge) pairs from each edge's (dilated) bounding box. The
  // exact cover visits a subset of these cells, so the scratch sized from the bound always
  // suffices; run_cut() reports the exact count in its stats. A pass over an edge costs about
  // as much as a few pair tests.
  uint64_t pairs = 0;
  const uint32_t parts = kHost && n > 0 ? part_count(params, uint64_t{n} * 4) : 1;
  if (parts > 1) {
    const Status s = plan_in_parts(edges, n, parts, &p, &pairs);
    if (s != Status::kOk) return s;
  } else if (n > 0) {
    // The range check and the extent in one pass (choose_grid's, less a pass of its own).
    bool all = true;
    Extent x;
    for (uint32_t i = 0; i < n; ++i) {
      all = all && in_range(edges[i]);
      x.add(edges[i]);
    }
    if (!all) return Status::kCoordinateOutOfRange;
    p.grid = grid_for(x, n, params.grid.cell <= 0 ? average_length(edges, n) : 0, params.grid);
    pairs = pair_bound(p.grid, edges, 0, n, params.reach);
  }
  if (pairs > 0xffffffffu) return Status::kCellPairOverflow;
  p.cell_pairs = static_cast<uint32_t>(pairs);
  p.scratch_bytes = scratch_for(params, p.grid.cells(), p.cell_pairs, n);
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
  RecordPieces pieces;
  RecordPieces* in_place = kHost ? &pieces : nullptr;
  if (plan.params.compact_cells)
    fill_and_test<CompactEntry>(plan, edges, scratch, rec, st, in_place);
  else
    fill_and_test<IndexEntry>(plan, edges, scratch, rec, st, in_place);
  if (plan.params.progress) plan.params.progress(plan.params.progress_context, cells, cells);
  if (plan.params.phase) plan.params.phase(plan.params.phase_context, CutPhase::kPairsTested);

  if (stats) *stats = st;
  if (rec.overflow) {
    *out = CutSet{};
    return Status::kCrossingCapacity;
  }

  // C7-C9: group by behind edge with a counting sort, in the scratch: the cell lists are no
  // longer needed.
  if (kHost && groups_in_parts_fit(pieces, n, rec.stored, scratch_bytes)) {
    st.max_per_edge = group_in_parts(*plan.params.parts, pieces, records, first, n, scratch);
  } else {
    if (kHost && pieces.n > 0) join_pieces(&pieces, records);
    uint32_t* next = static_cast<uint32_t*>(scratch);
    for (uint32_t e = 0; e <= n; ++e) first[e] = 0;
    for (uint32_t i = 0; i < rec.stored; ++i) ++first[records[i].behind + 1];
    for (uint32_t e = 0; e < n; ++e) first[e + 1] += first[e];
    for (uint32_t e = 0; e < n; ++e) next[e] = first[e];
    group_records(records, rec.stored, n, first, next, scratch, scratch_bytes);
    // Sorting k records costs about k log k: as work, 16 a record.
    const uint32_t sort_parts = part_count(plan.params, uint64_t{rec.stored} * 16);
    st.max_per_edge = sort_parts == 1
                          ? sort_range(records, first, 0, n)
                          : sort_in_parts(*plan.params.parts, sort_parts, records, first, n);
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
