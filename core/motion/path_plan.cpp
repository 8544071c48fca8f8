#include "haloplot/motion/path_plan.h"

#include "haloplot/geometry/units.h"
#include "haloplot/geometry/wide.h"
#include "memory/carve.h"
#include "motion/stroke_clean.h"
#include "motion/stroke_simplify.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

constexpr uint32_t kNone = 0xffffffffu;

struct EndKey {
  int32_t x, y;
  uint32_t id;  // 2 * span + (0 for (x0, y0), 1 for (x1, y1))
};

struct Chain {
  uint32_t first_end;  // the end the chain starts at, when walked forward
  uint32_t last_end;   // the end it finishes at
  uint32_t spans;
};

void end_point(const Segment2* s, uint32_t id, int32_t* x, int32_t* y) {
  const Segment2& g = s[id >> 1];
  *x = (id & 1) ? g.x1 : g.x0;
  *y = (id & 1) ? g.y1 : g.y0;
}

// Walk a chain from `start` (an end id): the span leaves by its other end, which links to the
// next span's end. Calls visit(span, reversed) for each span; returns the final end id.
template <typename Visit>
uint32_t walk(const uint32_t* link, uint32_t start, Visit visit) {
  uint32_t enter = start;
  for (;;) {
    const uint32_t leave = enter ^ 1u;
    if (!visit(enter >> 1, (enter & 1u) != 0)) return leave;
    const uint32_t next = link[leave];
    if (next == kNone || next == start) return leave;
    enter = next;
  }
}

// The workspace, in carving order (memory/carve.h): the links, the chains, their done flags,
// then the endpoint sort. The clean-up's scratch is dead before the links are made, so a third
// carver takes it from the same place (it needs less than they do). The sort is dead once the
// chains exist, so the nearest-neighbour grid (cell starts and items) is carved from the same
// place by a second carver. C is a Carver for the run, or a ByteCounter for path_plan_bytes().
struct Workspace {
  void* clean_scratch;
  uint32_t* link;
  Chain* chains;
  uint32_t* order;  // the tour: 2 * chain + (1 when walked from its last end)
  uint8_t* done;
  EndKey* ends;
  uint32_t* cell_start;
  uint32_t* items;  // 2 * chain + end
};

uint32_t cells_cap(uint32_t n) { return n + 1; }

// 2-opt on the greedy tour: reversing a run of the tour (each chain in it then walked the
// other way) keeps every pen-up move inside the run and changes only the two at its ends, so a
// reversal is taken when those two get shorter. Greedy nearest neighbour leaves stragglers
// behind and crosses the region again to fetch them; a reversal removes such a crossing. Runs
// of up to kTwoOptWindow chains are tried, a few passes, so the cost stays linear in the tour.
// The moves' lengths are kept in `gap` (gap[k]: from position k to k + 1, or to the end),
// and a candidate is first bounded below by its moves' Chebyshev lengths, so most candidates
// cost no square root.
constexpr uint32_t kTwoOptWindow = 48;
constexpr int kTwoOptPasses = 4;

struct Tour {
  const Segment2* spans;
  const Chain* chains;
  uint32_t* order;  // 2 * chain + (1 when walked from its last end)
  uint32_t* gap;
  uint32_t n;
  int32_t start_x, start_y;
  PathEnd end;

