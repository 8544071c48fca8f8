// The band conductor: a haloed (or all-edges) plot of any size in one fixed arena.
//
// The plot is cut into horizontal bands [y0, y1) (band/band_rule.h). Each band is worked alone
// in the arena: the edges that meet it (read from an EdgeSource, the scene never stored),
// CUT and DRAW on them, the visible pieces the band owns, their pen path. The motion planner
// pulls band after band through next(), so the arena holds one band at a time whatever the
// scene's size.
//
// Why the result equals the unbanded plot exactly. A band must see every gap that reaches its
// rows. A gap is cut into edge E by a front edge F (a CUTSET record); E runs through the gap,
// and F comes within `gap reach` rows of every point of it. So the band takes every edge that
// meets its rows widened by margin = gap reach + 1: both edges of every record whose gap
// touches the band are then there, CUT finds the record (it finds every crossing of its input,
// wherever it lies) with the same Q0.32 position, and DRAW cuts the same gap. The gap reach is
// measured first, by a margin pass over the scene in bands (CUT only, each band widened by
// CUT's reach so every record is found where its point lies, each record's gap as DRAW sizes
// it: draw.h record_gap); a plot whose scene fits in one band skips it. Inside its rows a band's
// visibility is then exact; a piece that runs past the top is carried up by (edge, lower end), so
// the band owning its upper end draws it whole with the true lower end. No piece is split, lost or
// drawn twice.
//
// Band heights come from the arena: the first attempt is the whole scene; a band that does not
// fit (edges, CUTSET, scratch, pieces or path) is halved and tried again, never truncated; a
// band that fitted in half the arena lets the next one double. A band one row high that still
// does not fit returns kArenaTooSmall with the bytes it needed in stats().need_bytes.
//
// Arena, during one band (low addresses left):
//   [carry in, deferred in | band edges -> ... CUTSET | CUT or DRAW scratch | carry out |
//    pieces -> ... <- ids]
// and once the band fits:
//   [carry out | segments deferred to the band above | segments to draw now | one column's
//    path points and path workspace]
// The carry and the deferred segments stay at the front while the next band is worked.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/band/edge_source.h"
#include "haloplot/band/solid_source.h"
#include "haloplot/cut/cut.h"
#include "haloplot/draw/draw.h"
#include "haloplot/geometry/edge_piece.h"
#include "haloplot/geometry/quarter_turn.h"
#include "haloplot/motion/path_plan.h"
#include "haloplot/solid/modes.h"
#include "haloplot/status/status.h"
#include "haloplot/surface/hatch.h"

