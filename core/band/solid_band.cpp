// The band conductor's solid stage: a solid's hidden lines band by band (conductor.h,
// begin_solid). A band gathers the faces and drawn edges meeting its rows with the vertices
// they use, runs the topology-free method in its rows only, and keeps the strokes of the
// pieces it owns; a piece running past the top is carried up with its q. Intersection lines
// (where its faces cross) and contour diagonals (sides of its triangles that are no drawn edge
// but a contour: visible parts, and hidden ones dashed) are drawn in its rows too, cut at its
// borders.
#include "band/band_attempt.h"
#include "haloplot/band/conductor.h"
#include "haloplot/memory/sized_stage.h"
#include "haloplot/solid/hidden_lines.h"
#include "haloplot/sort/lower_bound.h"
#include "memory/carve.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

// The index of global vertex v among the band's sorted vertex ids.
uint32_t local_vertex(const uint32_t* ids, uint32_t n, uint32_t v) {
  return lower_bound_index(0, n, [&](uint32_t i) { return ids[i] < v; });
}

// A piece of the band's run, as cut (solid/fallback.h emits a band's pieces unmerged).
struct RawPiece {
  int64_t t0, t1;
  int32_t q;
  uint8_t hidden, tested;
};

// A run of equal pieces from its lower end (in y) to its upper end, as positions on the edge.
struct Run {
  int64_t lower, upper;
  int32_t q;
  bool hidden;
};

// The hidden-line run's sink for one band. Pieces are merged into runs here, of equal q (the
// way one unbanded run merges them), and hidden-dashed, hidden ones whatever their q (a hidden
// run's dashes are measured from its start, solid/modes.h: a change of q behind the front faces
// starts no new pattern, in the whole-model plot either), across the band's borders too: an
// edge's pieces are taken from its lower end up (a falling edge's in reverse), the first
// continues the run carried from below, the last is carried up. A piece too short to test takes
// the q of the run below it, as in the unbanded run, except a sliver that the top border cut
// off a longer piece: its q is the piece's above the border, so the run below it is carried up
// unfinished and the band above decides where it ends.
struct SolidSink {
  BandConductor::Attempt* a;
  const StrokeStyle* style;
  RawPiece* raw_top = nullptr;  // the current edge's pieces, stacked down from the tail's end
  uint32_t n_raw = 0, raw_edge = 0;
  // The tail's start, and the most of it in use at once (its strokes from the start and its
  // stacks from the end, at the same moment): the band's peak counts it.
  uint8_t* base = nullptr;
  size_t high = 0;
  // Bytes right past the run's buffer that the tail takes too (the band's vertex pairs: the
  // run's topology has read them by the time the sink begins), and whether it has begun: a run
  // asked again after that would read the tail's bytes as its edges (BandRun).
  uint8_t* spare = nullptr;
  size_t spare_bytes = 0;
  bool begun = false;

  static void begin(void* ctx, uint8_t* tail, size_t bytes, const Edge3* edges);
  static Status piece(void* ctx, const HiddenPiece& p);
  static Status outline(void* ctx, const OutlinePiece& p);
  Status finish() { return n_raw > 0 ? flush_edge() : Status::kOk; }
  Status line_piece(const HiddenPiece& p);
  Status diagonal_piece(const HiddenPiece& p);
  Status store_line(const Edge3& g, int64_t t0, int64_t t1, bool extends);
  // The style in this band's frame: short edges' dashes are read on the page (solid/modes.h).
  StrokeStyle frame_style() const {
    StrokeStyle s = *style;
    s.turned = a->turned;
    return s;
  }
  const Edge3* last_line = nullptr;  // the segment whose geometry was stacked last
  // The stored piece of the last line that a piece of it starting at its end goes on (a
  // band's run emits a diagonal's pieces unmerged), or kNoPiece.
  static constexpr uint32_t kNoPiece = ~uint32_t{0};
  uint32_t extend_at = kNoPiece;
  // A contour diagonal's sliver at the low end of its window (too short to test: the border cut
  // it off a piece that began in the band beyond), held for the verdict of the piece after it.
  int64_t sliver_t0 = -1, sliver_t1 = -1;
  uint32_t sliver_edge = 0;
  Status flush_edge();
  Status emit(uint32_t local, bool up, const Run& r);
  Status carry_up(uint32_t id, bool up, const Run& r, int64_t join);
  // The lowest byte the top of the tail uses: the current edge's raw pieces, or (after every
  // edge) the intersection lines' segments.
  uint8_t* raw_bottom() const {
    return reinterpret_cast<uint8_t*>(raw_top - n_raw) - size_t{a->n_lines} * sizeof(Edge3);
  }
  void note() {
    const size_t used = size_t(reinterpret_cast<uint8_t*>(a->pieces + a->n_pieces) - base) +
                        size_t(reinterpret_cast<const uint8_t*>(a->lines_end) - raw_bottom());
    if (used > high) high = used;
  }
};