  void point(uint32_t k, bool entry, int32_t* x, int32_t* y) const {
    const Chain& c = chains[order[k] >> 1];
    const bool from_last = (order[k] & 1) != 0;
    end_point(spans, entry != from_last ? c.first_end : c.last_end, x, y);
  }
  // Where the pen is before position k, and where it goes after position k (false: nowhere).
  void before(uint32_t k, int32_t* x, int32_t* y) const {
    if (k == 0) {
      *x = start_x, *y = start_y;
    } else {
      point(k - 1, false, x, y);
    }
  }
  bool after(uint32_t k, int32_t* x, int32_t* y) const {
    if (k + 1 < n) return point(k + 1, true, x, y), true;
    *x = end.x, *y = end.y;
    return end.known;
  }
  static uint32_t chebyshev(int32_t ax, int32_t ay, int32_t bx, int32_t by) {
    const int64_t dx = int64_t{bx} - ax, dy = int64_t{by} - ay;
    const int64_t ux = dx < 0 ? -dx : dx, uy = dy < 0 ? -dy : dy;
    return uint32_t(ux > uy ? ux : uy);
  }
  static uint32_t dist(int32_t ax, int32_t ay, int32_t bx, int32_t by) {
    return length_floor(int64_t{bx} - ax, int64_t{by} - ay);
  }
  uint32_t gap_after(uint32_t k) const {
    int32_t x, y, nx, ny;
    point(k, false, &x, &y);
    return after(k, &nx, &ny) ? dist(x, y, nx, ny) : 0;
  }
  // The run [i, j] reversed, each chain in it turned; the moves inside keep their lengths in
  // reverse order, the two at its ends are given.
  void reverse(uint32_t i, uint32_t j, uint32_t into, uint32_t out_of, uint32_t* first) {
    for (uint32_t a = i, b = j; a < b; ++a, --b) {
      const uint32_t t = order[a];
      order[a] = order[b] ^ 1u;
      order[b] = t ^ 1u;
    }
    if (((j - i) & 1u) == 0) order[i + (j - i) / 2] ^= 1u;  // the middle one turns too
    for (uint32_t a = i, b = j - 1; a < b; ++a, --b) {      // j > i: b never wraps
      const uint32_t t = gap[a];
      gap[a] = gap[b];
      gap[b] = t;
    }
    if (i == 0)
      *first = into;
    else
      gap[i - 1] = into;
    gap[j] = out_of;
  }
};

void improve_tour(Tour& t) {
  if (t.n < 2) return;
  for (uint32_t k = 0; k < t.n; ++k) t.gap[k] = t.gap_after(k);
  uint32_t first = 0;  // from the start to position 0
  {
    int32_t x, y;
    t.point(0, true, &x, &y);
    first = Tour::dist(t.start_x, t.start_y, x, y);
  }
  for (int pass = 0; pass < kTwoOptPasses; ++pass) {
    bool changed = false;
    for (uint32_t i = 0; i < t.n; ++i) {
      int32_t px, py, ix, iy;
      t.before(i, &px, &py);
      t.point(i, true, &ix, &iy);
      const uint64_t into_i = i == 0 ? first : t.gap[i - 1];
      const uint32_t last = t.n - 1 < i + kTwoOptWindow ? t.n - 1 : i + kTwoOptWindow;
      for (uint32_t j = i + 1; j <= last; ++j) {
        int32_t jx, jy, nx, ny;  // where the run [i, j] is left now, and what comes after it
        t.point(j, false, &jx, &jy);
        const bool has_next = t.after(j, &nx, &ny);
        const uint64_t old_cost = into_i + t.gap[j];
        uint64_t bound = Tour::chebyshev(px, py, jx, jy);
        if (has_next) bound += Tour::chebyshev(ix, iy, nx, ny);
        if (bound >= old_cost) continue;
        const uint32_t into = Tour::dist(px, py, jx, jy);
        const uint32_t out_of = has_next ? Tour::dist(ix, iy, nx, ny) : 0;
        if (uint64_t{into} + out_of >= old_cost) continue;
        t.reverse(i, j, into, out_of, &first);
        changed = true;
        break;
      }
    }
    if (!changed) break;
  }
}

template <typename C>
Workspace carve_workspace(C* front, C* grid, C* scratch, uint32_t n) {
  Workspace w;
  *scratch = *front;
  w.clean_scratch = scratch->template take<uint8_t>(stroke_clean_bytes(n));
  w.link = front->template take<uint32_t>(size_t{2} * n);
  w.chains = front->template take<Chain>(n);
  w.order = front->template take<uint32_t>(n);
  w.done = front->template take<uint8_t>(n);
  *grid = *front;
  w.ends = front->template take<EndKey>(size_t{2} * n);
  w.cell_start = grid->template take<uint32_t>(size_t{cells_cap(n)} + 1);
  w.items = grid->template take<uint32_t>(size_t{2} * n);
  return w;
}

// Pen-up travel with no planning (every span on its own, in input order): the stats' baseline.
uint64_t naive_pen_up(const Segment2* spans, uint32_t n, int32_t start_x, int32_t start_y) {
  uint64_t length = 0;
  int32_t px = start_x, py = start_y;
  for (uint32_t i = 0; i < n; ++i) {
    length += length_floor(int64_t{spans[i].x0} - px, int64_t{spans[i].y0} - py);
    px = spans[i].x1;
    py = spans[i].y1;
  }
  return length;
}

