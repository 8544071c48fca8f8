#include "haloplot/band/conductor.h"

#include "band/band_attempt.h"
#include "haloplot/band/band_rule.h"
#include "memory/carve.h"

namespace haloplot {

Status BandConductor::begin(const BandSpec& spec, EdgeSource source, void* arena,
                            size_t arena_bytes) {
  const PieceObserver observer = observer_;
  uint64_t (*clock)() = clock_;
  *this = BandConductor{};
  observer_ = observer;
  clock_ = clock;
  if (buffer_misaligned(arena)) return Status::kMisalignedBuffer;
  if (source.n > 0 && source.read == nullptr) return Status::kBadParameter;
  if (spec.substep_bits < 0 || spec.substep_bits > kMaxSubstepBits) return Status::kBadParameter;
  if (spec.haloed && (spec.draw.halo < 0 || spec.draw.halo > kCoordMax || spec.cut.reach < 0 ||
                      spec.cut.reach > kCoordMax))
    return Status::kBadParameter;
  if (source.n > kMaxEdges) return Status::kTooManyEdges;
  spec_ = spec;
  // Bands always list cells by edge index (4 bytes a pair, not 20), and report no progress:
  // the bands, and so the plot, must not depend on the caller's host-side preferences.
  spec_.cut.compact_cells = false;
  spec_.cut.progress = nullptr;
  spec_.cut.phase = nullptr;
  source_ = source;
  arena_ = static_cast<uint8_t*>(arena);
  arena_bytes_ = arena == nullptr ? 0 : arena_bytes & ~size_t{7};
  // One read of the scene: its rows, and every coordinate in range.
  int32_t lo = kCoordLimit, hi = -1;
  bool in_range_all = true;
  const Status s = for_each_edge(source, [&](uint32_t, const Edge3& e) {
    in_range_all = in_range(e);
    if (edge_row_min(e) < lo) lo = edge_row_min(e);
    if (edge_row_max(e) > hi) hi = edge_row_max(e);
    return in_range_all;
  });
  if (!ok(s)) return s;
  if (!in_range_all) return Status::kCoordinateOutOfRange;
  stats_.edge_reads += source.n;
  pen_x_ = spec.start_x;
  pen_y_ = spec.start_y;
  pen_down_ = false;
  turned_ = false;                        // begin_solid turns a wide solid
  if (source.n == 0) return Status::kOk;  // done: nothing to draw
  row_lo_ = lo;
  row_hi_ = hi;
  next_row_ = lo;
  height_ = int64_t{hi} - lo + 1;  // the first attempt: the whole scene in one band
  running_ = true;
  return Status::kOk;
}

Status BandConductor::begin_streamed(const BandSpec& spec, int32_t margin, BandStream stream,
                                     void* arena, size_t arena_bytes) {
  if (stream.next == nullptr || margin < 0) return Status::kBadParameter;
  const Status s = begin(spec, EdgeSource{}, arena, arena_bytes);
  if (!ok(s)) return s;
  stream_ = stream;
  stats_.margin = margin;
  margin_known_ = true;
  running_ = true;
  return Status::kOk;
}

// A streamed band: its edges read from the stream's buffer as the gathering reads a scene, then
// worked like any band. It must fit: the host that sent it ran this arena.
Status BandConductor::next_streamed_band() {
  StreamedBand band;
  bool end = false;
  Status s = stream_.next(stream_.ctx, &band, &end);
  if (!ok(s)) return s;  // kBusy: not here yet
  if (end) {
    running_ = false;
    return n_carry_ != 0 || n_defer_ != 0 ? Status::kBandCarryLost : Status::kOk;
  }
  if (band.y0 != next_row_ && stats_.bands > 0) return Status::kMalformedRequest;
  if (solid_mode() && band.solid == nullptr) return Status::kMalformedRequest;
  if (solid_mode()) solid_ = solid_stage_->streamed(*band.solid, closed_);
  source_ = array_edge_source(band.edges, band.n);
  stream_ids_ = band.ids;
  next_row_ = band.y0;
  bool fitted = false;
  s = try_band(band.y1, &fitted);
  stream_ids_ = nullptr;
  source_ = EdgeSource{};
  if (solid_mode()) solid_ = SolidSource{};
  if (stream_.release != nullptr) stream_.release(stream_.ctx);
  if (!ok(s)) return s;
  if (!fitted) return Status::kArenaTooSmall;
  next_row_ = band.y1;
  return Status::kOk;
}

// The edges meeting rows [lo, hi]: Edge3s from the front of the free arena, source indices
// from its top down, so one read of the source fills both.
Status BandConductor::gather(int64_t lo, int64_t hi, Gathered* g) {
  uint8_t* base = arena_ + front_bytes();
  uint8_t* top = arena_ + arena_bytes_;
  g->edges = reinterpret_cast<Edge3*>(base);
  g->ids_end = reinterpret_cast<uint32_t*>(top);
  const size_t room = top > base ? size_t(top - base) : 0;
  uint32_t m = 0;
  const Status s = for_each_edge(source_, [&](uint32_t index, const Edge3& e) {
    if (!edge_meets_rows(e, lo, hi)) return true;
    if (size_t{m + 1} * (sizeof(Edge3) + sizeof(uint32_t)) <= room) {
      g->edges[m] = e;
      g->ids_end[-1 - int64_t{m}] = stream_ids_ != nullptr ? stream_ids_[index] : index;
    }
    ++m;
    return true;  // keep counting past the room: the count says what the band needs
  });
  if (!ok(s)) return s;
  stats_.edge_reads += source_.n;
  g->n = m;
  if (size_t{m} * (sizeof(Edge3) + sizeof(uint32_t)) + 16 > room ||
      (spec_.max_band_edges > 0 && m > spec_.max_band_edges))
    return Status::kWorkspaceTooSmall;
  g->free_lo = align_up(base + size_t{m} * sizeof(Edge3));
  g->free_hi = align_down(top - size_t{m} * sizeof(uint32_t));
  return Status::kOk;
}

// CUT on the gathered edges: the CUTSET from the free middle's start with as many records as
// fit beside CUT's scratch. *after is where the CUTSET really ends (DRAW's space starts there).
Status BandConductor::cut_band(const Gathered& g, CutSet* cs, uint8_t** after, size_t* need) {
  const size_t fixed = size_t(g.free_lo - arena_) + size_t(arena_ + arena_bytes_ - g.free_hi);
  CutPlan plan;
  Status s = plan_cut(g.edges, g.n, spec_.cut, &plan);
  if (!ok(s)) return s;
  const size_t scratch = carve_round(plan.scratch_bytes);
  const size_t space = size_t(g.free_hi - g.free_lo);
  const size_t index = carve_round(cutset_bytes(g.n, 0));
  if (space < scratch + index) {
    *need = fixed + scratch + index;
    return Status::kWorkspaceTooSmall;
  }
  const size_t storage = (space - scratch) & ~size_t{7};
  CutStats st;
  ++stats_.cut_runs;
  s = run_cut(plan, g.edges, g.free_lo + storage, scratch, g.free_lo, storage, cs, &st);
  if (s == Status::kCrossingCapacity) {
    const uint64_t records = st.crossings + st.near_misses;
    *need = fixed + scratch + carve_round(cutset_bytes(g.n, uint32_t(records)));
    return s;
  }
  if (!ok(s)) return s;
  const size_t used = carve_round(cutset_bytes(g.n, cs->n_crossings));
  note_used(fixed + used + scratch);
  *after = g.free_lo + used;
  return Status::kOk;
}

// How far a band must look for this record's front edge: the rows from the farthest point of
// the gap to the front edge's nearest row (0 when the gap lies within the edge's rows). A band
// whose rows the gap touches then holds the front edge once widened by that many rows, and
// the behind edge too (it runs through the gap). For the exact halo every gap point is within
// the halo width of the front edge, so this stays near W; the paper's W / sin(theta) can
// reach far along a near-parallel edge.
int64_t BandConductor::gap_reach(const CutSet& cs, const Crossing& r) const {
  const Gap gap = record_gap(cs, r, spec_.draw);
  if (gap.empty()) return 0;
  const Edge3& e = cs.edges[r.behind];
  const int64_t base = int64_t{e.a.y} * kFracOne, dy = int64_t{e.b.y} - e.a.y;
  const int64_t v0 = base + dy * gap.lo, v1 = base + dy * gap.hi;          // rows * 2^32, < 2^54
  const int64_t low = (v0 < v1 ? v0 : v1) >> kFracBits;                    // floor
  const int64_t high = ((v0 < v1 ? v1 : v0) + kFracOne - 1) >> kFracBits;  // ceiling
  const Edge3& f = cs.edges[r.front_edge()];
  const int64_t below = edge_row_min(f) - low, above = high - edge_row_max(f);
  const int64_t d = below > above ? below : above;
  return d > 0 ? d : 0;
}

// The margin pass: CUT over the scene in bands (each widened by CUT's reach, so every record
// is found in the band that holds its point), and the farthest row any record's gap reaches
// from that point. Only a plot whose scene did not fit one band runs it.
Status BandConductor::margin_pass() {
  const uint64_t t_start = now();
  const int64_t widen = int64_t{spec_.cut.reach} + 1;
  int64_t y = row_lo_, h = (int64_t{row_hi_} - row_lo_ + 2) / 2;
  int64_t reach = 0;
  while (y <= row_hi_) {
    const int64_t y1 = y + h < int64_t{row_hi_} + 1 ? y + h : int64_t{row_hi_} + 1;
    Gathered g;
    CutSet cs;
    uint8_t* after = nullptr;
    size_t need = 0;
    band_used_ = 0;
    Status s = gather(y - widen, y1 - 1 + widen, &g);
    if (s == Status::kWorkspaceTooSmall) need = size_t{g.n} * (sizeof(Edge3) + 4) + 16;
    if (ok(s)) s = cut_band(g, &cs, &after, &need);
    if (does_not_fit(s)) {
      if (y1 - y == 1) {
        stats_.need_bytes = need + front_bytes();
        return Status::kArenaTooSmall;
      }
      h = shorter(y1 - y, need);
      ++stats_.splits;
      continue;
    }
    if (!ok(s)) return s;
    for (uint32_t i = 0; i < cs.n_crossings; ++i) {
      const int64_t rows = gap_reach(cs, cs.crossings[i]);
      if (rows > reach) reach = rows;
    }
    ++stats_.margin_bands;
    h = next_height(y1 - y);
    y = y1;
  }
  stats_.gap_reach = int32_t(reach);
  stats_.margin = int32_t(reach + 1);
  margin_known_ = true;
  stats_.margin_ticks += now() - t_start;
  return Status::kOk;
}

// DRAW (or every edge whole) into the attempt's sink; scratch, carry out and pieces carved
// from `after` (where the CUTSET ends).
Status BandConductor::draw_band(Attempt& a) {
  const bool cut = cuts();
  uint8_t* p = a.after;
  const size_t scratch = cut ? carve_round(draw_scratch_bytes(a.cs)) : 0;
  // At most one piece of an edge runs past the top row: room for the edges that cross it.
  for (uint32_t k = 0; k < a.g.n; ++k)
    if (edge_row_min(a.g.edges[k]) < a.y1 && edge_row_max(a.g.edges[k]) >= a.y1) ++a.carry_capacity;
  uint8_t* carry = p + scratch;
  uint8_t* carry_points = carry + carve_round(size_t{a.carry_capacity} * sizeof(Carry));
  uint8_t* pieces = carry_points + carve_round(size_t{a.carry_capacity} * sizeof(RowPoint));
  const size_t fixed = size_t(a.g.free_lo - arena_) + size_t(arena_ + arena_bytes_ - a.g.free_hi);
  if (pieces > a.g.free_hi) {
    a.need = fixed + size_t(pieces - a.g.free_lo);
    return Status::kWorkspaceTooSmall;
  }
  a.carry_in = reinterpret_cast<const Carry*>(arena_);
  a.n_carry_in = n_carry_;
  a.carry_out = reinterpret_cast<Carry*>(carry);
  a.carry_points = reinterpret_cast<RowPoint*>(carry_points);
  a.pieces = reinterpret_cast<StoredPiece*>(pieces);
  a.piece_capacity = uint32_t(size_t(a.g.free_hi - pieces) / sizeof(StoredPiece));
  Status s = Status::kOk;
  const uint64_t t0 = now();
  if (cut) {
    ++stats_.draw_runs;
    s = draw(a.cs, spec_.draw, p, scratch, SpanSink{&Attempt::on_span, &a}, nullptr);
  } else {
    for (uint32_t k = 0; k < a.g.n && ok(s); ++k)
      s = Attempt::on_span(&a, Span{{k, 0, kFracOne}, 0, 0, 0, 0});
  }
  stats_.draw_ticks += now() - t0;
  if (s == Status::kSinkFull)
    a.need = fixed + size_t(pieces - a.g.free_lo) + 2 * size_t(a.g.free_hi - pieces);
  if (!ok(s)) return s;
  if (a.carry_used != n_carry_) return Status::kBandCarryLost;
  note_used(size_t(reinterpret_cast<uint8_t*>(a.pieces + a.n_pieces) - arena_) +
            size_t(arena_ + arena_bytes_ - a.g.free_hi));
  return Status::kOk;
}

// Band heights from the bytes bands take. A band holds the edges of its rows and of the margin
// above and below them, so its bytes grow about in proportion to rows + 2 margin: the next band
// aims at 7/8 of the arena at the last band's bytes per such row, at most doubling (a dense
// stretch may follow a sparse one), and a band that did not fit is cut the same way by the
// bytes it asked for (at most halved when that is unknown). Every retry costs a band's CUT, so
// a good guess is worth more than a tall band.
int64_t BandConductor::rows_for(int64_t rows, size_t bytes) const {
  const int64_t span = rows + 2 * int64_t{stats_.margin};
  const uint64_t target = arena_bytes_ / 8 * 7;
  const int64_t aim =
      int64_t(uint64_t(span) * target / (bytes > 0 ? bytes : 1)) - 2 * int64_t{stats_.margin};
  return aim < 1 ? 1 : aim;
}

int64_t BandConductor::next_height(int64_t rows) const {
  const int64_t aim = rows_for(rows, band_used_);
  return aim < 2 * rows ? aim : 2 * rows;
}

int64_t BandConductor::shorter(int64_t rows, size_t need) const {
  const int64_t aim = need > arena_bytes_ ? rows_for(rows, need) : rows / 2;
  const int64_t h = aim < rows / 2 ? aim : rows / 2;
  return h < 1 ? 1 : h;
}

// One attempt at the band [next_row_, y1): *fitted false when the arena was too small for it.
Status BandConductor::try_band(int32_t y1, bool* fitted) {
  const uint64_t t_start = now();
  band_used_ = 0;
  const uint64_t cut_before = stats_.cut_ticks, draw_before = stats_.draw_ticks;
  Attempt a;
  a.y0 = next_row_;
  a.y1 = y1;
  a.turned = turned_;
  const int64_t margin = stats_.margin;
  Status s;
  if (solid_mode()) {  // a solid: its faces and edges, then its hidden lines
    s = solid_stage_->band(*this, a);
  } else {
    s = gather(a.y0 - margin, a.y1 - 1 + margin, &a.g);
    if (s == Status::kWorkspaceTooSmall)
      a.need = front_bytes() + size_t{a.g.n} * (sizeof(Edge3) + sizeof(uint32_t)) + 16;
    a.after = a.g.free_lo;
    if (ok(s) && cuts()) {
      const uint64_t t0 = now();
      s = cut_band(a.g, &a.cs, &a.after, &a.need);
      stats_.cut_ticks += now() - t0;
    }
    if (ok(s)) s = draw_band(a);
  }
  if (ok(s)) s = commit_band(a);
  *fitted = !does_not_fit(s);
  const uint64_t spent = now() - t_start;
  if (!*fitted) {  // the attempt's work is waste: count it there, not in CUT and DRAW
    stats_.need_bytes = a.need;
    stats_.wasted_ticks += spent;
    stats_.cut_ticks = cut_before;
    stats_.draw_ticks = draw_before;
  } else {
    stats_.other_ticks +=
        spent - (stats_.cut_ticks - cut_before) - (stats_.draw_ticks - draw_before);
  }
  return *fitted ? s : Status::kOk;
}

Status BandConductor::next(const PathPoint** points, uint32_t* n) {
  *n = 0;
  *points = nullptr;
  while (running_ || next_seg_ < n_segs_) {
    if (next_seg_ < n_segs_) {  // the current band's next column
      const Status s = plan_column(points, n);
      if (!ok(s) || *n > 0) return s;
      continue;
    }
    if (stream_.next != nullptr) {
      const Status s = next_streamed_band();
      if (!ok(s)) return s;
      continue;
    }
    if (next_row_ > row_hi_) {
      running_ = false;
      if (n_carry_ != 0 || n_defer_ != 0) return Status::kBandCarryLost;
      break;
    }
    const int64_t h = spec_.max_rows > 0 && height_ > spec_.max_rows ? spec_.max_rows : height_;
    const int64_t y1 = next_row_ + h < int64_t{row_hi_} + 1 ? next_row_ + h : int64_t{row_hi_} + 1;
    bool fitted = false;
    const Status s = try_band(int32_t(y1), &fitted);
    if (!ok(s)) return s;
    if (!fitted) {
      if (y1 - next_row_ == 1) return Status::kArenaTooSmall;
      if (!margin_known_ && cuts() && spec_.fixed_margin >= 0) {
        stats_.margin = spec_.fixed_margin;
        margin_known_ = true;
      }
      if (!margin_known_ && cuts()) {
        const Status ms = margin_pass();
        if (!ok(ms)) return ms;
      }
      height_ = shorter(y1 - next_row_, stats_.need_bytes);
      ++stats_.splits;
      continue;
    }
    height_ = next_height(y1 - next_row_);
    next_row_ = y1;
  }
  return Status::kOk;
}

}  // namespace haloplot