// The band's run as a sized stage, each run with the sink afresh. The sink's tail takes the
// band's vertex pairs once it begins, so a run asked again after that would build its topology
// from the tail's bytes: refused (kBandInputReused). None is: the counts a run can come short
// of (CUT's records, the incidences) are found before the sink begins, and a run short of
// bytes is not run again in a fixed arena (memory/sized_stage.h).
struct BandRun {
  HiddenLinesStage* stage;
  SolidSink* sink;
  uint32_t capacity;
  size_t bytes(const StageNeeds& needs) const { return stage->bytes(needs); }
  Status run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want) {
    if (sink->begun) return Status::kBandInputReused;
    BandConductor::Attempt& a = *sink->a;
    a.n_pieces = a.n_carry_out = a.carry_cursor = a.carry_used = 0;
    a.carry_capacity = capacity;
    sink->n_raw = 0;
    return stage->run(needs, buffer, bytes, want);
  }
};

}  // namespace

// The carry and the pieces take the run's free tail, once every stage of it has carved; the
// current edge's raw pieces stack down from its end. The run's edges stay below the tail until
// the band is committed.
void SolidSink::begin(void* ctx, uint8_t* tail, size_t bytes, const Edge3* edges) {
  SolidSink& self = *static_cast<SolidSink*>(ctx);
  BandConductor::Attempt& a = *self.a;
  a.g.edges = const_cast<Edge3*>(edges);  // the band's drawn edges are the run's first ones
  uint8_t* end = tail + bytes;
  if (end == self.spare) end += self.spare_bytes;
  end = align_down(end);
  self.begun = true;
  uint8_t* carry = align_up(tail);
  uint8_t* runs = carry + carve_round(size_t{a.carry_capacity} * sizeof(a.carry_out[0]));
  uint8_t* pieces = runs + carve_round(size_t{a.carry_capacity} * sizeof(a.carry_runs_out[0]));
  a.n_pieces = a.n_carry_out = a.carry_cursor = a.carry_used = a.n_lines = 0;
  self.n_raw = 0;
  self.last_line = nullptr;
  self.extend_at = kNoPiece;
  self.sliver_t1 = -1;
  self.base = carry;
  self.high = 0;
  if (pieces > end) {  // no room even for the carry: every piece is then a full sink
    a.carry_capacity = 0;
    a.pieces = reinterpret_cast<StoredPiece*>(end);
    self.raw_top = reinterpret_cast<RawPiece*>(end);
    a.lines_end = reinterpret_cast<const Edge3*>(end);
    return;
  }
  a.carry_out = reinterpret_cast<decltype(a.carry_out)>(carry);
  a.carry_runs_out = reinterpret_cast<decltype(a.carry_runs_out)>(runs);
  a.carry_points = nullptr;  // the commit finds a carried run's lower end on the band's edge
  a.pieces = reinterpret_cast<StoredPiece*>(pieces);
  self.raw_top = reinterpret_cast<RawPiece*>(end);
  a.lines_end = reinterpret_cast<const Edge3*>(end);
}