// 1. Join: sort all ends by position, pair the ends that meet, so the pen can go on without
//    lifting. Zero-length spans (dots) stay alone so a chain never links a span to itself.
void join_ends(const Segment2* spans, uint32_t n, EndKey* ends, uint32_t* link) {
  for (uint32_t id = 0; id < 2 * n; ++id) {
    end_point(spans, id, &ends[id].x, &ends[id].y);
    ends[id].id = id;
    link[id] = kNone;
  }
  sort_total(ends, size_t{2} * n, [](const EndKey& a, const EndKey& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.id < b.id;
  });
  auto is_dot = [&](uint32_t s) {
    return spans[s].x0 == spans[s].x1 && spans[s].y0 == spans[s].y1;
  };
  for (uint32_t i = 0; i < 2 * n;) {
    uint32_t j = i;
    while (j < 2 * n && ends[j].x == ends[i].x && ends[j].y == ends[i].y) ++j;
    uint32_t pending = kNone;
    for (uint32_t k = i; k < j; ++k) {
      const uint32_t id = ends[k].id;
      if (is_dot(id >> 1)) continue;
      if (pending == kNone) {
        pending = id;
      } else if ((pending >> 1) != (id >> 1)) {
        link[pending] = id;
        link[id] = pending;
        pending = kNone;
      }
    }
    i = j;
  }
}

// 2. Chains: open ones start at an unlinked end (so each is drawn end to end); what is left
//    over forms closed loops. Returns the number of chains. `skip_dots`: the clean-up ran, and
//    a dot (one found or one a merge left) is no stroke.
uint32_t make_chains(const Segment2* spans, uint32_t n, const uint32_t* link, Chain* chains,
                     uint8_t* done, bool skip_dots) {
  for (uint32_t s = 0; s < n; ++s)
    done[s] = skip_dots && spans[s].x0 == spans[s].x1 && spans[s].y0 == spans[s].y1;
  uint32_t n_chains = 0;
  auto make_chain = [&](uint32_t start) {
    Chain c{start, 0, 0};
    c.last_end = walk(link, start, [&](uint32_t s, bool) {
      if (done[s]) return false;
      done[s] = 1;
      ++c.spans;
      return true;
    });
    chains[n_chains++] = c;
  };
  for (uint32_t id = 0; id < 2 * n; ++id)
    if (link[id] == kNone && !done[id >> 1]) make_chain(id);
  for (uint32_t s = 0; s < n; ++s)
    if (!done[s]) make_chain(2 * s);  // a closed loop: start anywhere
  return n_chains;
}

// 3. The chain ends bucketed in a uniform grid (counting sort) over them and the start, so the
//    nearest end not yet taken is found by searching rings of cells outwards.
struct EndGrid {
  const Segment2* spans;
  const Chain* chains;
  uint32_t* cell_start;
  uint32_t* items;  // 2 * chain + end
  int32_t xmin = 0, ymin = 0;
  uint32_t side = 1, gx = 1, gy = 1;

  uint32_t cell_of(int32_t x, int32_t y) const {
    return uint32_t(uint64_t(y - ymin) / side) * gx + uint32_t(uint64_t(x - xmin) / side);
  }
  void chain_end(uint32_t item, int32_t* x, int32_t* y) const {
    const Chain& c = chains[item >> 1];
    end_point(spans, (item & 1) ? c.last_end : c.first_end, x, y);
  }

