// Hidden lines of a solid model in one call, for the host tool and the controller alike:
// topology and checks, classes, CUT over every edge (outside a band, only the pairs with an edge
// a crossing behind which can change a count of faces: a fold, a contour on paper, an irregular
// edge; behind any other the count stays, so the pieces are the same), incidences, then
// Appel/Heger QI (with Kira's outlines traced when asked) on any mesh (counting both sides of
// every face where the mesh is not a closed oriented manifold: solid/qi.h), or the topology-free
// fallback (with Kira's V.C. table and classes when the mesh allows, and Kira's outline
// condition asked part by part when outlines are asked) otherwise.
//
// Memory: one caller buffer, carved stage by stage; CUT's scratch is given back before the
// incidences are found (the CUTSET, carved above the scratch, then moves down onto it, cut to
// the records stored; outside a band CUT's copy of the edges goes with its scratch; the incidences
// are packed the same way, and the vertex stars are built after them: what a run holds at once
// stays near what it uses, not what it first guessed). The report's bytes_used is the high-water
// mark, which may lie above the tail handed to the sink. Before the first piece is emitted every
// stage has carved what it needs, and the sink is told where the unused tail of the buffer begins
// (the controller's job puts its strokes there). A short buffer fails with kWorkspaceTooSmall and
// says how many bytes the run had reached (bytes_needed, a lower bound: later stages were not
// sized); kCrossingCapacity and kIncidenceCapacity say the counts a retry needs.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/cut/cut.h"
#include "haloplot/geometry/edge_piece.h"
#include "haloplot/solid/classify.h"
#include "haloplot/solid/fallback.h"
#include "haloplot/solid/hatch_lines.h"
#include "haloplot/solid/intersection_lines.h"
#include "haloplot/solid/outline.h"
#include "haloplot/solid/qi.h"
#include "haloplot/status/status.h"