Status SolidSink::piece(void* ctx, const HiddenPiece& p) {
  SolidSink& self = *static_cast<SolidSink*>(ctx);
  if (p.face[0] != kNoFace) return self.line_piece(p);
  if (p.edge >= self.a->in.n_edges) return self.diagonal_piece(p);
  if (self.n_raw > 0 && p.edge != self.raw_edge) {
    const Status s = self.flush_edge();
    if (!ok(s)) return s;
  }
  self.raw_edge = p.edge;
  if (self.raw_bottom() - sizeof(RawPiece) <
      reinterpret_cast<uint8_t*>(self.a->pieces + self.a->n_pieces))
    return Status::kSinkFull;
  self.raw_top[-1 - int64_t{self.n_raw++}] =
      RawPiece{p.t0, p.t1, p.q, uint8_t(p.hidden ? 1 : 0), uint8_t(p.tested ? 1 : 0)};
  self.note();
  return Status::kOk;
}

// A piece of an intersection line in the band's rows (they come after every edge's pieces): a
// visible one is stored as a stroke of this band, its segment stacked at the tail's top once.
// The band above draws the line's next part from the same segment (found from the same two
// faces), so the strokes of two bands meet end to end, and the border join (solid_border_join.cpp)
// draws them as one.
Status SolidSink::line_piece(const HiddenPiece& p) {
  if (n_raw > 0) {  // the last edge's pieces first: their space is the lines' now
    const Status s = flush_edge();
    if (!ok(s)) return s;
  }
  if (p.hidden || p.t1 <= p.t0 || style->mode == SolidMode::kAll) return Status::kOk;
  return store_line(*p.geometry, p.t0, p.t1, false);
}

// A piece of a contour diagonal (a side of the band's triangles drawn only where it is a contour,
// after every drawn edge: solid/fallback.h). Its visible parts are drawn, as in the whole-model
// plot (solid/modes.h), and like an intersection line's: a diagonal is the band's own, found
// from its triangles, so no index of it carries to the band above, but its segment does (the
// same two vertices), and the border join joins the two bands' strokes.
Status SolidSink::diagonal_piece(const HiddenPiece& p) {
  if (n_raw > 0) {  // the last drawn edge's pieces first: their space is the lines' now
    const Status s = flush_edge();
    if (!ok(s)) return s;
  }
  if (p.t1 <= p.t0 || style->mode == SolidMode::kAll) return Status::kOk;
  int64_t t0 = p.t0;
  if (!p.tested) {
    // The band's run has not seen the piece a sliver at the window's low end belongs to (its
    // default verdict, visible, would draw a stray dot where that piece is hidden): it takes the
    // verdict of the piece after it, which differs from the true one by less than a step. One at
    // the high end takes the piece's before it, as unbanded, and likewise.
    const RowWindow w = row_window(*p.geometry, a->y0, a->y1);
    if (p.t0 == w.lo && w.lo > 0) {
      sliver_edge = p.edge;
      sliver_t0 = p.t0;
      sliver_t1 = p.t1;
      return Status::kOk;
    }
  }
  if (sliver_t1 == p.t0 && sliver_edge == p.edge) t0 = sliver_t0;
  sliver_t1 = -1;
  if (!p.hidden) return store_line(*p.geometry, t0, p.t1, true);
  // Hidden: its dashes hang on the diagonal's ends (solid/modes.h), so this band's are the
  // whole-model plot's wherever the band cuts it.
  return piece_strokes(
      *p.geometry, p.edge, PieceKind::kContour, t0, p.t1, true, frame_style(),
      [this, &p](const Span& d) { return store_line(*p.geometry, d.t0, d.t1, false); });
}

// [t0, t1) of segment g as a stroke of this band: g stacked at the tail's top unless it is the
// last one stacked; with `extends`, a stroke of g ending at t0 goes on instead of a new one.
Status SolidSink::store_line(const Edge3& g, int64_t t0, int64_t t1, bool extends) {
  if (last_line == nullptr || last_line->a.x != g.a.x || last_line->a.y != g.a.y ||
      last_line->a.z != g.a.z || last_line->b.x != g.b.x || last_line->b.y != g.b.y ||
      last_line->b.z != g.b.z) {
    if (raw_bottom() - sizeof(Edge3) < reinterpret_cast<uint8_t*>(a->pieces + a->n_pieces))
      return Status::kSinkFull;
    Edge3* slot = const_cast<Edge3*>(a->lines_end) - 1 - a->n_lines++;
    *slot = g;
    last_line = slot;
    extend_at = kNoPiece;
    note();
  }
  const uint32_t local = a->g.n + a->n_lines - 1;
  if (extends && extend_at != kNoPiece && a->pieces[extend_at].t1_minus_1 + int64_t{1} == t0) {
    StoredPiece& sp = a->pieces[extend_at];
    sp.t1_minus_1 = uint32_t(t1 - 1);
    sp.x_sum = frame_x_sum(a->turned, *last_line, sp.t0, t1);
    return Status::kOk;
  }
  if (reinterpret_cast<uint8_t*>(a->pieces + a->n_pieces + 1) > raw_bottom())
    return Status::kSinkFull;
  if (extends) extend_at = a->n_pieces;
  a->pieces[a->n_pieces++] = StoredPiece{local, uint32_t(t0), uint32_t(t1 - 1),
                                         frame_x_sum(a->turned, *last_line, t0, t1)};
  note();
  return Status::kOk;
}