  // The grid's extent from the sorted ends (read before the cells, carved over them, are
  // written), then its items. Cell side: about one chain end per cell.
  void build(const EndKey* ends, uint32_t n, uint32_t n_chains, int32_t start_x, int32_t start_y) {
    int32_t xmax = start_x, ymax = start_y;
    xmin = start_x, ymin = start_y;
    for (uint32_t i = 0; i < 2 * n; ++i) {
      xmin = ends[i].x < xmin ? ends[i].x : xmin;
      xmax = ends[i].x > xmax ? ends[i].x : xmax;
      ymin = ends[i].y < ymin ? ends[i].y : ymin;
      ymax = ends[i].y > ymax ? ends[i].y : ymax;
    }
    // In 64 bits: a caller's start need not lie in the coordinate range the strokes do.
    const uint64_t w = uint64_t(int64_t{xmax} - xmin) + 1, h = uint64_t(int64_t{ymax} - ymin) + 1;
    side = isqrt_u64(w * h / (2ull * n_chains + 1)) + 1;
    while ((w / side + 1) * (h / side + 1) > cells_cap(n)) side += side / 8 + 1;
    gx = uint32_t(w / side + 1), gy = uint32_t(h / side + 1);
    const uint32_t cells = gx * gy;
    for (uint32_t c = 0; c <= cells; ++c) cell_start[c] = 0;
    for (uint32_t item = 0; item < 2 * n_chains; ++item) {
      int32_t x, y;
      chain_end(item, &x, &y);
      ++cell_start[cell_of(x, y) + 1];
    }
    for (uint32_t c = 0; c < cells; ++c) cell_start[c + 1] += cell_start[c];
    for (uint32_t item = 2 * n_chains; item-- > 0;) {
      int32_t x, y;
      chain_end(item, &x, &y);
      items[--cell_start[cell_of(x, y) + 1]] = item;
    }
    for (uint32_t c = 0; c < cells; ++c) cell_start[c] = cell_start[c + 1];
    cell_start[cells] = 2 * n_chains;
  }

  // The nearest end of a chain not done (ties: the lower item), ring by ring until no cell
  // further out can hold a nearer one.
  uint32_t nearest(int32_t px, int32_t py, const uint8_t* done) const {
    const int64_t pcx = (px - xmin) / int64_t(side), pcy = (py - ymin) / int64_t(side);
    uint64_t best = ~uint64_t{0};
    uint32_t best_item = kNone;
    for (int64_t r = 0;; ++r) {
      for (int64_t cy = pcy - r; cy <= pcy + r; ++cy) {
        if (cy < 0 || cy >= gy) continue;
        const bool edge_row = cy == pcy - r || cy == pcy + r;
        for (int64_t cx = pcx - r; cx <= pcx + r; cx += edge_row ? 1 : 2 * r) {
          if (cx >= 0 && cx < gx) {
            const uint32_t c = uint32_t(cy) * gx + uint32_t(cx);
            for (uint32_t k = cell_start[c]; k < cell_start[c + 1]; ++k) {
              const uint32_t item = items[k];
              if (done[item >> 1]) continue;
              int32_t x, y;
              chain_end(item, &x, &y);
              const int64_t dx = x - px, dy = y - py;
              const uint64_t d2 = uint64_t(dx * dx + dy * dy);
              if (d2 < best || (d2 == best && item < best_item)) {
                best = d2;
                best_item = item;
              }
            }
          }
          if (r == 0) break;
        }
      }
      const uint64_t reach = uint64_t(r) * side;  // anything beyond ring r is at least this far
      if (best_item != kNone && best <= reach * reach) break;
      if (r > int64_t(gx) + int64_t(gy)) break;
    }
    return best_item;
  }
};

// 4. The tour's chains as pen moves: a pen-up move to each chain's entry unless the pen is
//    already there, then its spans pen-down. Returns the number of points written.
uint32_t write_path(const Segment2* spans, const uint32_t* link, const Chain* chains,
                    const uint32_t* order, uint32_t n_chains, int32_t start_x, int32_t start_y,
                    PathPoint* out, PathStats& st) {
  uint32_t count = 0;
  int32_t px = start_x, py = start_y;
  for (uint32_t taken = 0; taken < n_chains; ++taken) {
    const uint32_t best_item = order[taken];
    const Chain& ch = chains[best_item >> 1];
    // Walk from the end we arrived at; a chain entered at its last end is walked backwards.
    const bool backwards = (best_item & 1) != 0;
    const uint32_t entry = backwards ? ch.last_end : ch.first_end;
    int32_t sx, sy;
    end_point(spans, entry, &sx, &sy);
    if (sx != px || sy != py || count == 0) {
      out[count++] = PathPoint{sx, sy, 0};
      st.pen_up_length += length_floor(int64_t{sx} - px, int64_t{sy} - py);
      if (taken > 0) ++st.pen_lifts;
    }
    // Backwards: walk the links from the last end; each span is then left by its other end.
    uint32_t remaining = ch.spans;
    walk(link, entry, [&](uint32_t s, bool reversed) {
      if (remaining == 0) return false;
      --remaining;
      const Segment2& g = spans[s];
      const int32_t ex = reversed ? g.x0 : g.x1, ey = reversed ? g.y0 : g.y1;
      st.pen_down_length += length_floor(int64_t{ex} - (reversed ? g.x1 : g.x0),
                                         int64_t{ey} - (reversed ? g.y1 : g.y0));
      out[count++] = PathPoint{ex, ey, 1};
      return true;
    });
    px = out[count - 1].x;
    py = out[count - 1].y;
  }
  return count;
}