namespace haloplot {

struct BandSpec {
  bool haloed = true;                // false: every edge whole (no CUT, no DRAW), still in bands
  DrawParams draw;                   // halo width and mode
  CutParams cut;                     // grid choices and reach (compact_cells off saves arena)
  int32_t start_x = 0, start_y = 0;  // the pen before the first band
  // >= 0: this margin instead of the margin pass's. Unsafe below the measured one (gaps from
  // outside the margin are lost); the band test uses it to show that its check sees that.
  int32_t fixed_margin = -1;
  // > 0: no band taller than this many rows (the floor bench plots a solid in bands one row
  // high, each band's peak then its exact bytes).
  int32_t max_rows = 0;
  // > 0: at most this many edges in a band (a controller that receives bands over its link
  // stages the next band in a buffer of this many edges); more is a band that does not fit.
  uint32_t max_band_edges = 0;
  // A solid (begin_solid): the hidden-line strokes of each band in this style (solid/modes.h),
  // and Kira's outlines, asked part by part in each band (solid/fallback.h).
  StrokeStyle style;
  bool outline = false;
  // And the visible parts of the lines where faces cross (solid/intersection_lines.h), each
  // band those in its rows, cut at its borders (a stroke on each side meets the other's end).
  bool intersections = false;
  // And hatching (solid/hatch_lines.h): each band the parts of the lines in its rows, cut at its
  // borders. A band then holds every triangle of each polygon it holds (band_rule.h).
  bool hatch = false;
  HatchParams hatch_params;
  // The scene's units are 2^-substep_bits steps: the lengths above are in units already
  // (band_spec() converts a job's), and each column's strokes are rounded to steps before its
  // path is planned (geometry/units.h).
  int32_t substep_bits = 0;
  // The planner's clean-up of each column's strokes (motion/path_plan.h). band_spec() keeps a
  // job's switch but no minimum stroke: a column's strokes end at its sides, so a short piece
  // there goes on in the next column and is no crumb.
  PathClean clean;
  // A solid wider than tall (begin_solid) is banded in the page turned a quarter
  // (geometry/quarter_turn.h): its bands are then columns of the page, and the pen crosses
  // each along the drawing's shorter side, not its longer (tests/cli/band_pen_up.sh: 10 x 10
  // hatched cubes in 64 KB, 1.21x of one band's pen-up travel turned, 1.33x in strips of the
  // page's rows). Every point leaves the conductor turned back, rounded as the page rounds it.
  // Off: strips of the page's rows. A streamed solid turns as its host's plan did
  // (begin_streamed_solid's `turned`).
  bool turn_wide = true;
};

// A band sent from outside: a host ran the same conductor over the whole scene with the same
// arena, and sends each committed band's rows with the edges it gathered (the same rule, the
// same order) and their indices in the scene. The controller never holds the scene.
struct StreamedBand {
  int32_t y0 = 0, y1 = 0;  // rows [y0, y1)
  const Edge3* edges = nullptr;
  const uint32_t* ids = nullptr;  // scene indices of the edges (a solid's: of its drawn edges)
  uint32_t n = 0;
  const StagedSolidBand* solid = nullptr;  // a solid's band (begin_streamed_solid): its model part
};
struct BandStream {
  void* ctx = nullptr;
  // The next band: kOk with *band filled; kOk with *end set after the last one; kBusy while
  // the next one is still arriving (the plot then waits, and asks again).
  Status (*next)(void* ctx, StreamedBand* band, bool* end) = nullptr;
  // The band's edges are in the arena now: its buffer may take the next band.
  void (*release)(void* ctx) = nullptr;
};

// A visible piece as a band emits it: the edge's index in the source, its Q0.32 ends along
// the edge (t0 < t1, DRAW's values) and the rounded segment the path draws.
// edge: the scene's edge, or kNoFace for a piece of a line on the faces or of a contour
// diagonal (or an outline along one) ...
struct BandPiece : EdgePiece {
  Segment2 segment;
  const Edge3* line = nullptr;  // ... of this segment (t0, t1 along it; valid during the call)
};

// Sees every piece once, in the band that owns it, when the band is committed (tests compare
// them with the unbanded DRAW).
struct PieceObserver {
  void (*piece)(void* ctx, const BandPiece& p) = nullptr;
  void* ctx = nullptr;
  // Each band as it commits: its rows, in a turned plot the turned frame's (page columns
  // x = kTurnOffset - y, geometry/quarter_turn.h; BandStats::turned).
  void (*band)(void* ctx, int32_t y0, int32_t y1) = nullptr;
};

struct BandStats {
  uint32_t bands = 0;         // bands committed by the drawing pass
  uint32_t margin_bands = 0;  // bands of the margin pass (0 when the scene fit one band)
  uint32_t splits = 0;        // band attempts that did not fit and were halved
  int32_t gap_reach = 0;      // rows from a gap to its front edge, at most (margin pass)
  int32_t margin = 0;         // rows added above and below every band: gap reach + 1
  uint32_t most_edges = 0;    // edges in the largest band (its own and its margin's)
  uint32_t most_pieces = 0;   // pieces in the busiest band
  uint32_t most_carry = 0;    // pieces carried across one border at once
  uint64_t edge_reads = 0;    // edges read from the source, both passes, every attempt
  uint64_t band_edges = 0;    // edges over the committed bands (an edge in k bands counts k)
  uint64_t pieces = 0;
  uint64_t deferred = 0;  // pieces drawn with the band above, to join a polyline there
  uint64_t records = 0;   // CUTSET records over all committed bands (margins repeat some)
  uint64_t cut_runs = 0, draw_runs = 0;
  size_t peak_bytes = 0;  // the most of the arena any band used
  size_t need_bytes = 0;  // kArenaTooSmall: what the one-row band asked for
  PathStats path;         // summed over the bands
  bool turned = false;    // a solid banded in the page turned a quarter (BandSpec::turn_wide)
  // Clock ticks (set_clock) of the drawing pass's committed bands, spent in CUT, in DRAW and
  // in the rest (reading the source, the path); of its attempts that did not fit (all their
  // work); and of the whole margin pass.
  uint64_t cut_ticks = 0, draw_ticks = 0, other_ticks = 0, wasted_ticks = 0, margin_ticks = 0;
};

// What the host's dry run knew of a streamed solid that no band can tell: flags rather than two
// bools, so the two cannot trade places in a call.
enum class SolidStreamFlags : uint8_t { kNone = 0, kClosed = 1, kTurned = 2 };
constexpr SolidStreamFlags operator|(SolidStreamFlags a, SolidStreamFlags b) {
  return SolidStreamFlags(uint8_t(a) | uint8_t(b));
}
constexpr bool has(SolidStreamFlags set, SolidStreamFlags flag) {
  return (uint8_t(set) & uint8_t(flag)) != 0;
}

class BandConductor {
 public:
  constexpr BandConductor() : no_spec_(0) {}  // see spec_
  // A solid's hidden lines in bands (spec.style: hidden-removed or hidden-dashed): each band
  // takes the faces and drawn edges meeting its rows and runs the topology-free method on them
  // in its rows only (solid/hidden_lines.h, HiddenParams::band): Franklin's test of a piece's
  // middle asks the faces of its grid cell, all of which meet the band. Pieces are cut at the
  // band's borders (band_rule.h row_window) and carried up with their q, so the band owning a
  // piece's upper end strokes it whole, dashes measured from its true start. No margin: a cut
  // point inside the rows is a crossing with an edge, or a vertex, meeting those rows.
  Status begin_solid(const BandSpec& spec, SolidSource source, void* arena, size_t arena_bytes);
  // The same solid plot from streamed bands (StreamedBand::solid), as the host's dry run with
  // this arena cut them; SolidStreamFlags::kClosed is the whole model's check, which no band
  // can make; kTurned: the host's plan turned the page (BandStats::turned; its bands' rows are
  // then the turned frame's, its vertices the page's).
  Status begin_streamed_solid(const BandSpec& spec, SolidStreamFlags flags, BandStream stream,
                              void* arena, size_t arena_bytes);
  // Checks the scene (one read) and the settings; nothing is cut yet. Every begin takes an
  // arena that starts on a kBufferAlignment (8) boundary, or returns kMisalignedBuffer.
  Status begin(const BandSpec& spec, EdgeSource source, void* arena, size_t arena_bytes);
  // The same plot from streamed bands, with the margin the host's run measured: no margin
  // pass, no retries (the host's bands fit this arena, or kArenaTooSmall says they do not).
  Status begin_streamed(const BandSpec& spec, int32_t margin, BandStream stream, void* arena,
                        size_t arena_bytes);
  // The next band's path points, from where the previous band left the pen; n == 0 when the
  // plot is done; kBusy when a streamed band is still arriving. The points live in the arena
  // until the next call.
  Status next(const PathPoint** points, uint32_t* n);