// An outline run inside the band's rows (the fallback asks Kira's condition part by part): a
// stroke of this band, cut at its borders, so the runs of two bands meet end to end.
Status SolidSink::outline(void* ctx, const OutlinePiece& p) {
  SolidSink& self = *static_cast<SolidSink*>(ctx);
  BandConductor::Attempt& a = *self.a;
  if (p.t1 <= p.t0) return Status::kOk;
  if (p.edge >= a.in.n_edges) {  // along a contour diagonal: kept as its pieces are
    if (self.n_raw > 0) {
      const Status s = self.flush_edge();
      if (!ok(s)) return s;
    }
    return self.store_line(*p.geometry, p.t0, p.t1, false);
  }
  if (reinterpret_cast<uint8_t*>(a.pieces + a.n_pieces + 1) > self.raw_bottom())
    return Status::kSinkFull;
  a.pieces[a.n_pieces++] = StoredPiece{p.edge, uint32_t(p.t0), uint32_t(p.t1 - 1),
                                       frame_x_sum(a.turned, a.g.edges[p.edge], p.t0, p.t1)};
  self.note();
  return Status::kOk;
}

// The strokes of a finished run (solid/modes.h), as pieces the band owns.
Status SolidSink::emit(uint32_t local, bool up, const Run& r) {
  const int64_t t0 = up ? r.lower : r.upper, t1 = up ? r.upper : r.lower;
  if (t1 <= t0) return Status::kOk;  // an empty run before a sliver
  const Edge3& e = a->g.edges[local];
  return piece_strokes(
      e, local, PieceKind::kEdge, t0, t1, r.hidden, frame_style(),
      [this, local, &e](const Span& s) {
        if (reinterpret_cast<uint8_t*>(a->pieces + a->n_pieces + 1) > raw_bottom())
          return Status::kSinkFull;
        const int32_t x_sum = a->turned ? frame_x_sum(true, e, s.t0, s.t1) : s.x0 + s.x1;
        a->pieces[a->n_pieces++] = StoredPiece{local, uint32_t(s.t0), uint32_t(s.t1 - 1), x_sum};
        note();
        return Status::kOk;
      });
}

Status SolidSink::carry_up(uint32_t id, bool up, const Run& r, int64_t join) {
  if (a->n_carry_out == a->carry_capacity) return Status::kSinkFull;
  a->carry_runs_out[a->n_carry_out] = {uint32_t(join), r.q};
  a->carry_out[a->n_carry_out++] = {id, uint32_t(r.lower - (up ? 0 : 1))};
  return Status::kOk;
}