// 2b. Chains shorter than min_stroke dropped (joining has made every stroke as long as its
//     neighbours allow, so what is short now touches nothing it could go on into).
uint32_t drop_crumbs(const Segment2* spans, const uint32_t* link, Chain* chains, uint32_t n_chains,
                     uint32_t min_stroke, PathStats& st) {
  if (min_stroke == 0) return n_chains;
  uint32_t kept = 0;
  for (uint32_t c = 0; c < n_chains; ++c) {
    uint64_t length = 0;
    uint32_t remaining = chains[c].spans;
    walk(link, chains[c].first_end, [&](uint32_t s, bool) {
      if (remaining == 0) return false;
      --remaining;
      length +=
          length_floor(int64_t{spans[s].x1} - spans[s].x0, int64_t{spans[s].y1} - spans[s].y0);
      return true;
    });
    if (length < min_stroke) {
      ++st.crumbs_dropped;
      st.crumb_length += length;
    } else {
      chains[kept++] = chains[c];
    }
  }
  return kept;
}

}  // namespace

void round_to_steps(Segment2* spans, uint32_t n, int substep_bits) {
  if (substep_bits == 0) return;
  for (uint32_t i = 0; i < n; ++i) {
    Segment2& g = spans[i];
    g = Segment2{units_to_steps(g.x0, substep_bits), units_to_steps(g.y0, substep_bits),
                 units_to_steps(g.x1, substep_bits), units_to_steps(g.y1, substep_bits)};
  }
}

uint32_t length_floor(int64_t dx, int64_t dy) {
  return isqrt_u64(static_cast<uint64_t>(dx * dx + dy * dy));
}

size_t path_plan_bytes(uint32_t n_spans) {
  ByteCounter front, grid, scratch;
  carve_workspace(&front, &grid, &scratch, n_spans);
  const size_t most = front.total > grid.total ? front.total : grid.total;
  return most > scratch.total ? most : scratch.total;
}

void add_path_stats(PathStats* a, const PathStats& b) {
  a->polylines += b.polylines;
  a->pen_up_length += b.pen_up_length;
  a->naive_pen_up_length += b.naive_pen_up_length;
  a->pen_down_length += b.pen_down_length;
  a->pen_lifts += b.pen_lifts;
  a->dots_dropped += b.dots_dropped;
  a->overlaps_merged += b.overlaps_merged;
  a->crumbs_dropped += b.crumbs_dropped;
  a->points_simplified += b.points_simplified;
  a->overlap_length += b.overlap_length;
  a->crumb_length += b.crumb_length;
}

