#include "haloplot/solid/hidden_lines.h"

#include "haloplot/solid/incidence.h"
#include "memory/carve.h"
#include "solid/build_parts.h"

namespace haloplot {
namespace {

// The buffer, carved front to back; release() gives back everything after a mark.
struct Arena {
  uint8_t* base = nullptr;
  size_t size = 0, used = 0, high = 0, need = 0;

  Arena(void* buffer, size_t bytes) {
    const uintptr_t p = reinterpret_cast<uintptr_t>(buffer);
    const uintptr_t aligned = (p + 7) & ~uintptr_t{7};
    base = reinterpret_cast<uint8_t*>(aligned);
    size = buffer == nullptr || bytes < aligned - p ? 0 : bytes - (aligned - p);
  }
  uint8_t* take(size_t n) {
    n = carve_round(n);
    if (n > size - used) {
      need = used + n;
      return nullptr;
    }
    uint8_t* p = base + used;
    used += n;
    if (used > high) high = used;
    return p;
  }
};

// An edge's geometry for the sink. A band's run keeps CUT's array of the edges (its sink reads
// them: HiddenSink::begin) and hands on pointers into it, as it always did; any other run gave
// that array back after CUT, and makes each piece's geometry from the topology on the
// emitter's stack (valid during the sink's call, all HiddenPiece::geometry promises).
struct Adapter {
  HiddenSink sink;
  const Edge3* edges;    // a band's; null outside a band once CUT is done
  const Topology* topo;  // the edges' geometry; lines on the faces are numbered after them
};

// The QI's pieces and outlines (never in a band).
Status qi_piece(void* ctx, const QiPiece& p) {
  const Adapter* a = static_cast<const Adapter*>(ctx);
  const Edge3 g = a->topo->edge3(p.edge);
  return a->sink.piece(a->sink.context, HiddenPiece{p, &g, p.q, p.q != 0, true});
}

Status outline_piece(void* ctx, const OutlineSegment& s) {
  const Adapter* a = static_cast<const Adapter*>(ctx);
  if (a->sink.outline == nullptr) return Status::kOk;
  const Edge3 g = a->topo->edge3(s.edge);
  return a->sink.outline(a->sink.context, OutlinePiece{{s, &g, 0, false, true}});
}

// The fallback's, in a band (the array kept).
Status fallback_piece(void* ctx, const FallbackPiece& p) {
  const Adapter* a = static_cast<const Adapter*>(ctx);
  return a->sink.piece(a->sink.context, HiddenPiece{p, a->edges + p.edge, p.q, p.hidden, p.tested});
}

Status fallback_outline(void* ctx, const FallbackPiece& p) {
  const Adapter* a = static_cast<const Adapter*>(ctx);
  if (a->sink.outline == nullptr) return Status::kOk;
  return a->sink.outline(a->sink.context, OutlinePiece{{p, a->edges + p.edge, 0, false, true}});
}

// The fallback's outside a band (the array given back).
Status fallback_piece_made(void* ctx, const FallbackPiece& p) {
  const Adapter* a = static_cast<const Adapter*>(ctx);
  const Edge3 g = a->topo->edge3(p.edge);
  return a->sink.piece(a->sink.context, HiddenPiece{p, &g, p.q, p.hidden, p.tested});
}

Status fallback_outline_made(void* ctx, const FallbackPiece& p) {
  const Adapter* a = static_cast<const Adapter*>(ctx);
  if (a->sink.outline == nullptr) return Status::kOk;
  const Edge3 g = a->topo->edge3(p.edge);
  return a->sink.outline(a->sink.context, OutlinePiece{{p, &g, 0, false, true}});
}

Status line_piece(const Adapter* a, const LinePiece& p, bool hatch) {
  return a->sink.piece(a->sink.context, HiddenPiece{{a->topo->n_edges + p.edge, p.t0, p.t1},
                                                    p.segment,
                                                    p.q,
                                                    p.hidden,
                                                    true,
                                                    {p.face[0], p.face[1]},
                                                    hatch});
}
Status intersection_piece(void* ctx, const LinePiece& p) {
  return line_piece(static_cast<const Adapter*>(ctx), p, false);
}
Status hatch_piece(void* ctx, const LinePiece& p) {
  return line_piece(static_cast<const Adapter*>(ctx), p, true);
}

// Lines on the faces: intersection lines, hatching.
bool draws_lines(const HiddenParams& params) { return params.intersections || params.hatch; }

// A band's faces are those meeting a strip a few rows high, spread along the plot's width: in
// a grid of about one face per cell each reaches over some three cells, most of them never
// asked (only the strip's are). Cells twice as wide list each face about half as often: on the
// hatched 28 x 28 cubes' worst band one row high, 7,888 bytes of grid become 3,720, for some
// 5 to 10 % more time in the band's run (more faces a cell asks). A cell lists every face whose
// box meets it, whatever its size, and each is then tested exactly: the picture is the same.
constexpr uint32_t kBandGridCoarsen = 2;

// The fallback's face grid when the lines on the faces share it (and always in a band, for its
// coarser cells), carved before the sink is given the tail (the QI method's own grid serves
// them otherwise).
bool shares_grid(const HiddenParams& params) { return draws_lines(params) || params.band; }
bool carve_shared_grid(const Topology& topo, const HiddenParams& params, Arena* arena, FaceGrid* fg,
                       HiddenReport* r) {
  if (!shares_grid(params)) return true;
  const uint32_t coarsen = params.band ? kBandGridCoarsen : 1;
  r->bytes_intersections = face_grid_bytes(topo, coarsen);
  uint8_t* mem = arena->take(r->bytes_intersections);
  return mem != nullptr &&
         build_face_grid(topo, mem, r->bytes_intersections, fg, coarsen) == Status::kOk;
}

Status short_of(const Arena& a, HiddenReport* r) {
  r->bytes_needed = a.need;
  r->bytes_used = a.high;
  return Status::kWorkspaceTooSmall;
}

// CUT over every edge; its scratch is given back afterwards. The scratch comes first and the
// CUTSET above it; once CUT is done the CUTSET (its index and the records it stored) moves
// down onto the scratch, and the rest of its capacity is free again. The next stages then
// reuse the pages CUT wrote instead of new ones past a capacity that is mostly a guess (the
// host's first guess on a 1M-triangle torus is six times the records stored). The high-water
// mark is the same as with the CUTSET first. Only pairs with a marked edge are tested (null:
// every pair). With `drop_edges` the edges are the last block carved before CUT, and the
// CUTSET moves down onto them instead (the run reads them no more). kWorkspaceTooSmall: the
// arena is short (arena->need says how much it needed).
Status cut_step(const Edge3* edges, uint32_t n, const HiddenParams& params, const uint32_t* marked,
                bool drop_edges, Arena* arena, CutSet* cutset, HiddenReport* r) {
  CutParams cp = params.cut;
  cp.marked = marked;
  // With few edges marked, few pairs get past the marks to read geometry: cell lists of indices
  // (4 bytes a pair, not a copy of the endpoints) then cost little time and save CUT's largest
  // block (on the 1M-triangle torus some 60 MB, the whole plot's peak).
  if (marked != nullptr) cp.compact_cells = false;
  CutPlan plan;
  Status s = plan_cut(edges, n, cp, &plan);
  if (s != Status::kOk) return s;
  const size_t cutset_size = cutset_bytes(n, params.crossing_capacity);
  r->bytes_cut = cutset_size + plan.scratch_bytes;
  const size_t mark = arena->used;
  uint8_t* cut_scratch = arena->take(plan.scratch_bytes);
  uint8_t* cutset_mem = cut_scratch == nullptr ? nullptr : arena->take(cutset_size);
  if (cutset_mem == nullptr) {
    arena->used = mark;
    arena->need = mark + carve_round(plan.scratch_bytes) + carve_round(cutset_size);
    return Status::kWorkspaceTooSmall;
  }
  s = run_cut(plan, edges, cut_scratch, plan.scratch_bytes, cutset_mem, cutset_size, cutset,
              &r->cut);
  arena->used = drop_edges ? size_t(reinterpret_cast<const uint8_t*>(edges) - arena->base) : mark;
  if (s != Status::kOk) return s;
  // Down onto the scratch (or the edges), in order (the destination lies below the source).
  const size_t words = (cutset_bytes(n, cutset->n_crossings) + 3) / 4;
  uint32_t* to = reinterpret_cast<uint32_t*>(arena->take(words * 4));
  const uint32_t* from = reinterpret_cast<const uint32_t*>(cutset_mem);
  for (size_t i = 0; i < words; ++i) to[i] = from[i];
  cutset->first = to;
  cutset->crossings = reinterpret_cast<const Crossing*>(to + (size_t{n} + 1));
  return Status::kOk;
}

// Copies n items down to `at` (at most where they are: forward is safe); returns their new
// place and moves `at` past them.
template <typename T>
T* move_down(uint8_t** at, T* from, size_t n) {
  T* to = reinterpret_cast<T*>(*at);
  for (size_t i = 0; i < n; ++i) {
    const T x = from[i];
    to[i] = x;
  }
  *at += carve_round(n * sizeof(T));
  return to;
}

// The incidences' arrays packed down from `at` in their order, each cut to what it holds: the
// records' capacity is a first guess (one per vertex) and mostly unwritten, and the stages
// after them would otherwise start on new pages beyond it. Returns their end.
uint8_t* pack_incidences(Incidences* inc, const Topology& topo, uint8_t* at) {
  inc->by_edge = move_down(&at, inc->by_edge, inc->n);
  inc->edge_first = move_down(&at, inc->edge_first, size_t{topo.n_edges} + 1);
  if (inc->by_vertex == nullptr) return at;
  inc->by_vertex = move_down(&at, inc->by_vertex, inc->n);
  inc->vertex_first = move_down(&at, inc->vertex_first, size_t{topo.n_vertices} + 1);
  inc->same_next = move_down(&at, inc->same_next, topo.n_vertices);
  return at;
}

// The bytes handed to the topology's build (TopologyOptions::stars false): at most what it
// can need, since its scratch lies at their top and a host's pages stay resident once written.
// Without its stars it keeps only the edges (at most one a drawn edge and one a triangle
// side); topology_bytes() also counts the stars, which would put the scratch above all the
// later stages reach (on the 1M-triangle torus some 44 MB higher, 16 MB of the plot's peak). A
// band's run keeps the bound its conductor sized it with.
size_t topology_build_bytes(const SolidInput& in, bool band) {
  const size_t all = topology_bytes(in);
  if (band) return all;
  const size_t edges = size_t{in.n_edges} + 3 * size_t{in.n_triangles};
  const size_t bound = carve_round(edges * sizeof(SolidEdge)) + topology_scratch_bytes(in) + 8;
  return bound < all ? bound : all;
}

// The marks (mark_crossing_edges) of words [w0, w1): edges 32 w0 to 32 w1.
void mark_words(const Topology& topo, uint32_t* marked, uint32_t w0, uint32_t w1) {
  const uint32_t end = w1 * 32 < topo.n_edges ? w1 * 32 : topo.n_edges;
  for (uint32_t w = w0; w < w1; ++w) marked[w] = 0;
  for (uint32_t e = w0 * 32; e < end; ++e) {
    const SolidEdge& se = topo.edges[e];
    if (!se.regular || is_fold(se.cls) || paper_jump(topo, e) != 0)
      marked[e >> 5] |= uint32_t{1} << (e & 31);
  }
}

// Every edge as CUT sees it, and its mark (marked: null in a band), in parts of whole mark
// words: most of the time is the kernel's first touch of the edges' fresh pages (36 MB on the
// 1M-triangle torus), which threads share.
struct EdgeFill {
  const Topology* topo;
  Edge3* edges;
  uint32_t* marked;
  uint32_t words, n_parts;
};
void fill_edge_part(void* arg, uint32_t k) {
  const EdgeFill& f = *static_cast<const EdgeFill*>(arg);
  const uint32_t w0 = uint32_t(uint64_t{f.words} * k / f.n_parts);
  const uint32_t w1 = uint32_t(uint64_t{f.words} * (k + 1) / f.n_parts);
  const uint32_t n = f.topo->n_edges, e1 = w1 * 32 < n ? w1 * 32 : n;
  for (uint32_t e = w0 * 32; e < e1; ++e) f.edges[e] = f.topo->edge3(e);
  if (f.marked != nullptr) mark_words(*f.topo, f.marked, w0, w1);
}
void fill_edges(const Topology& topo, Edge3* edges, uint32_t* marked, const Parts* parts) {
  EdgeFill f{&topo, edges, marked, (topo.n_edges + 31) / 32, 1};
  // An edge costs about as much as a pair test's fraction: parts of min_work edges at least,
  // each of whole mark words.
  f.n_parts = build_part_count(parts, topo.n_edges);
  if (f.n_parts > f.words) f.n_parts = f.words < 1 ? 1 : f.words;
  if (f.n_parts == 1) return fill_edge_part(&f, 0);
  run_parts(*parts, f.n_parts, &fill_edge_part, &f);
}

// One run's state, shared by its steps: the arena, the report so far, and what each step built
// for the next. Every step that fails writes the report before it returns.
struct HiddenRun {
  const SolidInput& in;
  const HiddenParams& params;
  HiddenReport* report;
  Arena arena;
  HiddenReport r;
  Topology topo;
  uint8_t* front = nullptr;
  Edge3* edges = nullptr;      // every edge as CUT reads it; given back after CUT outside a band
  uint32_t* marked = nullptr;  // the edges CUT pairs with every other (mark_crossing_edges)
  CutSet cutset;
  Incidences inc;
  FaceGrid crossing_grid;
  PartsBuffer end_parts;  // the QI pieces' and the intersection lines' parts, one after another
  Adapter adapter;  // holds the run's sink (one copy: this frame is on a chip's deepest stack)