// One edge's pieces in this band, from its lower end up.
Status SolidSink::flush_edge() {
  const uint32_t local = raw_edge, n = n_raw;
  const Edge3& e = a->g.edges[local];
  const uint32_t id = a->g.id(local);
  const RowWindow w = row_window(e, a->y0, a->y1);
  const bool up = rising(e);
  const bool dashed = style->mode == SolidMode::kHiddenDashed;  // hidden runs whatever their q
  Run cur{0, 0, 0, false};
  bool have = false;
  Status s = Status::kOk;
  for (uint32_t k = 0; k < n && ok(s); ++k) {
    RawPiece p = raw_top[-1 - int64_t{up ? k : n - 1 - k}];  // the k-th from below
    int64_t lower = up ? p.t0 : p.t1;
    const int64_t upper = up ? p.t1 : p.t0;
    const bool at_bottom =
        k == 0 && (up ? (p.t0 == w.lo && w.lo > 0) : (p.t1 == w.hi && w.hi < kFracOne));
    const bool at_top =
        k + 1 == n && (up ? (p.t1 == w.hi && w.hi < kFracOne) : (p.t0 == w.lo && w.lo > 0));
    if (at_bottom) {  // the run carried from below goes on here, up to its join
      while (a->carry_cursor < a->n_carry_in && a->carry_in[a->carry_cursor].edge < id)
        ++a->carry_cursor;
      if (a->carry_cursor == a->n_carry_in || a->carry_in[a->carry_cursor].edge != id)
        return Status::kBandCarryLost;
      const auto& c = a->carry_in[a->carry_cursor];
      const auto& run = a->carry_runs_in[a->carry_cursor++];
      ++a->carry_used;
      cur = Run{int64_t{c.lower} + (up ? 0 : 1), int64_t{run.join}, run.q, run.q != 0};
      have = true;
      lower = run.join;  // this piece takes the sliver below the border, if any
      if (!p.tested) {   // the rest of a piece the border cut: the q below it
        p.q = cur.q;
        p.hidden = cur.hidden;
        p.tested = 1;
      }
    }
    if (!p.tested && at_top) {  // cut off by the border: the band above tells its q
      if (!have) cur = Run{lower, lower, 0, false};
      s = carry_up(id, up, cur, lower);
      have = false;
      break;
    }
    if (!p.tested) {  // too short to test: the q of the run below, as unbanded
      p.q = have ? cur.q : 0;
      p.hidden = have ? cur.hidden : 0;
    }
    if (have && cur.hidden == (p.hidden != 0) && (cur.q == p.q || (cur.hidden && dashed))) {
      cur.upper = upper;
    } else {
      if (have) s = emit(local, up, cur);
      cur = Run{lower, upper, p.q, p.hidden != 0};
      have = true;
    }
    if (at_top && ok(s)) {
      s = carry_up(id, up, cur, upper);
      have = false;
    }
  }
  if (have && ok(s)) s = emit(local, up, cur);
  n_raw = 0;
  return s;
}

Status BandConductor::begin_solid(const BandSpec& spec, SolidSource source, void* arena,
                                  size_t arena_bytes) {
  if (source.vertex == nullptr || source.edge == nullptr || source.triangle == nullptr)
    return Status::kBadParameter;
  if (spec.style.dash < 1 || spec.style.gap < 1 || spec.style.dash > kCoordMax ||
      spec.style.gap > kCoordMax)
    return Status::kBadParameter;
  if (source.n_edges > kMaxEdges || source.n_triangles > kMaxEdges) return Status::kTooManyEdges;
  Status s = begin(spec, EdgeSource{}, arena, arena_bytes);
  if (!ok(s)) return s;
  // One read of the vertices: every coordinate in range, and the drawing's extent.
  int32_t lo = kCoordLimit, hi = -1, left = kCoordLimit, right = -1;
  for (uint32_t v = 0; v < source.n_vertices; ++v) {
    Point3 p;
    s = source.vertex(source.ctx, v, &p);
    if (!ok(s)) return s;
    if (!in_range(Edge3{p, p})) return Status::kCoordinateOutOfRange;
    if (p.y < lo) lo = p.y;
    if (p.y > hi) hi = p.y;
    if (p.x < left) left = p.x;
    if (p.x > right) right = p.x;
  }
  solid_ = source;
  solid_stage_ = &kSolidStage;
  closed_ = source.closed;
  // Nothing to draw: no vertices, or neither drawn edges nor faces (a model whose every side is
  // smooth (a crease angle) still draws the contour diagonals of its faces).
  if (source.n_vertices == 0 || (source.n_edges == 0 && source.n_triangles == 0))
    return Status::kOk;
  // Wider than tall: bands across the width, each a column of the page (BandSpec::turn_wide).
  turned_ = spec.turn_wide && right - left > hi - lo;
  stats_.turned = turned_;
  if (turned_) {
    lo = kTurnOffset - right;
    hi = kTurnOffset - left;
    turn_pen();
  }
  row_lo_ = lo;
  row_hi_ = hi;
  next_row_ = lo;
  height_ = int64_t{hi} - lo + 1;
  margin_known_ = true;  // a solid band needs no margin
  running_ = true;
  return Status::kOk;
}