Status plan_path(Segment2* spans, uint32_t n, PenAt start, void* workspace, size_t workspace_bytes,
                 PathPoint* out, uint32_t out_capacity, uint32_t* out_count, PathStats* stats,
                 PathEnd end, PathClean clean) {
  const int32_t start_x = start.x, start_y = start.y;
  if (buffer_misaligned(workspace)) return Status::kMisalignedBuffer;
  Carver front(workspace, workspace_bytes), grid = front, scratch = front;
  const Workspace ws = carve_workspace(&front, &grid, &scratch, n);
  if (front.short_ || grid.short_ || scratch.short_) return Status::kWorkspaceTooSmall;
  if (out_capacity < path_points_max(n)) return Status::kBadParameter;
  PathStats st;
  st.naive_pen_up_length = naive_pen_up(spans, n, start_x, start_y);
  if (clean.on) {  // 0. The clean-up, in place
    const Status s = clean_spans(spans, n, ws.clean_scratch, stroke_clean_bytes(n), &st);
    if (!ok(s)) return s;
  }
  join_ends(spans, n, ws.ends, ws.link);
  uint32_t n_chains = make_chains(spans, n, ws.link, ws.chains, ws.done, clean.on);
  n_chains = drop_crumbs(spans, ws.link, ws.chains, n_chains, clean.on ? clean.min_stroke : 0, st);
  st.polylines = n_chains;

  // 3. Greedy nearest neighbour over chain ends, then 2-opt on that tour.
  EndGrid eg{spans, ws.chains, ws.cell_start, ws.items};
  eg.build(ws.ends, n, n_chains, start_x, start_y);
  uint8_t* done = ws.done;
  for (uint32_t c = 0; c < n_chains; ++c) done[c] = 0;
  int32_t px = start_x, py = start_y;
  for (uint32_t taken = 0; taken < n_chains; ++taken) {
    const uint32_t best_item = eg.nearest(px, py, done);
    done[best_item >> 1] = 1;
    ws.order[taken] = best_item;
    // The pen leaves the chain by its other end.
    eg.chain_end(best_item ^ 1u, &px, &py);
  }
  Tour tour{spans, ws.chains, ws.order, ws.items, n_chains, start_x, start_y, end};
  improve_tour(tour);  // the grid's items are dead now: they hold the moves' lengths

  *out_count = write_path(spans, ws.link, ws.chains, ws.order, n_chains, start_x, start_y, out, st);
  if (clean.on && clean.simplify > 0)  // 4. Fewer points along the same lines
    *out_count = simplify_strokes(out, *out_count, clean.simplify, &st.points_simplified);
  if (stats) *stats = st;
  return Status::kOk;
}

Status plan_path_layers(Segment2* spans, uint32_t n, const LayerCounts& layers, int32_t start_x,
                        int32_t start_y, void* workspace, size_t workspace_bytes, PathPoint* out,
                        uint32_t out_capacity, uint32_t* out_count, LayerCounts* points_per_layer,
                        PathStats* stats, PathClean clean) {
  if (buffer_misaligned(workspace)) return Status::kMisalignedBuffer;  // even with no spans
  if (layers.n > kMaxLayers) return Status::kBadParameter;
  uint64_t total = 0;
  for (uint32_t k = 0; k < layers.n; ++k) total += layers.count[k];
  if (layers.n > 0 && total != n) return Status::kBadParameter;
  if (out_capacity < path_points_max(n)) return Status::kBadParameter;
  LayerCounts written;
  written.n = layers.n;
  if (layers.n <= 1) {
    const Status s = plan_path(spans, n, PenAt{start_x, start_y}, workspace, workspace_bytes, out,
                               out_capacity, out_count, stats, PathEnd{}, clean);
    written.count[0] = *out_count;
    if (ok(s) && points_per_layer != nullptr) *points_per_layer = written;
    return s;
  }
  // Each layer in the same workspace (a smaller plan carves less of it), its points after the
  // previous layer's.
  PathStats sum;
  // The input order as given, before each layer's clean-up changes its spans in place.
  sum.naive_pen_up_length = naive_pen_up(spans, n, start_x, start_y);
  uint32_t first = 0, count = 0;
  int32_t x = start_x, y = start_y;
  for (uint32_t k = 0; k < layers.n; ++k) {
    const uint32_t m = layers.count[k];
    if (m == 0) continue;
    uint32_t wrote = 0;
    PathStats st;
    const Status s = plan_path(spans + first, m, PenAt{x, y}, workspace, workspace_bytes,
                               out + count, path_points_max(m), &wrote, &st, PathEnd{}, clean);
    if (!ok(s)) return s;
    if (count > 0 && wrote > 0) ++sum.pen_lifts;  // the move to this layer's first stroke
    st.naive_pen_up_length = 0;                   // counted over all layers below
    add_path_stats(&sum, st);
    written.count[k] = wrote;
    first += m;
    count += wrote;
    if (wrote > 0) x = out[count - 1].x, y = out[count - 1].y;
  }
  *out_count = count;
  if (points_per_layer != nullptr) *points_per_layer = written;
  if (stats) *stats = sum;
  return Status::kOk;
}

}  // namespace haloplot