namespace haloplot {

// kQi: QI whatever conflicts it meets; kQiPaperOnly: the same without looking for edges that
// pass through faces (what paper alone shows: the control that proves a test sees them).
enum class HiddenMethod : uint8_t { kAuto = 0, kQi = 1, kFallback = 2, kQiPaperOnly = 3 };

// Why the fallback drew the picture (kNone when QI did).
enum class FallbackReason : uint8_t {
  kNone = 0,
  kAsked,      // HiddenMethod::kFallback
  kConflicts,  // QI met vertices with two values: the mesh pierces itself
  kBand,       // a band of a banded plot: the faces are local, the propagation is not
};

struct HiddenParams {
  HiddenMethod method = HiddenMethod::kAuto;
  bool outline = false;  // Kira's outlines (traced from the QI; asked part by part otherwise)
  bool kira = true;      // the fallback's V.C. table and class shortcuts, on manifold meshes
  // Intersection lines where faces cross (solid/intersection_lines.h), after the edges' pieces
  // and before the outlines; in a band, their parts in its rows.
  bool intersections = false;
  // Hatching (solid/hatch_lines.h) after the intersection lines, drawn with the same grid: each
  // hatched face's lines, their visible parts (in a band, those in its rows). A band must hold
  // every triangle of each polygon it holds (the lines' direction reads the whole polygon).
  bool hatch = false;
  HatchParams hatch_params;
  CutParams cut;
  uint32_t crossing_capacity = 0;   // CUTSET records (CUT says the count if short)
  uint32_t incidence_capacity = 0;  // vertex-on-edge incidences
  // The QI propagation's parts (solid/qi.h's QiSplit), run by cut.parts' runner when given.
  uint32_t qi_part_vertices = kQiPartVertices;
  // The most bytes of the buffer the end of the stage in parts (the QI's emission where its
  // walks stop at pierces, the intersection lines) may keep its pieces in, with cut.parts'
  // runner, outside a band: taken before the sink is given the tail, so only a caller that
  // keeps no strokes in the tail asks for it (the host tool). 0: the end on one thread. Tests
  // make it small so parts fill up (what does not fit is done on the calling thread, in turn).
  size_t end_parts_bytes = 0;
  // A band of a solid plotted in bands (band/conductor.h): the input holds the faces and edges
  // meeting rows [band_y0, band_y1) and only those rows are drawn (the fallback's window, no
  // V.C. table: a vertex outside the rows may miss faces of its star). `closed` is the whole
  // model's check: a band's part of a closed solid is open at its borders.
  bool band = false;
  bool closed = false;
  int32_t band_y0 = 0, band_y1 = 0;
};

struct HiddenReport {
  MeshCheck check;
  ClassCounts classes;
  CutStats cut;
  QiStats qi;
  FallbackStats fallback;
  OutlineStats outline;
  IntersectionStats intersections;
  HatchLineStats hatch;
  uint32_t incidences = 0, incidences_needed = 0, coincident_vertices = 0;
  uint32_t n_drawn = 0, n_edges = 0;
  bool used_qi = false;
  // The model's facing (SolidInput::facing) gave the QI conflicts, so it ran again on the
  // facing of the projected area (what the rounded geometry shows) before any fallback.
  bool projected_facing = false;
  FallbackReason reason = FallbackReason::kNone;
  size_t bytes_topology = 0, bytes_cut = 0, bytes_incidence = 0, bytes_qi = 0, bytes_fallback = 0,
         bytes_outline = 0, bytes_intersections = 0;  // the lines' face grid (and a band's)
  size_t bytes_used = 0;                              // the buffer's high-water mark
  size_t bytes_needed = 0;                            // on kWorkspaceTooSmall: at least this many
};

// A piece of a drawn edge (edge < n_drawn), of a contour diagonal (edge >= n_drawn), or of a
// line on the faces (face[0] != kNoFace): an intersection line, or a hatch line (`hatch`, on
// face[0]); a line's edge is the run's edge count + its number (the hatch lines' after the
// intersection lines'). With its projection for rounding; q in halves or kQiUnknown (class or
// V.C. decided).
struct HiddenPiece : EdgePiece {
  const Edge3* geometry;  // valid during the call only (it may lie on the emitter's stack)
  int32_t q;
  bool hidden;
  bool tested;  // false: too short for a test point (solid/fallback.h); a band merges it
  uint32_t face[2] = {kNoFace, kNoFace};  // the faces a line lies on
  bool hatch = false;
};

// An outline run handed to HiddenSink::outline: its own type, so a piece callback and an
// outline callback cannot trade places in a HiddenSink.
struct OutlinePiece : HiddenPiece {};

struct HiddenSink {
  // Called once, before the first piece: [tail, tail + tail_bytes) of the buffer is free
  // until hidden_lines() returns. In a band's run (HiddenParams::band) `edges` are every edge
  // of the run as projected (the drawn ones first, in input order), in the buffer below the
  // tail: they stay there after the run until the buffer is used again, so a caller keeps no
  // copy of its own. Any other run gives CUT's copy of them back once CUT is done (the QI
  // holds its most there) and passes null: each piece still carries its geometry.
  // `begin` may be null.
  void (*begin)(void* context, uint8_t* tail, size_t tail_bytes, const Edge3* edges);
  Status (*piece)(void* context, const HiddenPiece& piece);
  Status (*outline)(void* context, const OutlinePiece& segment);  // may be null
  void* context;
};

// `buffer` starts on a kBufferAlignment (8) boundary, or the run returns kMisalignedBuffer
// before it touches it (status/status.h).
Status hidden_lines(const SolidInput& in, const HiddenParams& params, void* buffer, size_t bytes,
                    HiddenSink sink, HiddenReport* report);

// hidden_lines() as a sized stage (memory/sized_stage.h): needs.crossings and .incidences
// replace the params' capacities. No query sizes every stage before a run, so bytes() is the
// caller's first guess, and a short run's bytes_needed (a lower bound) asks for at least half
// as much again as the run had.
struct HiddenLinesStage {
  const SolidInput* in;
  HiddenParams params;
  HiddenSink sink;
  HiddenReport* report;
  size_t first_bytes;
  size_t bytes(const StageNeeds&) const { return first_bytes; }
  Status run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want);
};

// What a run of hidden_lines() that ended with `s` in a buffer of `bytes` needs (*want).
void hidden_lines_needs(Status s, const HiddenReport& report, size_t bytes, StageNeeds* want);

// A first guess at hidden_lines()'s bytes that fits most scenes: the sized stage's first ask of
// a growing buffer, not a bound (it can be several times the run's need, or short of it). The
// bound for a solid job is job_solid_bytes() (job/job.h), a counting pass.
size_t hidden_lines_first_bytes(const SolidInput& in);

// The edges a crossing behind which can change the count of faces over a point, as bits
// (edge e: bit e % 32 of marked[e / 32], (n_edges + 31) / 32 words): a fold by the model's
// facing (the QI's own rule), an edge whose faces lie on one side of it on paper (a contour,
// also after the QI's retry with the projected facing, and two-sided counting's rule), and any
// edge that is not a regular two-faced one (a boundary, a fin, a seam; its other faces are not
// all at hand before the stars). Behind any other edge one of its faces stops covering the
// walking point where the other starts: nothing changes, in the QI or in the fallback's counts,
// so the hidden lines' CUT pairs only these with the rest (CutParams::marked); on a smooth mesh
// they are few (the 1M-triangle torus: some 2,800 edges of 1.5 million). Needs classify().
void mark_crossing_edges(const Topology& topo, uint32_t* marked);

}  // namespace haloplot