Status BandConductor::begin_streamed_solid(const BandSpec& spec, SolidStreamFlags flags,
                                           BandStream stream, void* arena, size_t arena_bytes) {
  const bool closed = has(flags, SolidStreamFlags::kClosed);
  const bool turned = has(flags, SolidStreamFlags::kTurned);
  if (stream.next == nullptr) return Status::kBadParameter;
  if (spec.style.dash < 1 || spec.style.gap < 1 || spec.style.dash > kCoordMax ||
      spec.style.gap > kCoordMax)
    return Status::kBadParameter;
  const Status s = begin(spec, EdgeSource{}, arena, arena_bytes);
  if (!ok(s)) return s;
  stream_ = stream;
  solid_stage_ = &kSolidStage;
  closed_ = closed;
  margin_known_ = true;
  running_ = true;
  turned_ = turned;
  stats_.turned = turned;
  if (turned) turn_pen();
  return Status::kOk;
}

const BandConductor::SolidStage BandConductor::kSolidStage = {
    [](BandConductor& self, Attempt& a) {
      const Status s = self.gather_solid(a);
      return ok(s) ? self.hide_band(a) : s;
    },
    [](const StagedSolidBand& band, bool closed) { return band.source(closed); },
    [](const BandConductor& self, const Attempt& a, Segment2* u, uint32_t n_own, uint32_t nu,
       uint8_t* free) { return self.join_at_border(a, u, n_own, nu, free); }};

// The band's drawn edges (those meeting its rows), its faces (meeting its rows or the row
// above: the outline pass asks just beyond each border) and the vertices they use, with
// local vertex indices: one read of the model to count, one to fill, then the vertices.
//   [front | triangles | vertices | free ... | (vertex ids) | vertex pairs | edge ids]
// The band keeps no Edge3 of its own: its edges are the hidden-line run's (SolidSink::begin).
// Its vertex pairs stand just past the run's buffer: only the run's topology reads them, so the
// sink's tail takes their bytes once the run has begun (SolidSink::spare).
Status BandConductor::gather_solid(Attempt& a) {
  const SolidSource& src = solid_;
  const int64_t lo = a.y0, hi = a.y1 - 1;
  auto read_vertex = [&](uint32_t v, Point3* p) { return solid_vertex(v, p); };
  uint32_t m = 0, nt = 0;
  uint32_t* pairs = nullptr;
  Triangle* tris = nullptr;
  uint32_t* vids = nullptr;
  for (int pass = 0; pass < 2; ++pass) {
    uint32_t k = 0;
    for (uint32_t i = 0; i < src.n_edges; ++i) {
      uint32_t v0, v1;
      Point3 p0, p1;
      Status s = src.edge(src.ctx, i, &v0, &v1);
      if (ok(s)) s = read_vertex(v0, &p0);
      if (ok(s)) s = read_vertex(v1, &p1);
      if (!ok(s)) return s;
      if (!edge_meets_rows(Edge3{p0, p1}, lo, hi)) continue;
      if (pass == 1) {
        a.g.ids_end[-1 - int64_t{k}] = stream_ids_ != nullptr ? stream_ids_[i] : i;
        pairs[2 * k] = v0;
        pairs[2 * k + 1] = v1;
      }
      ++k;
    }
    if (pass == 0) m = k;
    k = 0;
    auto read_triangle = [&](uint32_t i, Triangle* t, bool* meets) {
      Point3 p[3];
      Status s = src.triangle(src.ctx, i, t);
      for (int c = 0; c < 3 && ok(s); ++c) s = read_vertex(t->v[c], &p[c]);
      *meets = triangle_meets_rows(p[0], p[1], p[2], lo, hi + 1);  // and the row above it
      return s;
    };
    const Status ts =
        for_band_triangles(src.n_triangles, spec_.hatch, read_triangle, [&](uint32_t, Triangle t) {
          if (pass == 1) tris[k] = t;
          ++k;
        });
    if (!ok(ts)) return ts;
    if (pass == 0) nt = k;
    stats_.edge_reads += src.n_edges;
    if (pass == 1) break;
    // The layout, now that the counts are known: the vertex ids (every end and corner) are
    // scratch below the vertex pairs, dead once the indices are local.
    uint8_t* base = arena_ + front_bytes();
    uint8_t* top = arena_ + arena_bytes_;
    const size_t front = carve_round(size_t{nt} * sizeof(Triangle));
    const size_t ids = carve_round((size_t{2} * m + size_t{3} * nt) * sizeof(uint32_t));
    const size_t back =
        carve_round(size_t{m} * 2 * sizeof(uint32_t)) + carve_round(size_t{m} * sizeof(uint32_t));
    a.g.n = m;
    if (top < base || front + ids + back + 64 > size_t(top - base)) {
      a.need = front_bytes() + front + ids + back + 64;
      return Status::kWorkspaceTooSmall;
    }
    a.g.edges = nullptr;  // the hidden-line run's, once it has them
    a.g.ids_end = reinterpret_cast<uint32_t*>(top);
    a.g.free_lo = base;
    a.g.free_hi = top - back;
    pairs = reinterpret_cast<uint32_t*>(a.g.free_hi);
    tris = reinterpret_cast<Triangle*>(base);
    vids = reinterpret_cast<uint32_t*>(a.g.free_hi - ids);
  }
  a.in.edge_pairs = pairs;
  a.in.n_edges = m;
  a.in.triangles = tris;
  a.in.n_triangles = nt;
  return gather_vertices(a, pairs, tris, vids);
}

