#include "haloplot/band/curve_bands.h"

#include "haloplot/geometry/units.h"
#include "memory/carve.h"

namespace haloplot {

// Far beyond the contract's rows: a margin this wide takes every edge.
inline constexpr int64_t kWholeScene = int64_t{1} << 40;

struct CurveBands::Band {
  int64_t y0 = 0, y1 = 0;  // rows [y0, y1)
  BezierEdge3* curves = nullptr;
  Edge3* segments = nullptr;
  uint32_t* ids = nullptr;  // scene index of local edge k (curves first, then segments)
  uint32_t nc = 0, ns = 0;
  size_t front = 0;  // bytes of the three arrays above
  CurveHit* hits = nullptr;
  uint32_t n_hits = 0;
  Segment2* chords = nullptr;
  uint32_t n_chords = 0;
  size_t need = 0;  // did not fit: the bytes it asked for
};

namespace {

// The band's chords: counted, or stored (with `out`), only those whose upper end lies in the
// band's rows; each stored one shown to the observer in steps.
struct OwnedChords {
  const CurveBands::Band* band;
  Segment2* out;
  uint32_t capacity, count;
  const PieceObserver* observer;
  int substep_bits;
  static Status emit(void* ctx, const Span& s) {
    auto* self = static_cast<OwnedChords*>(ctx);
    const int64_t upper = s.y0 > s.y1 ? s.y0 : s.y1;
    if (upper < self->band->y0 || upper >= self->band->y1) return Status::kOk;
    if (self->out != nullptr) {
      if (self->count == self->capacity) return Status::kSinkFull;
      const Segment2 g{s.x0, s.y0, s.x1, s.y1};
      self->out[self->count] = g;
      if (self->observer->piece != nullptr) {
        Segment2 steps = g;
        round_to_steps(&steps, 1, self->substep_bits);
        self->observer->piece(self->observer->ctx,
                              BandPiece{{self->band->ids[s.edge], s.t0, s.t1}, steps});
      }
    }
    ++self->count;
    return Status::kOk;
  }
};

Status no_chords(void*, const Span&) { return Status::kOk; }

}  // namespace

void CurveBands::box_rows(uint32_t k, int64_t* lo, int64_t* hi) const {
  if (k < nc_) {
    const BezierEdge3& c = curves_[k];
    *lo = *hi = c.p[0].y;
    for (int i = 1; i < 4; ++i) {
      *lo = c.p[i].y < *lo ? c.p[i].y : *lo;
      *hi = c.p[i].y > *hi ? c.p[i].y : *hi;
    }
    return;
  }
  const Edge3& e = segments_[k - nc_];
  *lo = e.a.y < e.b.y ? e.a.y : e.b.y;
  *hi = e.a.y < e.b.y ? e.b.y : e.a.y;
}

Status CurveBands::begin(const CurveBandSpec& spec, const BezierEdge3* curves, uint32_t n_curves,
                         const Edge3* segments, uint32_t n_segments, void* arena,
                         size_t arena_bytes) {
  done_ = true;
  stats_ = BandStats{};
  if (buffer_misaligned(arena)) return Status::kMisalignedBuffer;
  if (spec.substep_bits < 0 || spec.substep_bits > kMaxSubstepBits || spec.max_rows < 0)
    return Status::kBadParameter;
  // The stages' plans check the scene and the settings once, before any band.
  CurveCrossPlan cp;
  Status s = plan_curve_cross(curves, n_curves, segments, n_segments, spec.cross, &cp);
  CurveDrawPlan dp;
  if (ok(s))
    s = plan_curve_draw(curves, n_curves, segments, n_segments, nullptr, 0, spec.draw, &dp);
  if (!ok(s)) return s;
  spec_ = spec;
  spec_.clean.min_stroke = 0;
  curves_ = curves;
  segments_ = segments;
  nc_ = n_curves;
  ns_ = n_segments;
  arena_ = static_cast<uint8_t*>(arena);
  arena_bytes_ = arena_bytes & ~size_t{7};
  row_lo_ = kWholeScene;
  row_hi_ = -kWholeScene;
  for (uint32_t k = 0; k < nc_ + ns_; ++k) {
    int64_t lo, hi;
    box_rows(k, &lo, &hi);
    row_lo_ = lo < row_lo_ ? lo : row_lo_;
    row_hi_ = hi > row_hi_ ? hi : row_hi_;
  }
  stats_.edge_reads += nc_ + ns_;
  next_row_ = row_lo_;
  height_ = row_hi_ - row_lo_ + 1;
  margin_known_ = spec.fixed_margin >= 0;
  margin_ = margin_known_ ? spec.fixed_margin : 0;
  stats_.margin = int32_t(margin_);
  pen_x_ = spec.start_x;
  pen_y_ = spec.start_y;
  points_ = nullptr;
  n_points_ = 0;
  done_ = nc_ + ns_ == 0;
  return Status::kOk;
}

// The edges whose box meets rows [lo, hi], at the arena's front in the scene's order.
Status CurveBands::gather(int64_t lo, int64_t hi, Band* b) {
  uint32_t nc = 0, ns = 0;
  for (uint32_t k = 0; k < nc_ + ns_; ++k) {
    int64_t r0, r1;
    box_rows(k, &r0, &r1);
    if (r1 >= lo && r0 <= hi) ++(k < nc_ ? nc : ns);
  }
  stats_.edge_reads += nc_ + ns_;
  const size_t cb = carve_round(size_t{nc} * sizeof(BezierEdge3));
  const size_t sb = carve_round(size_t{ns} * sizeof(Edge3));
  b->front = cb + sb + carve_round(size_t{nc + ns} * sizeof(uint32_t));
  if (b->front > arena_bytes_) {
    b->need = b->front;
    return Status::kWorkspaceTooSmall;
  }
  b->curves = reinterpret_cast<BezierEdge3*>(arena_);
  b->segments = reinterpret_cast<Edge3*>(arena_ + cb);
  b->ids = reinterpret_cast<uint32_t*>(arena_ + cb + sb);
  b->nc = nc;
  b->ns = ns;
  uint32_t i = 0, j = 0;
  for (uint32_t k = 0; k < nc_ + ns_; ++k) {
    int64_t r0, r1;
    box_rows(k, &r0, &r1);
    if (r1 < lo || r0 > hi) continue;
    if (k < nc_) {
      b->curves[i] = curves_[k];
      b->ids[i++] = k;
    } else {
      b->segments[j] = segments_[k - nc_];
      b->ids[nc + j++] = k;
    }
  }
  stats_.edge_reads += nc_ + ns_;
  if (nc + ns > stats_.most_edges) stats_.most_edges = nc + ns;
  note(b->front);
  return Status::kOk;
}

// The crossings (their scratch at the arena's end, the hits growing up to it), then DRAW: the
// chords counted, the arena checked for them and for the path, then stored after DRAW's
// scratch. The margin pass stops after a DRAW that only measures its gaps' reach.
Status CurveBands::cross_and_draw(Band* b, bool drawing) {
  CurveCrossPlan cp;
  Status s = plan_curve_cross(b->curves, b->nc, b->segments, b->ns, spec_.cross, &cp);
  if (!ok(s)) return s;
  const size_t cross = carve_round(cp.scratch_bytes);
  const size_t room = arena_bytes_ > b->front + cross ? arena_bytes_ - b->front - cross : 0;
  const uint32_t capacity =
      uint32_t(room / sizeof(CurveHit) < UINT32_MAX ? room / sizeof(CurveHit) : UINT32_MAX);
  if (capacity == 0) {
    b->need = b->front + cross + sizeof(CurveHit);
    return Status::kWorkspaceTooSmall;
  }
  b->hits = reinterpret_cast<CurveHit*>(arena_ + b->front);
  CurveCrossStats cs;
  ++stats_.cut_runs;
  s = run_curve_cross(cp, b->curves, b->segments, arena_ + arena_bytes_ - cross, cross, b->hits,
                      capacity, &b->n_hits, &cs);
  if (s == Status::kCrossingCapacity) {  // in 64 bits: a 32-bit size_t may not hold it
    const uint64_t need = uint64_t{b->front} + cross + cs.needed * sizeof(CurveHit);
    b->need = need < SIZE_MAX ? size_t(need) : SIZE_MAX;
  }
  if (!ok(s)) return s;
  const size_t hits_end = b->front + carve_round(size_t{b->n_hits} * sizeof(CurveHit));
  note(hits_end + cross);
  stats_.records += b->n_hits;

  CurveDrawPlan dp;
  s = plan_curve_draw(b->curves, b->nc, b->segments, b->ns, b->hits, b->n_hits, spec_.draw, &dp);
  if (!ok(s)) return s;
  const size_t draw = carve_round(dp.scratch_bytes);
  if (hits_end + draw > arena_bytes_) {
    b->need = hits_end + draw;
    return Status::kWorkspaceTooSmall;
  }
  uint8_t* scratch = arena_ + hits_end;
  CurveDrawStats ds;
  ++stats_.draw_runs;
  OwnedChords own{b, nullptr, 0, 0, &observer_, spec_.substep_bits};
  const SpanSink counter =
      drawing ? SpanSink{&OwnedChords::emit, &own} : SpanSink{&no_chords, nullptr};
  s = run_curve_draw(dp, b->curves, b->segments, b->hits, b->n_hits, scratch, draw, counter,
                     nullptr, &ds);
  if (!ok(s)) return s;
  note(hits_end + draw);
  if (!drawing) {
    const int64_t reach = ds.reach < uint64_t(kWholeScene) ? int64_t(ds.reach) : kWholeScene;
    if (reach > margin_) margin_ = reach;
    return Status::kOk;
  }
  const uint32_t n = own.count;
  const size_t chords = carve_round(size_t{n} * sizeof(Segment2));
  const size_t path = chords + carve_round(size_t{path_points_max(n)} * sizeof(PathPoint)) +
                      carve_round(path_plan_bytes(n));
  const size_t need = hits_end + draw + chords > path ? hits_end + draw + chords : path;
  if (need > arena_bytes_) {
    b->need = need;
    return Status::kWorkspaceTooSmall;
  }
  note(need);
  b->need = need;
  return Status::kOk;
}

// The fitted band's chords for good: DRAW again, storing them (and showing each to the
// observer), moved to the arena's front over the dead arrays, rounded to steps, planned.
Status CurveBands::commit(Band* b) {
  CurveDrawPlan dp;
  Status s =
      plan_curve_draw(b->curves, b->nc, b->segments, b->ns, b->hits, b->n_hits, spec_.draw, &dp);
  if (!ok(s)) return s;
  const size_t hits_end = b->front + carve_round(size_t{b->n_hits} * sizeof(CurveHit));
  const size_t draw = carve_round(dp.scratch_bytes);
  Segment2* stored = reinterpret_cast<Segment2*>(arena_ + hits_end + draw);
  const size_t room = (arena_bytes_ - hits_end - draw) / sizeof(Segment2);
  OwnedChords own{b, stored,     uint32_t(room < UINT32_MAX ? room : UINT32_MAX),
                  0, &observer_, spec_.substep_bits};
  CurveDrawStats ds;
  s = run_curve_draw(dp, b->curves, b->segments, b->hits, b->n_hits, arena_ + hits_end, draw,
                     SpanSink{&OwnedChords::emit, &own}, nullptr, &ds);
  if (!ok(s)) return s;
  // Forward copy through a local: overlapping records are read before they are overwritten.
  Segment2* chords = reinterpret_cast<Segment2*>(arena_);
  for (uint32_t i = 0; i < own.count; ++i) {
    const Segment2 g = stored[i];
    chords[i] = g;
  }
  const uint32_t n = own.count;
  round_to_steps(chords, n, spec_.substep_bits);
  const size_t chord_bytes = carve_round(size_t{n} * sizeof(Segment2));
  const size_t point_bytes = carve_round(size_t{path_points_max(n)} * sizeof(PathPoint));
  PathPoint* points = reinterpret_cast<PathPoint*>(arena_ + chord_bytes);
  PathStats ps;
  uint32_t np = 0;
  s = plan_path(chords, n, PenAt{pen_x_, pen_y_}, arena_ + chord_bytes + point_bytes,
                arena_bytes_ - chord_bytes - point_bytes, points, path_points_max(n), &np, &ps,
                PathEnd{}, spec_.clean);
  if (!ok(s)) return s;
  add_path_stats(&stats_.path, ps);
  ++stats_.bands;
  stats_.pieces += n;
  stats_.band_edges += b->nc + b->ns;
  if (n > stats_.most_pieces) stats_.most_pieces = n;
  if (observer_.band != nullptr) observer_.band(observer_.ctx, int32_t(b->y0), int32_t(b->y1));
  if (np > 0) {
    pen_x_ = points[np - 1].x;
    pen_y_ = points[np - 1].y;
  }
  points_ = points;
  n_points_ = np;
  return Status::kOk;
}

namespace {
// An attempt that ran out of arena: the band is halved, never truncated.
bool too_big(Status s) {
  return s == Status::kWorkspaceTooSmall || s == Status::kCrossingCapacity ||
         s == Status::kSinkFull;
}
}  // namespace

Status CurveBands::attempt(int64_t y0, int64_t y1, bool drawing, bool* fitted) {
  used_ = 0;
  *fitted = false;
  Band b;
  b.y0 = y0;
  b.y1 = y1;
  int64_t lo = y0, hi = y1 - 1;
  if (drawing) {  // the rows of the own edges' boxes, widened by the margin
    int64_t own_lo = kWholeScene, own_hi = -kWholeScene;
    for (uint32_t k = 0; k < nc_ + ns_; ++k) {
      int64_t r0, r1;
      box_rows(k, &r0, &r1);
      if (r1 < y0 || r0 > y1 - 1) continue;
      own_lo = r0 < own_lo ? r0 : own_lo;
      own_hi = r1 > own_hi ? r1 : own_hi;
    }
    stats_.edge_reads += nc_ + ns_;
    if (own_lo > own_hi) {  // no edge meets the band: nothing to draw
      *fitted = true;
      n_points_ = 0;
      return Status::kOk;
    }
    lo = own_lo - margin_;
    hi = own_hi + margin_;
  }
  if (y0 <= row_lo_ && y1 > row_hi_) lo = -kWholeScene, hi = kWholeScene;  // the whole scene
  Status s = gather(lo, hi, &b);
  if (ok(s)) s = cross_and_draw(&b, drawing);
  if (ok(s) && drawing) s = commit(&b);
  if (too_big(s)) {
    stats_.need_bytes = b.need;
    return Status::kOk;
  }
  *fitted = ok(s);
  return s;
}

int64_t CurveBands::grown(int64_t rows) const {
  return used_ <= arena_bytes_ / 2 ? 2 * rows : rows;
}

Status CurveBands::margin_pass() {
  int64_t y = row_lo_, h = row_hi_ - row_lo_ + 1;
  while (y <= row_hi_) {
    const int64_t y1 = y + h < row_hi_ + 1 ? y + h : row_hi_ + 1;
    bool fitted = false;
    const Status s = attempt(y, y1, false, &fitted);
    if (!ok(s)) return s;
    if (!fitted) {
      if (y1 - y == 1) return Status::kArenaTooSmall;
      h = (y1 - y) / 2;
      ++stats_.splits;
      continue;
    }
    ++stats_.margin_bands;
    h = grown(y1 - y);
    y = y1;
  }
  stats_.gap_reach = int32_t(margin_ < INT32_MAX ? margin_ : INT32_MAX - 1);
  margin_ = margin_ + 1;
  stats_.margin = int32_t(margin_ < INT32_MAX ? margin_ : INT32_MAX);
  margin_known_ = true;
  return Status::kOk;
}

Status CurveBands::next(const PathPoint** points, uint32_t* n) {
  *points = nullptr;
  *n = 0;
  while (!done_) {
    if (next_row_ > row_hi_) {
      done_ = true;
      break;
    }
    const int64_t h = spec_.max_rows > 0 && height_ > spec_.max_rows ? spec_.max_rows : height_;
    const int64_t y1 = next_row_ + h < row_hi_ + 1 ? next_row_ + h : row_hi_ + 1;
    if (!margin_known_ && (next_row_ > row_lo_ || y1 <= row_hi_)) {  // a band, not the scene
      const Status ms = margin_pass();
      if (!ok(ms)) return ms;
    }
    bool fitted = false;
    const Status s = attempt(next_row_, y1, true, &fitted);
    if (!ok(s)) return s;
    if (!fitted) {
      if (y1 - next_row_ == 1) return Status::kArenaTooSmall;
      height_ = (y1 - next_row_) / 2;
      ++stats_.splits;
      continue;
    }
    height_ = grown(y1 - next_row_);
    next_row_ = y1;
    if (n_points_ > 0) {
      *points = points_;
      *n = n_points_;
      return Status::kOk;
    }
  }
  return Status::kOk;
}

}  // namespace haloplot
