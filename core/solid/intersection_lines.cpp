#include "haloplot/solid/intersection_lines.h"

#include "memory/carve.h"
#include "solid/face_crossing.h"

namespace haloplot {
namespace {

// A 32-bit chip runs no parts (no runner there): their code is not built into its image.
constexpr bool kRunsParts = UINTPTR_MAX > 0xffffffffu;

bool shares_corner(const Triangle& s, const Triangle& t) {
  for (uint32_t u : s.v)
    if (u == t.v[0] || u == t.v[1] || u == t.v[2]) return true;
  return false;
}

// Every pair of cell c's faces asked the exact question, in the one order the pieces are
// numbered in; on_crossing(i, j, segment) for each pair that crosses (after it is counted).
template <typename OnCrossing>
Status cell_pairs(const Topology& topo, const uint8_t* front, const FaceGrid& fg, uint32_t c,
                  IntersectionStats& st, OnCrossing on_crossing) {
  const Grid& g = fg.grid;
  auto box = [&](uint32_t t) {
    const uint32_t* v = topo.triangles[t].v;
    return box_of(topo.vertices[v[0]], topo.vertices[v[1]], topo.vertices[v[2]]);
  };
  auto asked = [&](uint32_t t) { return front == nullptr || front[t] != 0; };
  // One pair of the cell's faces: the exact question if their boxes overlap in depth too and
  // this cell holds their boxes' common lower-left corner (so each pair is asked once).
  auto pair = [&](uint32_t i, const FaceBox& bi, uint32_t j, const FaceBox& bj) {
    if (!overlap_on_paper(bi, bj) || bi.z1 < bj.z0 || bj.z1 < bi.z0) return Status::kOk;
    if (g.cell_of(max_i32(bi.x0, bj.x0), max_i32(bi.y0, bj.y0)) != c) return Status::kOk;
    const Triangle &ti = topo.triangles[i], &tj = topo.triangles[j];
    if (shares_corner(ti, tj)) return Status::kOk;
    const Point3 p[3] = {topo.vertices[ti.v[0]], topo.vertices[ti.v[1]], topo.vertices[ti.v[2]]};
    const Point3 q[3] = {topo.vertices[tj.v[0]], topo.vertices[tj.v[1]], topo.vertices[tj.v[2]]};
    ++st.pairs;
    Edge3 s;
    if (!face_crossing(p, q, &s)) return Status::kOk;
    ++st.segments;
    return on_crossing(i, j, s);
  };
  const uint32_t* first = fg.faces + fg.first[c];
  const uint32_t* last = fg.faces + fg.first[c + 1];
  // The cell's asked faces with their boxes, each box found once instead of once a pair;
  // past kCached of them (rare: about one face per cell) the rest find theirs as they go.
  constexpr uint32_t kCached = 24;
  uint32_t ids[kCached];
  FaceBox boxes[kCached];
  uint32_t m = 0;
  const uint32_t* spill = last;
  for (const uint32_t* f = first; f != last && spill == last; ++f) {
    if (!asked(*f)) continue;
    if (m == kCached) {
      spill = f;
    } else {
      ids[m] = *f;
      boxes[m++] = box(*f);
    }
  }
  Status s = Status::kOk;
  for (uint32_t i = 0; i < m && ok(s); ++i)
    for (uint32_t j = i + 1; j < m && ok(s); ++j) s = pair(ids[i], boxes[i], ids[j], boxes[j]);
  for (const uint32_t* f = spill; f != last && ok(s); ++f) {
    if (!asked(*f)) continue;
    const FaceBox bf = box(*f);
    for (uint32_t i = 0; i < m && ok(s); ++i) s = pair(ids[i], boxes[i], *f, bf);
    for (const uint32_t* h = f + 1; h != last && ok(s); ++h)
      if (asked(*h)) s = pair(*f, bf, *h, box(*h));
  }
  return s;
}

// The lines of cells [lo, hi) straight to the sink, numbered on from *index.
Status direct_cells(const Topology& topo, const uint8_t* front, const FaceGrid& fg, uint32_t lo,
                    uint32_t hi, LineSink sink, LineRows rows, uint32_t* index,
                    IntersectionStats& st) {
  for (uint32_t c = lo; c < hi; ++c) {
    const Status s = cell_pairs(topo, front, fg, c, st, [&](uint32_t i, uint32_t j, Edge3 seg) {
      const SegmentPass pass{topo, front, fg, &st, seg, {i, j}};
      return pass.run((*index)++, sink, rows);
    });
    if (!ok(s)) return s;
  }
  return Status::kOk;
}

// In parts (LineParts): part k's cells are [cell_lo, cell_hi), split where the cells' face
// lists reach k / n of their total (the pairs a cell asks grow with its list). A part keeps
// its segments (their faces and ends) from the front of its share of the buffer and their
// pieces from the back; a segment or piece that does not fit makes it drop the cell it is in
// and stop there (stop_cell): the cells from there on are drawn on the calling thread, after
// what the part kept, in their order.
struct FoundSegment {
  Edge3 s;
  uint32_t face[2];
  uint32_t pieces;
};
struct FoundPiece {
  int64_t t0, t1;
  int32_t q;
};

struct PartOut {
  uint8_t* lo;  // the share: segments up from lo, pieces down from hi
  uint8_t* hi;
  uint32_t cell_lo, cell_hi, stop_cell;
  uint32_t n_segments, n_pieces;
  IntersectionStats st;