// The vertices the band's edges and triangles use, sorted and once each, read right after its
// triangles (the ids at `vids` lie above them); then its local indices.
Status BandConductor::gather_vertices(Attempt& a, uint32_t* pairs, Triangle* tris, uint32_t* vids) {
  const uint32_t m = a.in.n_edges, nt = a.in.n_triangles;
  uint32_t nv = 0;
  for (uint32_t k = 0; k < 2 * m; ++k) vids[nv++] = pairs[k];
  for (uint32_t k = 0; k < nt; ++k)
    for (int c = 0; c < 3; ++c) vids[nv++] = tris[k].v[c];
  sort_in_place(vids, nv, [](uint32_t x, uint32_t y) { return x < y; });
  uint32_t unique = 0;
  for (uint32_t k = 0; k < nv; ++k)
    if (unique == 0 || vids[unique - 1] != vids[k]) vids[unique++] = vids[k];
  Point3* verts = reinterpret_cast<Point3*>(reinterpret_cast<uint8_t*>(tris) +
                                            carve_round(size_t{nt} * sizeof(Triangle)));
  uint8_t* verts_end =
      reinterpret_cast<uint8_t*>(verts) + carve_round(size_t{unique} * sizeof(Point3));
  if (verts_end + 64 > reinterpret_cast<uint8_t*>(vids)) {  // the band's bytes so far, and 64
    a.need = size_t(verts_end - arena_) +
             size_t(arena_ + arena_bytes_ - reinterpret_cast<uint8_t*>(vids)) + 64;
    return Status::kWorkspaceTooSmall;
  }
  for (uint32_t k = 0; k < unique; ++k) {
    const Status s = solid_vertex(vids[k], &verts[k]);
    if (!ok(s)) return s;
  }
  for (uint32_t k = 0; k < 2 * m; ++k) pairs[k] = local_vertex(vids, unique, pairs[k]);
  for (uint32_t k = 0; k < nt; ++k)
    for (int c = 0; c < 3; ++c) tris[k].v[c] = local_vertex(vids, unique, tris[k].v[c]);
  a.in.vertices = verts;
  a.in.n_vertices = unique;
  a.after = verts_end;
  a.gathered = size_t(verts_end - arena_) +
               size_t(arena_ + arena_bytes_ - reinterpret_cast<uint8_t*>(vids)) + 64;
  return Status::kOk;
}