  void set_observer(PieceObserver o) { observer_ = o; }
  void set_clock(uint64_t (*clock)()) { clock_ = clock; }
  const BandStats& stats() const { return stats_; }
  bool done() const { return !running_; }

  // Adapter for MotionPlanner::set_feed: the planner pulls the bands itself.
  static Status feed(void* self, const PathPoint** points, uint32_t* n) {
    return static_cast<BandConductor*>(self)->next(points, n);
  }

  // One try at one band (band_attempt.h, internal to core/band).
  struct Attempt;

 private:
  // A piece running past a band's top: its edge and its lower end along it, stored as t0 for
  // a rising edge and t1 - 1 for a falling one, so 32 bits hold it (t0 < 2^32 <= ... t1 > 0).
  // A solid's piece also keeps its q and whether it is hidden: the band above merges it with
  // its own first piece of the edge only when both agree, as one unbanded run would.
  struct Carry {
    uint32_t edge, lower;
  };
  // A solid's carried piece also keeps its run's q, and `join` (0 < join < 2^32): where the
  // run ends, coming up (the border, or where a sliver too short to test begins; the band above
  // tells the sliver's q). A run is hidden exactly when its q is not 0 (the band's fallback
  // uses no V.C. table; a class decision is kQiUnknown and hidden). Kept beside the carry, in
  // solid mode only, so an edge plot's carry stays 8 bytes an edge.
  struct CarryRun {
    uint32_t join;
    int32_t q;
  };
  struct Gathered {  // one attempt's edges: Edge3 at the front, source indices at the top
    Edge3* edges;
    uint32_t* ids_end;  // local edge k has source index ids_end[-1 - k]
    uint32_t n;
    uint8_t* free_lo;  // the free middle of the arena
    uint8_t* free_hi;
    uint32_t id(uint32_t local) const { return ids_end[-1 - int64_t{local}]; }
  };

