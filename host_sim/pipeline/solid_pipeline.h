// Hidden lines of a solid model on the host: the core's stages in order (topology, classes,
// CUT over every edge, incidences, then QI propagation or the topology-free fallback), each
// in a buffer sized by the core's own query, and the pieces of every drawn edge with its QI.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "haloplot/haloplot.h"
#include "haloplot/solid/classify.h"
#include "haloplot/solid/fallback.h"
#include "haloplot/solid/hidden_lines.h"
#include "haloplot/solid/outline.h"
#include "haloplot/solid/qi.h"
#include "pipeline/host_pipeline.h"

namespace haloplot::host {

struct SolidScene {
  std::vector<Point3> vertices;      // projected
  std::vector<uint32_t> edge_pairs;  // drawn edges, output order
  std::vector<Triangle> triangles;
  int32_t substep_bits = 0;     // the vertices' units: 2^-S steps (View::substep_bits)
  std::vector<uint8_t> facing;  // per triangle from the model (empty: the projected area)
  // What plot says when a shell is not a closed solid (cli/shells_note.h): the open shells
  // (the --weld that closes their gaps, or open as made) and where a shell cannot be oriented.
  std::string repair_note;
  std::string repair_stats;  // what the note rests on, key=value lines for --stats
};

// The core's view of a scene (pointers into it: the scene must outlive the input).
SolidInput solid_input(const SolidScene& scene);

// A piece of a drawn edge: t in Q0.32 from its first vertex; q in halves (kQiUnknown when a
// class or the V.C. table decided, then only `hidden` is known). 24 bytes, not an EdgePiece's
// 24 and 8 more: `hidden` takes the top bit of t1's word (t1 <= 2^32), q the edge's padding.
// A 1M-triangle plot keeps some 1.5 million of them while the stage's buffer is still held,
// the whole plot's peak on the torus.
struct SolidPiece {
  uint32_t edge;
  int32_t q;
  int64_t t0;
  int64_t t1 : 63;
  bool hidden : 1;
};
static_assert(sizeof(SolidPiece) == 24, "a piece packs into three words");

struct SolidRun {
  bool used_qi = false;
  std::string fallback_reason;  // why the fallback ran (empty when QI did)
  MeshCheck check;
  ClassCounts classes;
  CutStats cut;
  QiStats qi;
  FallbackStats fallback;
  uint32_t incidences = 0, coincident_vertices = 0;
  size_t bytes_topology = 0, bytes_incidence = 0, bytes_qi = 0, bytes_fallback = 0, bytes_cut = 0,
         bytes_intersections = 0;
  double ms_total = 0;
  // The same run's CPU time, every thread's (a shared machine's clocks are fairer in CPU).
  double cpu_ms_total = 0;
  std::vector<SolidPiece> pieces;             // drawn edges
  std::vector<SolidPiece> contour_diagonals;  // H3 diagonals (QI only): edge >= drawn count
  // Intersection lines (when asked): edge >= every edge's count; the two faces of each piece.
  std::vector<SolidPiece> intersections;
  std::vector<std::array<uint32_t, 2>> intersection_faces;
  IntersectionStats intersection_stats;
  // Hatch lines (when asked): edge >= every edge's and line's count; the face of each piece.
  std::vector<SolidPiece> hatch;
  std::vector<uint32_t> hatch_faces, hatch_polygons;
  HatchLineStats hatch_stats;
  std::vector<Edge3> edges;  // every edge as projected (drawn first, then diagonals)
  uint32_t n_drawn = 0;
  // Kira's outlines (QI method only, when asked).
  std::vector<OutlineSegment> outline;
  OutlineStats outline_stats;
  size_t bytes_outline = 0;
};

// The whole model's faces make a closed, consistently oriented 2-manifold (its topology's
// MeshCheck; loose `l` lines allowed): what a plot in bands is told, since no band can see it.
bool model_closed(const SolidScene& scene);

// kAuto: QI on a closed oriented manifold, the fallback otherwise. `kira` chooses the
// fallback's shortcuts (classes, V.C.); they are only used on manifold meshes.
Status run_hidden_lines(const SolidScene& scene, HiddenMethod method, FallbackParams kira,
                        SolidRun* out, bool outlines = false, bool intersections = false,
                        const HatchParams* hatch = nullptr, const Parts* parts = nullptr,
                        uint32_t qi_part_vertices = kQiPartVertices);

}  // namespace haloplot::host