// The band's hidden lines, as a sized stage in the free middle of the arena: a run short of
// records or incidences is run again with the counts it reported; one short of bytes means the
// band does not fit.
Status BandConductor::hide_band(Attempt& a) {
  for (uint32_t k = 0; k < a.in.n_edges; ++k) {
    const Edge3 e{a.in.vertices[a.in.edge_pairs[2 * k]], a.in.vertices[a.in.edge_pairs[2 * k + 1]]};
    if (edge_row_min(e) < a.y1 && edge_row_max(e) >= a.y1) ++a.carry_capacity;
  }
  a.carry_in = reinterpret_cast<const Carry*>(arena_);
  a.carry_runs_in = carry_runs(arena_, n_carry_);
  a.n_carry_in = n_carry_;
  SolidSink sink{&a, &spec_.style};
  HiddenReport report;
  HiddenLinesStage stage{
      &a.in, HiddenParams{},
      HiddenSink{&SolidSink::begin, &SolidSink::piece, &SolidSink::outline, &sink}, &report, 0};
  stage.params.method = HiddenMethod::kFallback;
  stage.params.cut = spec_.cut;
  stage.params.cut.rows = true;  // cuts outside the band's rows would only be clipped away
  stage.params.cut.row_lo = int32_t(a.y0);
  stage.params.cut.row_hi = int32_t(a.y1);
  stage.params.band = true;
  stage.params.outline = spec_.outline;
  stage.params.intersections = spec_.intersections;
  stage.params.hatch = spec_.hatch;
  stage.params.hatch_params = spec_.hatch_params;
  stage.params.hatch_params.turned = turned_;  // the page's lattice, in the turned frame
  stage.params.closed = closed_;
  stage.params.band_y0 = int32_t(a.y0);
  stage.params.band_y1 = int32_t(a.y1);
  // The vertex pairs stand right past the run's buffer, the edge ids above them.
  uint8_t* ids = reinterpret_cast<uint8_t*>(a.g.ids_end) - carve_round(size_t{a.g.n} * 4);
  sink.spare = a.g.free_hi;
  sink.spare_bytes = size_t(ids - a.g.free_hi);
  BandRun fresh{&stage, &sink, a.carry_capacity};
  StageNeeds needs;
  // The first guess: the last band's records and a quarter more (a short guess costs a run).
  needs.crossings = solid_crossings_ + solid_crossings_ / 4 + 16;
  needs.incidences = 16;
  uint8_t* space = a.after;
  const size_t fixed = size_t(space - arena_) + size_t(arena_ + arena_bytes_ - a.g.free_hi);
  FixedMemory memory{space, size_t(a.g.free_hi - space)};
  const uint64_t t0 = now();
  ++stats_.draw_runs;
  Status s = run_sized(fresh, memory.memory(), &needs);
  if (ok(s)) s = sink.finish();
  stats_.draw_ticks += now() - t0;
  if (is_shortfall(s) || does_not_fit(s)) {  // records, incidences, bytes or strokes: too big
    const size_t more = memory.bytes + memory.bytes / 2;
    a.need = fixed + (needs.bytes > more ? needs.bytes : more);
    return Status::kWorkspaceTooSmall;
  }
  if (!ok(s)) return s;
  if (a.carry_used != n_carry_) return Status::kBandCarryLost;
  solid_crossings_ = need_count(report.cut.crossings + report.cut.near_misses);
  stats_.records += report.cut.crossings;
  // The next band's height follows the bytes the band keeps (note_used); its peak counts every
  // byte it touched: the run's stages at their highest (transient scratch included) with the
  // vertex pairs and the edge ids, or the sink's tail at its fullest (its strokes from the
  // start and its stacks from the end at one moment; the pairs' bytes are the tail's by then)
  // with the edge ids; or the gathering's, the vertex ids below the pairs.
  const size_t top = size_t(arena_ + arena_bytes_ - ids);
  const size_t run = size_t(space - arena_) + report.bytes_used + size_t(ids - a.g.free_hi);
  const size_t tail = sink.base != nullptr ? size_t(sink.base - arena_) + sink.high : 0;
  note_used(size_t(reinterpret_cast<uint8_t*>(a.pieces + a.n_pieces) - arena_) + top);
  const size_t most = (run > tail ? run : tail) + top;
  note_peak(most > a.gathered ? most : a.gathered);
  return Status::kOk;
}

}  // namespace haloplot