  HiddenRun(const SolidInput& input, const HiddenParams& p, void* buffer, size_t bytes,
            HiddenSink s, HiddenReport* out)
      : in(input), params(p), report(out), arena(buffer, bytes), adapter{s, nullptr, nullptr} {}

  Status fail(Status s) { return *report = r, s; }
  Status out_of_room() { return *report = r, short_of(arena, report); }
  Status finish(Status s) {
    r.bytes_used = arena.high;
    *report = r;
    return s;
  }
  Status build_edges();
  Status cut_and_touches();
  Status add_stars();
  void carve_end_parts(bool pierces);
  Status lines(const uint8_t* hiding_front);
  Status qi_method(bool* gave_up);
  Status fallback_method(bool manifold);
};

// Topology, classes, and every edge as CUT sees it. The build takes what it needs of the free
// arena and keeps its first kept_bytes. Outside a band the edges come last, just below CUT's
// scratch, so that CUT gives them back with it: only CUT reads them (the sink's geometry comes
// from the topology), and on the 1M-triangle torus they are 36 MB the QI would otherwise hold
// on to (its peak: the stars and the QI's own blocks then take their pages).
Status HiddenRun::build_edges() {
  TopologyOptions to;
  to.stars = false;  // built after CUT (add_stars), which does not read them
  to.parts = params.band ? nullptr : params.cut.parts;  // a band's build stays one part
  if (params.band) {  // the band's fallback reads no stars, and no side beyond its rows
    to.rows = true;
    to.row_lo = params.band_y0;
    to.row_hi = params.band_y1 - 1;
  }
  // At most the bytes the build can need: its scratch, at the top of what it is given, then
  // lies on pages the next stages write again (a growing buffer is far larger than the build).
  const size_t free = arena.size - arena.used, most = topology_build_bytes(in, params.band);
  const Status s =
      build_topology(in, arena.base + arena.used, most < free ? most : free, &topo, to);
  if (s == Status::kWorkspaceTooSmall) {
    arena.need = arena.used + topology_bytes(in);
    return out_of_room();
  }
  if (s != Status::kOk) return fail(s);
  if (params.band) drop_flat_diagonals(&topo, in.facing);  // CUT need not see them
  r.bytes_topology = topo.kept_bytes;
  arena.take(topo.kept_bytes);
  const size_t build_high = arena.used + topo.scratch_bytes;
  if (arena.high < build_high && build_high <= arena.size) arena.high = build_high;
  r.check = topo.check;
  r.n_drawn = topo.n_drawn;
  r.n_edges = topo.n_edges;
  const size_t edge_bytes = size_t{topo.n_edges} * sizeof(Edge3);
  front = arena.take(topo.n_triangles);
  if (params.band) edges = reinterpret_cast<Edge3*>(arena.take(edge_bytes));
  if (front == nullptr || (params.band && edges == nullptr)) return out_of_room();
  r.classes = classify(&topo, front, in.facing);
  // A band's CUT pairs every edge, as it always did: its arena stays as the conductor sized it.
  if (!params.band) {
    marked = reinterpret_cast<uint32_t*>(arena.take((size_t{topo.n_edges} + 31) / 32 * 4));
    edges = reinterpret_cast<Edge3*>(arena.take(edge_bytes));
    if (marked == nullptr || edges == nullptr) return out_of_room();
  }
  fill_edges(topo, edges, marked, params.cut.parts);
  adapter.edges = edges;
  adapter.topo = &topo;
  return Status::kOk;
}

// CUT, then the singular touches CUT leaves out: every place an edge's visibility may change.
Status HiddenRun::cut_and_touches() {
  const bool drop_edges = !params.band;  // a band's sink reads them (HiddenSink::begin)
  Status s = cut_step(edges, topo.n_edges, params, marked, drop_edges, &arena, &cutset, &r);
  if (s == Status::kWorkspaceTooSmall) return out_of_room();
  if (s != Status::kOk) return fail(s);
  if (drop_edges) edges = nullptr, adapter.edges = nullptr;
  // A band's fallback uses no V.C. table: it needs the incidences by edge only.
  const bool by_vertex = !params.band;
  r.bytes_incidence = incidence_bytes(topo, params.incidence_capacity, by_vertex);
  uint8_t* inc_mem = arena.take(r.bytes_incidence);
  if (inc_mem == nullptr) return out_of_room();
  s = find_incidences(topo, params.incidence_capacity, inc_mem, r.bytes_incidence, &inc,
                      &r.incidences_needed, by_vertex, params.cut.parts);  // CUT's runner
  if (s != Status::kOk) return fail(s);
  // The search's scratch ends the block, and its 8 bytes of alignment slack: both free again;
  // so is the records' capacity beyond the ones found.
  arena.used = size_t(pack_incidences(&inc, topo, inc_mem) - arena.base);
  r.incidences = inc.n;
  r.coincident_vertices = inc.coincident_vertices;
  return params.band ? Status::kOk : add_stars();
}

// The vertex stars the QI, the fallback's V.C. table and the outlines read, kept from here on.
Status HiddenRun::add_stars() {
  const size_t bytes = topology_star_bytes(topo);
  uint8_t* mem = arena.take(bytes);
  if (mem == nullptr) return out_of_room();
  const Status s = build_topology_stars(&topo, mem, bytes, params.cut.parts);
  if (s != Status::kOk) return fail(s);
  r.bytes_topology += bytes;
  return Status::kOk;
}

// The end of the stage in parts keeps its pieces in the arena (the QI's emission where the
// walks stop at pierces, solid/qi.h, then the intersection lines, solid/intersection_lines.h,
// in the same buffer), carved before the sink is given the tail, and only when the caller asks
// (HiddenParams::end_parts_bytes, the host tool: a controller's tail stays as it was) with a
// runner that splits. Its room is what lies below the high-water mark the run has reached
// (CUT's scratch, written once already, so the run's peak stays), at least kLeast (a fresh
// high-water mark by at most that), at most params.end_parts_bytes; a part that fills its
// share leaves the rest of its work to the calling thread, so the size costs time, never a
// piece.
void HiddenRun::carve_end_parts(bool pierces) {
  const Parts* parts = params.cut.parts;
  if (!kRunsParts || !(params.intersections || pierces) || parts == nullptr || parts->split() < 2 ||
      params.band || params.end_parts_bytes == 0)
    return;
  constexpr size_t kLeast = size_t{64} << 10;
  size_t bytes = arena.high - arena.used;
  if (bytes < kLeast) bytes = kLeast;
  if (bytes > params.end_parts_bytes) bytes = params.end_parts_bytes;
  if (bytes > arena.size - arena.used) bytes = arena.size - arena.used;
  bytes &= ~size_t{7};
  uint8_t* mem = arena.take(bytes);
  if (mem != nullptr) end_parts = PartsBuffer{parts, mem, bytes};
}

// The lines on the faces, after the edges: intersection lines, then hatching.
Status HiddenRun::lines(const uint8_t* hiding_front) {
  const LineRows rows{params.band, params.band_y0, params.band_y1};
  Status ls = Status::kOk;
  if (params.intersections)
    ls = draw_intersections(topo, hiding_front, crossing_grid,
                            LineSink{&intersection_piece, &adapter}, &r.intersections, rows,
                            end_parts);
  if (ls == Status::kOk && params.hatch)
    ls = draw_hatch_lines(topo, hiding_front, crossing_grid, params.hatch_params,
                          uint32_t(r.intersections.segments), LineSink{&hatch_piece, &adapter},
                          &r.hatch, rows);
  return ls;
}

// The QI method. *gave_up (the report not yet written) when its walk found conflicts the
// fallback must settle instead; its memory is given back then.
Status HiddenRun::qi_method(bool* gave_up) {
  const size_t before_method = arena.used;
  r.bytes_qi = qi_bytes(topo, params.qi_part_vertices);
  uint8_t* qi_mem = arena.take(r.bytes_qi);
  if (qi_mem == nullptr) return out_of_room();
  QiState state;
  const QiSplit split{params.qi_part_vertices, params.cut.parts};  // CUT's runner serves it too
  Status s =
      propagate_qi(topo, front, cutset, inc, qi_mem, r.bytes_qi, &state, &r.qi, false, split);
  if (s != Status::kOk) return fail(s);
  // Where a sliver folds over on paper, the model's facing disagrees with the geometry the
  // QI walks and it finds conflicts: once more with the facing the geometry shows, before
  // giving up the QI (a diagonal may then be drawn as contour; the picture stays right).
  // (Counting both sides of every face, the facing plays no part in the walk.)
  if (params.method == HiddenMethod::kAuto && r.qi.conflicts > 0 && in.facing != nullptr &&
      !state.two_sided) {
    r.projected_facing = true;
    r.classes = classify(&topo, front, nullptr);
    r.qi = QiStats{};
    s = propagate_qi(topo, front, cutset, inc, qi_mem, r.bytes_qi, &state, &r.qi, false, split,
                     QiGrid::kKeep);  // the grid reads no facing
    if (s != Status::kOk) return fail(s);
  }
  // Conflicts left: does the mesh pierce itself? Once more, stopping where edges pass through
  // faces (the dearer walk, for the meshes that need it only).
  if (r.qi.conflicts > 0 && params.method != HiddenMethod::kQiPaperOnly) {
    const uint32_t first = r.qi.conflicts;
    r.qi = QiStats{};
    s = propagate_qi(topo, front, cutset, inc, qi_mem, r.bytes_qi, &state, &r.qi, true, split,
                     QiGrid::kKeep);
    if (s != Status::kOk) return fail(s);
    r.qi.first_conflicts = first;
  }
  if (params.method == HiddenMethod::kAuto && r.qi.conflicts > 0) {
    *gave_up = true;  // the mesh pierces itself: ask the faces directly
    r.reason = FallbackReason::kConflicts;
    arena.used = before_method;
    return Status::kOk;
  }
  uint8_t* outline_mem = nullptr;
  if (params.outline) {
    r.bytes_outline = outline_bytes(topo, cutset, inc);
    outline_mem = arena.take(r.bytes_outline);
    if (outline_mem == nullptr) return out_of_room();
  }
  crossing_grid = state.grid;  // the lines ask the QI's grid of every face
  carve_end_parts(state.pierces);
  if (adapter.sink.begin != nullptr)
    adapter.sink.begin(adapter.sink.context, arena.base + arena.used, arena.size - arena.used,
                       edges);
  r.used_qi = true;
  s = emit_qi_pieces(topo, front, cutset, inc, state, QiSink{&qi_piece, &adapter}, end_parts);
  if (s == Status::kOk) s = lines(state.two_sided ? nullptr : front);
  if (s == Status::kOk && params.outline)
    s = find_outlines(topo, front, cutset, inc, state, outline_mem, r.bytes_outline,
                      OutlineSink{&outline_piece, &adapter}, &r.outline);
  return finish(s);
}

// The fallback: every piece asked against the faces directly.
Status HiddenRun::fallback_method(bool manifold) {
  FallbackParams fp;
  fp.any_facing = !manifold;
  fp.use_classes = fp.use_vc = params.kira && manifold;
  if (params.band) {
    fp.use_vc = false;
    fp.window = true;
    fp.row_lo = params.band_y0;
    fp.row_hi = params.band_y1;
  }
  // Outlines from the fallback: Kira's condition on every visible contour part (no QI to
  // trace circuits with).
  fp.outline = params.outline;
  // With lines on the faces, one face grid of every face serves both: the lines skip back
  // faces themselves when only front faces hide.
  const bool share = shares_grid(params);
  r.bytes_fallback = fallback_bytes(topo, share) +
                     (fp.outline ? fallback_outline_bytes(topo, cutset, fp.any_facing) : 0);
  uint8_t* fb_mem = arena.take(r.bytes_fallback);
  if (fb_mem == nullptr || !carve_shared_grid(topo, params, &arena, &crossing_grid, &r))
    return out_of_room();
  carve_end_parts(false);
  if (adapter.sink.begin != nullptr)
    adapter.sink.begin(adapter.sink.context, arena.base + arena.used, arena.size - arena.used,
                       edges);
  const bool kept = adapter.edges != nullptr;  // a band's
  Status s =
      run_fallback(topo, front, cutset, inc, fp, fb_mem, r.bytes_fallback,
                   kept ? FallbackSink{&fallback_piece, &adapter, &fallback_outline}
                        : FallbackSink{&fallback_piece_made, &adapter, &fallback_outline_made},
                   &r.fallback, share ? &crossing_grid : nullptr);
  if (s == Status::kOk) s = lines(fp.any_facing ? nullptr : front);
  return finish(s);
}

}  // namespace

void mark_crossing_edges(const Topology& topo, uint32_t* marked) {
  mark_words(topo, marked, 0, (topo.n_edges + 31) / 32);
}

Status hidden_lines(const SolidInput& in, const HiddenParams& params, void* buffer, size_t bytes,
                    HiddenSink sink, HiddenReport* report) {
  HiddenRun run(in, params, buffer, bytes, sink, report);
  if (buffer_misaligned(buffer)) return run.fail(Status::kMisalignedBuffer);
  if (params.hatch && (params.hatch_params.spacing < 1 || params.hatch_params.spacing > kCoordMax))
    return run.fail(Status::kBadParameter);  // before any piece is emitted
  Status s = run.build_edges();
  if (s != Status::kOk) return s;
  s = run.cut_and_touches();
  if (s != Status::kOk) return s;

  // The method.
  // QI on any mesh (two-sided where it is not a closed oriented manifold: solid/qi.h); the
  // fallback when asked, in a band, or when the QI meets a mesh that pierces itself.
  const Topology& topo = run.topo;
  const bool manifold = params.band ? params.closed : topo.check.manifold();
  const bool use_qi = !params.band && params.method != HiddenMethod::kFallback;
  if (!use_qi) run.r.reason = params.band ? FallbackReason::kBand : FallbackReason::kAsked;
  if (use_qi) {
    bool gave_up = false;
    s = run.qi_method(&gave_up);
    if (!gave_up) return s;
  }
  return run.fallback_method(manifold);
}

Status HiddenLinesStage::run(const StageNeeds& needs, void* buffer, size_t bytes,
                             StageNeeds* want) {
  HiddenParams p = params;
  p.crossing_capacity = needs.crossings;
  p.incidence_capacity = needs.incidences;
  const Status s = hidden_lines(*in, p, buffer, bytes, sink, report);
  hidden_lines_needs(s, *report, bytes, want);
  return s;
}

void hidden_lines_needs(Status s, const HiddenReport& report, size_t bytes, StageNeeds* want) {
  if (s == Status::kCrossingCapacity)
    want->crossings = need_count(report.cut.crossings + report.cut.near_misses);
  if (s == Status::kIncidenceCapacity) want->incidences = report.incidences_needed;
  if (s == Status::kWorkspaceTooSmall) {
    const size_t more = bytes + bytes / 2;
    want->bytes = report.bytes_needed > more ? report.bytes_needed : more;
  }
}

size_t hidden_lines_first_bytes(const SolidInput& in) {
  return topology_bytes(in) * 3 + 96 * (size_t{in.n_edges} + 3 * size_t{in.n_triangles}) +
         (size_t{1} << 16);
}

}  // namespace haloplot