  Status gather(int64_t lo, int64_t hi, Gathered* g);
  Status cut_band(const Gathered& g, CutSet* cs, uint8_t** after, size_t* need);
  Status margin_pass();
  int64_t gap_reach(const CutSet& cs, const Crossing& r) const;
  Status try_band(int32_t y1, bool* fitted);
  Status next_streamed_band();
  Status draw_band(Attempt& a);
  // The solid stage (solid_band.cpp): one band's faces and edges, then its hidden lines; and a
  // streamed band's model part as its source. Reached only through solid_stage_, which only
  // begin_solid and begin_streamed_solid set, so a program that plots edges never links the
  // solid stages (conductor.cpp and band_path.cpp name none of them; test lean_link).
  struct SolidStage {
    Status (*band)(BandConductor& self, Attempt& a);
    SolidSource (*streamed)(const StagedSolidBand& band, bool closed);
    uint32_t (*join)(const BandConductor& self, const Attempt& a, Segment2* u, uint32_t n_own,
                     uint32_t nu, uint8_t* free);  // solid_border_join.cpp
  };
  static const SolidStage kSolidStage;
  Status gather_solid(Attempt& a);
  Status gather_vertices(Attempt& a, uint32_t* pairs, Triangle* tris, uint32_t* vids);
  Status hide_band(Attempt& a);
  bool solid_mode() const { return solid_stage_ != nullptr; }
  Status commit_band(Attempt& a);
  uint32_t defer_joined(const Attempt& a, Segment2* u, uint32_t n_own, uint32_t nu, uint8_t* free);
  uint32_t join_at_border(const Attempt& a, Segment2* u, uint32_t n_own, uint32_t nu,
                          uint8_t* free) const;
  static constexpr int kJoinDepth = 4;  // links followed from a carried piece's lower end
  size_t carry_bytes(uint32_t n) const {
    const size_t runs = solid_mode() ? size_t{n} * sizeof(CarryRun) : 0;
    return ((size_t{n} * sizeof(Carry) + 7) & ~size_t{7}) + runs;
  }
  // The runs stand after the carry entries at the front of the arena.
  CarryRun* carry_runs(uint8_t* carry, uint32_t n) const {
    return reinterpret_cast<CarryRun*>(carry + ((size_t{n} * sizeof(Carry) + 7) & ~size_t{7}));
  }
  // The front of the arena between bands: the carry and the segments deferred to the next band.
  size_t front_bytes() const {
    return carry_bytes(n_carry_) + ((size_t{n_defer_} * sizeof(Segment2) + 7) & ~size_t{7});
  }
  Status plan_column(const PathPoint** points, uint32_t* n);
  int64_t column_of(int64_t x_sum) const;                        // x_sum: x0 + x1 of a segment
  bool column_less(const Segment2& p, const Segment2& q) const;  // by column, then whole
  struct ColumnOrder {  // one comparator type for every sort by column (one instantiation)
    const BandConductor* self;
    bool operator()(const Segment2& p, const Segment2& q) const { return self->column_less(p, q); }
  };
  static constexpr int64_t kMinColumn = 256;  // steps: the narrowest path column
  uint64_t now() const { return clock_ ? clock_() : 0; }
  int64_t rows_for(int64_t rows, size_t bytes) const;  // rows that 7/8 of the arena holds
  int64_t next_height(int64_t rows) const;             // after a band that fitted
  int64_t shorter(int64_t rows, size_t need) const;    // after one that did not
  bool cuts() const { return spec_.haloed && spec_.draw.halo > 0; }  // halo 0: edges whole
  void note_used(size_t bytes) {
    if (bytes > stats_.peak_bytes) stats_.peak_bytes = bytes;
    if (bytes > band_used_) band_used_ = bytes;
  }
  void note_peak(size_t bytes) {  // a band's bytes at their highest, its transient ones too
    if (bytes > stats_.peak_bytes) stats_.peak_bytes = bytes;
  }
  // A turned plot (BandSpec::turn_wide): solid_'s vertices are read turned (solid_vertex),
  // and every point leaves turned back (band_frame.cpp).
  Status solid_vertex(uint32_t index, Point3* out) const;
  Segment2 page_segment(const Segment2& g) const;     // a band-frame segment, turned back
  void steps_to_band(Segment2* g, uint32_t n) const;  // page steps into the band frame's steps
  void steps_to_page(PathPoint* p, uint32_t n) const;
  int32_t turn_steps() const { return kTurnOffset >> spec_.substep_bits; }
  void turn_pen() {  // the pen's page steps into the turned frame's
    const int32_t x = pen_x_;
    pen_x_ = pen_y_;
    pen_y_ = turn_steps() - x;
  }