  FoundSegment* segment(uint32_t k) const { return reinterpret_cast<FoundSegment*>(lo) + k; }
  FoundPiece* piece(uint32_t k) const { return reinterpret_cast<FoundPiece*>(hi) - (k + 1); }
  size_t free_bytes() const {
    return size_t(hi - lo) - n_segments * sizeof(FoundSegment) - n_pieces * sizeof(FoundPiece);
  }
};

Status keep_piece(void* context, const LinePiece& p) {
  PartOut* out = static_cast<PartOut*>(context);
  if (out->free_bytes() < sizeof(FoundPiece)) return Status::kWorkspaceTooSmall;
  *out->piece(out->n_pieces++) = FoundPiece{p.t0, p.t1, p.q};
  ++out->segment(out->n_segments - 1)->pieces;
  return Status::kOk;
}

struct PartRun {
  const Topology* topo;
  const uint8_t* front;
  const FaceGrid* fg;
  LineRows rows;
  PartOut* out;
};

void run_part(const PartRun* run, uint32_t k) {
  const PartRun& r = *run;
  PartOut& out = r.out[k];
  for (uint32_t c = out.cell_lo; c < out.cell_hi; ++c) {
    const uint32_t n_segments = out.n_segments, n_pieces = out.n_pieces;
    const IntersectionStats st = out.st;
    const Status s =
        cell_pairs(*r.topo, r.front, *r.fg, c, out.st, [&](uint32_t i, uint32_t j, Edge3 seg) {
          if (out.free_bytes() < sizeof(FoundSegment)) return Status::kWorkspaceTooSmall;
          *out.segment(out.n_segments++) = FoundSegment{seg, {i, j}, 0};
          const SegmentPass pass{*r.topo, r.front, *r.fg, &out.st, seg, {i, j}};
          return pass.run(out.n_segments - 1, LineSink{&keep_piece, &out}, r.rows);
        });
    if (!ok(s)) {  // full (the only status a kept piece gives): this cell on, on the caller
      out.n_segments = n_segments;
      out.n_pieces = n_pieces;
      out.st = st;
      out.stop_cell = c;
      return;
    }
  }
}

// Part k's kept pieces to the sink, numbered on from *index, then its cells past stop_cell.
Status hand_on(const PartRun& r, const PartOut& out, LineSink sink, uint32_t* index,
               IntersectionStats& st) {
  uint32_t p = 0;
  for (uint32_t k = 0; k < out.n_segments; ++k, ++*index) {
    const FoundSegment& f = *out.segment(k);
    for (uint32_t e = 0; e < f.pieces; ++e, ++p) {
      const FoundPiece& x = *out.piece(p);
      const Status s =
          sink.emit(sink.context,
                    LinePiece{{*index, x.t0, x.t1}, {f.face[0], f.face[1]}, &f.s, x.q, x.q != 0});
      if (!ok(s)) return s;
    }
  }
  return direct_cells(*r.topo, r.front, *r.fg, out.stop_cell, out.cell_hi, sink, r.rows, index, st);
}

void add(IntersectionStats& to, const IntersectionStats& p) {
  to.pairs += p.pairs;
  to.segments += p.segments;
  to.pieces += p.pieces;
  to.tests += p.tests;
  to.face_tests += p.face_tests;
}

// Each worker (one a thread of the runner) draws the parts w, w + workers, ...: parts a few
// times as many as the workers, so where the pairs crowd (the cells of the far side of a
// model, seen through its near side) every worker gets some of them.
struct Workers {
  const PartRun* r;
  uint32_t n_parts, n_workers;
};
void run_worker(void* arg, uint32_t w) {
  const Workers& ws = *static_cast<const Workers*>(arg);
  for (uint32_t k = w; k < ws.n_parts; k += ws.n_workers) run_part(ws.r, k);
}
constexpr uint32_t kPartsPerWorker = 4;

// How many workers: the runner's count, at most kMaxLineParts / kPartsPerWorker, fewer where
// one would get fewer face entries than Parts::min_work; one without a runner, or without a
// buffer that gives each part a share to keep a few pieces in.
uint32_t line_workers(const FaceGrid& fg, const LineParts& lp, size_t* share) {
  if (lp.parts == nullptr || lp.buffer == nullptr) return 1;
  uint32_t n = lp.parts->split();
  if (n > kMaxLineParts / kPartsPerWorker) n = kMaxLineParts / kPartsPerWorker;
  const uint64_t entries = fg.first[fg.grid.cells()];
  const uint64_t worth = lp.parts->min_work == 0 ? n : entries / lp.parts->min_work;
  if (worth < n) n = worth < 1 ? 1 : uint32_t(worth);
  const size_t books = carve_round(sizeof(PartOut) * kMaxLineParts);
  if (n < 2 || lp.bytes < books) return 1;
  *share = (lp.bytes - books) / (n * kPartsPerWorker) & ~size_t{7};
  constexpr size_t kLeast = 4 * (sizeof(FoundSegment) + sizeof(FoundPiece));
  return *share < kLeast ? 1 : n;
}

Status draw_in_parts(const Topology& topo, const uint8_t* front, const FaceGrid& fg, LineSink sink,
                     IntersectionStats& st, LineRows rows, const LineParts& lp, uint32_t workers,
                     size_t share) {
  const uint32_t n = workers * kPartsPerWorker;
  uint8_t* at = static_cast<uint8_t*>(lp.buffer);
  PartOut* out = reinterpret_cast<PartOut*>(at);
  at += carve_round(sizeof(PartOut) * kMaxLineParts);
  const uint32_t cells = fg.grid.cells();
  const uint64_t entries = fg.first[cells];
  uint32_t c = 0;
  for (uint32_t k = 0; k < n; ++k) {
    out[k] = PartOut{at, at + share, c, cells, cells, 0, 0, IntersectionStats{}};
    at += share;
    if (k > 0) out[k - 1].cell_hi = out[k - 1].stop_cell = c;
    const uint64_t until = entries * (k + 1) / n;
    while (c < cells && fg.first[c] < until) ++c;
  }
  PartRun r{&topo, front, &fg, rows, out};
  Workers ws{&r, n, workers};
  run_parts(*lp.parts, workers, &run_worker, &ws);
  uint32_t index = 0;
  Status s = Status::kOk;
  for (uint32_t k = 0; k < n && ok(s); ++k) {
    add(st, out[k].st);
    if (out[k].stop_cell < out[k].cell_hi) ++st.parts_full;
    s = hand_on(r, out[k], sink, &index, st);
  }
  return s;
}

}  // namespace

Status draw_intersections(const Topology& topo, const uint8_t* front, const FaceGrid& fg,
                          LineSink sink, IntersectionStats* stats, LineRows rows, LineParts lp) {
  IntersectionStats st;
  size_t share = 0;
  const uint32_t n = kRunsParts ? line_workers(fg, lp, &share) : 1;
  uint32_t index = 0;
  const Status s = n > 1
                       ? draw_in_parts(topo, front, fg, sink, st, rows, lp, n, share)
                       : direct_cells(topo, front, fg, 0, fg.grid.cells(), sink, rows, &index, st);
  if (stats != nullptr) *stats = st;
  return s;
}

}  // namespace haloplot
