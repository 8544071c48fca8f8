// The band conductor's pen path (conductor.h): a committed band's pieces become segments, the
// ones joining a piece carried up are deferred to the band above, and the rest are planned a
// column at a time. Per band and per piece, not per edge read: built for size in a firmware
// image (core/CMakeLists.txt), where the conductor's per-edge loops (conductor.cpp) are -O2.
#include "band/band_attempt.h"
#include "haloplot/band/band_rule.h"
#include "haloplot/band/conductor.h"
#include "memory/carve.h"
#include "sort/in_place_sort.h"

namespace haloplot {

// The band's pen path, column by column. A band is a strip as wide as the plot and often far
// less tall, where one greedy nearest-neighbour pass leaves stragglers behind and crosses the
// whole width again to fetch them. So the strip is cut into columns three times as wide as it
// is tall (the shape measured best on Figure 4; a solid's thin bands hardly care), taken left to
// right in even bands and right to left in odd ones (a serpentine over the plot), and the
// planner (motion/path_plan.h: greedy, then 2-opt) orders each column's pieces from where the
// pen is to where it goes next: the column's far side, or after the band's last column the band
// above. Planning a column at a time also bounds the path's memory by the largest column, not
// the band. The measurements behind these choices (column shapes, 2-opt, the known exit, the
// page turned a quarter, joins at borders): docs/reports/bands.md, "Pen-up travel in bands".
int64_t BandConductor::column_of(int64_t x_sum) const {
  const int64_t c = x_sum / 2 / column_side_;  // x >= 0: truncation is floor
  return leftward_ ? -c : c;
}

bool BandConductor::column_less(const Segment2& p, const Segment2& q) const {
  const int64_t cp = column_of(int64_t{p.x0} + p.x1), cq = column_of(int64_t{q.x0} + q.x1);
  return cp != cq ? cp < cq : segment_less(p, q);
}

// The band fitted up to its pieces. The pieces it drew, with the pieces the band below deferred
// to it, are laid out as segments for next() to plan column by column; the ones that join a
// piece carried past the top (through shared ends, a polyline continuing across the border)
// are deferred to the band above, so the polyline is drawn in one go there. Sizes are checked
// first (the path of the widest column over all of them), and the observer sees the pieces
// only once the band is sure to fit.
Status BandConductor::commit_band(Attempt& a) {
  const uint32_t np = a.n_pieces, nco = a.n_carry_out, ndi = n_defer_;
  const int64_t min_column = kMinColumn << spec_.substep_bits;
  column_side_ = 3 * (a.y1 - a.y0 > min_column ? a.y1 - a.y0 : min_column);
  leftward_ = (stats_.bands & 1) != 0;
  sort_in_place(a.pieces, np, [this](const StoredPiece& p, const StoredPiece& q) {
    const int64_t cp = column_of(p.x_sum), cq = column_of(q.x_sum);
    if (cp != cq) return cp < cq;
    return p.local != q.local ? p.local < q.local : p.t0 < q.t0;
  });
  Segment2* deferred_in = reinterpret_cast<Segment2*>(arena_ + carry_bytes(n_carry_));
  auto seg_sum = [](const Segment2& g) { return int64_t{g.x0} + g.x1; };
  sort_in_place(deferred_in, ndi, ColumnOrder{this});
  // The widest column over both sorted lists (a bound for the columns drawn here).
  uint32_t widest = 0;
  for (uint32_t i = 0, j = 0; i < np || j < ndi;) {
    const int64_t c =
        j == ndi || (i < np && column_of(a.pieces[i].x_sum) <= column_of(seg_sum(deferred_in[j])))
            ? column_of(a.pieces[i].x_sum)
            : column_of(seg_sum(deferred_in[j]));
    uint32_t k = 0;
    for (; i < np && column_of(a.pieces[i].x_sum) == c; ++i) ++k;
    for (; j < ndi && column_of(seg_sum(deferred_in[j])) == c; ++j) ++k;
    if (k > widest) widest = k;
  }
  uint32_t nu = np + ndi;
  uint8_t* pieces_end = reinterpret_cast<uint8_t*>(a.pieces + np);
  const size_t total = carry_bytes(nco) + carve_round(size_t{nu} * sizeof(Segment2)) +
                       carve_round(size_t{path_points_max(widest)} * sizeof(PathPoint)) +
                       carve_round(path_plan_bytes(widest));
  const size_t middle = size_t(pieces_end - arena_) + size_t{ndi} * sizeof(Segment2);
  if (total > arena_bytes_ || middle > arena_bytes_) {
    a.need = total > middle ? total : middle;
    return Status::kWorkspaceTooSmall;
  }
  note_used(total > middle ? total : middle);
  // Each piece becomes its segment in place, seen by the observer first; the deferred ones
  // from below follow them, so all nu segments stand in one array.
  Segment2* u = reinterpret_cast<Segment2*>(a.pieces);
  for (uint32_t i = 0; i < np; ++i) {
    const StoredPiece sp = a.pieces[i];
    const bool line = sp.local >= a.g.n;  // a line on the faces, a diagonal (solid_band.cpp)
    const Edge3& e = line ? a.lines_end[-1 - int64_t{sp.local - a.g.n}] : a.g.edges[sp.local];
    Segment2 g;
    frame_point(a.turned, e, sp.t0, &g.x0, &g.y0);
    frame_point(a.turned, e, int64_t{sp.t1_minus_1} + 1, &g.x1, &g.y1);
    if (observer_.piece != nullptr) {  // in the page's frame, a turned plot's turned back
      const Edge3 page_line = line && turned_ ? unturn_edge(e) : e;
      observer_.piece(observer_.ctx, BandPiece{{line ? kNoFace : a.g.id(sp.local), sp.t0,
                                                int64_t{sp.t1_minus_1} + 1},
                                               page_segment(g),
                                               line ? &page_line : nullptr});
    }
    u[i] = g;
  }
  for (uint32_t j = 0; j < ndi; ++j) u[np + j] = deferred_in[j];
  uint8_t* free = pieces_end + size_t{ndi} * sizeof(Segment2);
  if (solid_mode()) nu = solid_stage_->join(*this, a, u, np, nu, free);
  const uint32_t n_defer = defer_joined(a, u, np, nu, free);
  // Forward copies: each destination starts below its source (the carry and the segments sit
  // past the band's edges, which are at least as large).
  Carry* carry = reinterpret_cast<Carry*>(arena_);
  for (uint32_t i = 0; i < nco; ++i) carry[i] = a.carry_out[i];
  if (a.carry_runs_out != nullptr) {
    CarryRun* runs = carry_runs(arena_, nco);
    for (uint32_t i = 0; i < nco; ++i) runs[i] = a.carry_runs_out[i];
  }
  Segment2* dest = reinterpret_cast<Segment2*>(arena_ + carry_bytes(nco));
  for (uint32_t i = 0; i < nu; ++i) {
    const Segment2 g = u[i];
    dest[i] = g;
  }
  n_carry_ = nco;
  n_defer_ = n_defer;
  segs_ = dest + n_defer;
  n_segs_ = nu - n_defer;
  next_seg_ = 0;
  band_y0_ = a.y0;
  band_y1_ = a.y1;
  if (observer_.band != nullptr) observer_.band(observer_.ctx, int32_t(a.y0), int32_t(a.y1));
  ++stats_.bands;
  stats_.pieces += np;
  stats_.deferred += n_defer;
  if (np > stats_.most_pieces) stats_.most_pieces = np;
  if (nco > stats_.most_carry) stats_.most_carry = nco;
  if (a.g.n > stats_.most_edges) stats_.most_edges = a.g.n;
  stats_.band_edges += a.g.n;
  if (cuts()) stats_.records += a.cs.n_crossings;
  return Status::kOk;
}

namespace {

// Each carried piece's lower end, rounded, into pts; returns how many. The edge stage stored
// them (carry_points); a solid's band keeps 8 bytes less a carried piece and finds each on its
// edge here, as its sink rounded it: the carry and the band's edges are both in source order,
// so one pass finds them (a full turn round the edges, should one not be, and an end not
// found is left out: the piece then joins nothing, and only the pen's path differs).
uint32_t carried_points(const BandConductor::Attempt& a, RowPoint* pts) {
  const uint32_t nco = a.n_carry_out;
  if (a.carry_points != nullptr) {
    for (uint32_t i = 0; i < nco; ++i) pts[i] = a.carry_points[i];
    return nco;
  }
  uint32_t n = 0, k = 0;
  for (uint32_t i = 0; i < nco && a.g.n > 0; ++i) {
    uint32_t tried = 0;
    while (tried < a.g.n && a.g.id(k) != a.carry_out[i].edge) {
      k = k + 1 == a.g.n ? 0 : k + 1;
      ++tried;
    }
    if (tried == a.g.n) continue;
    const Edge3& e = a.g.edges[k];
    frame_point(a.turned, e, int64_t{a.carry_out[i].lower} + (rising(e) ? 0 : 1), &pts[n].x,
                &pts[n].y);
    ++n;
  }
  return n;
}

}  // namespace

// Puts the segments joined to a carried piece's lower end (through shared ends, a few links
// deep) first, the rest after them in column order, and returns how many are deferred. Only the
// band's own segments (the first n_own of u) are deferred: those deferred to it from below are
// drawn here, so a piece carried across many bands cannot gather its neighbours band after
// band (a long hidden edge of a solid would, until the arena is full). Its workspace (the ends
// found so far, sorted, and a mark per segment) comes from `free`; with too little room, or
// more deferred than a quarter of the arena holds, nothing is deferred.
uint32_t BandConductor::defer_joined(const Attempt& a, Segment2* u, uint32_t n_own, uint32_t nu,
                                     uint8_t* free) {
  const uint32_t nco = a.n_carry_out;
  RowPoint* pts = reinterpret_cast<RowPoint*>(align_up(free));
  const size_t cap = size_t{nco} + 2 * size_t{nu};
  uint8_t* marks = reinterpret_cast<uint8_t*>(pts + cap);
  uint32_t marked = 0;
  // A solid's lines cut at the top border go on in the band above (join_at_border).
  const bool border = solid_mode();
  if (marks + nu <= arena_ + arena_bytes_ && (nco > 0 || border)) {
    uint32_t n_pts = carried_points(a, pts);
    for (uint32_t i = 0; i < nu; ++i) marks[i] = 0;
    const int32_t top = int32_t(a.y1);
    for (uint32_t i = 0; i < n_own && border; ++i)
      if (u[i].y0 == top || u[i].y1 == top) {
        marks[i] = 1;
        ++marked;
      }
    for (int round = 0; round < kJoinDepth; ++round) {
      sort_in_place(pts, n_pts, &point_less);
      const uint32_t sorted = n_pts;
      for (uint32_t i = 0; i < n_own; ++i) {
        if (marks[i] ||
            !(holds(pts, sorted, u[i].x0, u[i].y0) || holds(pts, sorted, u[i].x1, u[i].y1)))
          continue;
        marks[i] = 1;
        ++marked;
        pts[n_pts++] = RowPoint{u[i].x0, u[i].y0};
        pts[n_pts++] = RowPoint{u[i].x1, u[i].y1};
      }
      if (n_pts == sorted) break;
    }
    if (size_t{marked} * sizeof(Segment2) > arena_bytes_ / 4) {
      for (uint32_t i = 0; i < nu; ++i) marks[i] = 0;
      marked = 0;
    }
    // Marked first (swap with the marks), then each part in a full order.
    uint32_t front = 0;
    for (uint32_t i = 0; i < nu; ++i)
      if (marks[i]) {
        const Segment2 t = u[front];
        u[front] = u[i];
        u[i] = t;
        marks[i] = marks[front];
        marks[front++] = 1;
      }
  } else if (border) {  // no room to follow joins: still the lines cut at the top border
    const int32_t top = int32_t(a.y1);
    for (uint32_t i = 0; i < n_own; ++i)
      if (u[i].y0 == top || u[i].y1 == top) {
        const Segment2 t = u[marked];
        u[marked++] = u[i];
        u[i] = t;
      }
    if (size_t{marked} * sizeof(Segment2) > arena_bytes_ / 4) marked = 0;
  }
  sort_in_place(u, marked, &segment_less);
  sort_in_place(u + marked, nu - marked, ColumnOrder{this});
  return marked;
}

// The path of the band's next column, in the arena after the band's segments.
Status BandConductor::plan_column(const PathPoint** points, uint32_t* n) {
  uint32_t last = next_seg_ + 1;
  auto x_sum = [&](uint32_t i) { return int64_t{segs_[i].x0} + segs_[i].x1; };
  while (last < n_segs_ && column_of(x_sum(last)) == column_of(x_sum(next_seg_))) ++last;
  const uint32_t k = last - next_seg_;
  uint8_t* after =
      reinterpret_cast<uint8_t*>(segs_) + carve_round(size_t{n_segs_} * sizeof(Segment2));
  PathPoint* pts = reinterpret_cast<PathPoint*>(after);
  uint8_t* ws = after + carve_round(size_t{path_points_max(k)} * sizeof(PathPoint));
  const size_t ws_size = size_t(arena_ + arena_bytes_ - ws);
  PathStats ps;
  const uint64_t t0 = now();
  // The pen leaves the column for the next: through its far side (left or right, as the band
  // runs), or after the band's last column, up into the band above.
  const int64_t c = column_of(x_sum(next_seg_));
  PathEnd end;
  end.known = true;
  const int sub = spec_.substep_bits;
  end.x = int32_t((leftward_ ? -c * column_side_ : (c + 1) * column_side_) >> sub);
  end.y = int32_t((last == n_segs_ ? band_y1_ : band_y0_ + (band_y1_ - band_y0_) / 2) >> sub);
  steps_to_band(segs_ + next_seg_, k);  // the column's strokes to steps, after its choice
  const Status s = plan_path(segs_ + next_seg_, k, PenAt{pen_x_, pen_y_}, ws, ws_size, pts,
                             path_points_max(k), n, &ps, end, spec_.clean);
  stats_.other_ticks += now() - t0;
  if (!ok(s)) return s;
  // A column whose path starts where the last one left the pen down (a stroke continued across
  // the column's side or the band's border) goes on drawing: no lift and put-down on one spot.
  const bool goes_on = pen_down_ && *n > 1 && pts[0].pen_down == 0 && pts[0].x == pen_x_ &&
                       pts[0].y == pen_y_ && pts[1].pen_down != 0;
  if (*n > 0) {
    pen_x_ = pts[*n - 1].x;
    pen_y_ = pts[*n - 1].y;
    pen_down_ = pts[*n - 1].pen_down != 0;
  }
  steps_to_page(pts, *n);
  ps.pen_lifts += next_seg_ > 0 && ps.polylines > 0 && !goes_on ? 1 : 0;
  add_path_stats(&stats_.path, ps);
  next_seg_ = last;
  *points = goes_on ? pts + 1 : pts;
  *n -= goes_on ? 1 : 0;
  return Status::kOk;
}

}  // namespace haloplot