  // Set by every begin, read only after one. Until then a zero byte is the union's member, so a
  // conductor in static storage is all zeros: in .bss, with no constructor and no .data copy
  // (BandSpec's defaults are not zeros). Copying a BandSpec in makes it the member.
  union {
    uint8_t no_spec_;
    BandSpec spec_;
  };
  EdgeSource source_{};
  uint8_t* arena_ = nullptr;
  size_t arena_bytes_ = 0;
  int32_t row_lo_ = 0, row_hi_ = 0;  // the scene's rows, inclusive
  int64_t next_row_ = 0;             // the next band's y0
  int64_t height_ = 0;               // the next attempt's height
  bool margin_known_ = false;
  bool running_ = false;  // begun, and bands left (zero when not begun: see spec_)
  const SolidStage* solid_stage_ = nullptr;  // a solid's plot: &kSolidStage
  bool closed_ = false;                      // a solid's model is closed (SolidSource::closed)
  SolidSource solid_{};                      // a solid's model, or (streamed) the band's part
  bool turned_ = false;                      // the page turned a quarter (band_frame.cpp)
  uint32_t solid_crossings_ = 0;             // the last band's CUT records: the next first guess
  BandStream stream_{};                      // streamed mode when stream_.next is set
  const uint32_t* stream_ids_ = nullptr;     // scene indices of the streamed band's edges
  uint32_t n_carry_ = 0;                     // carry entries at the front of the arena
  uint32_t n_defer_ = 0;                     // segments deferred to the next band, after the carry
  size_t band_used_ = 0;                     // the current attempt's bytes
  // The committed band's segments, in column order, waiting for next() to plan them.
  Segment2* segs_ = nullptr;
  uint32_t n_segs_ = 0, next_seg_ = 0;
  int64_t column_side_ = 0;  // set as each band commits, before a column is planned
  bool leftward_ = false;
  int64_t band_y0_ = 0, band_y1_ = 0;  // the committed band's rows
  int32_t pen_x_ = 0, pen_y_ = 0;
  bool pen_down_ = false;  // the last column's path ended drawing
  PieceObserver observer_{};
  uint64_t (*clock_)() = nullptr;
  BandStats stats_{};
};

// Every band, without motion (the host's dry run of a streamed plot, `plot --arena`): next()
// until the plot is done, the points dropped.
inline Status run_all_bands(BandConductor& conductor) {
  Status s = Status::kOk;
  while (ok(s) && !conductor.done()) {
    const PathPoint* points = nullptr;
    uint32_t n = 0;
    s = conductor.next(&points, &n);
  }
  return s;
}

}  // namespace haloplot
