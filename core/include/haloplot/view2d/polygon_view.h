// Freeman & Loutrel (1967): which parts of a simple polygon's edges are visible from a
// vantage point E in its plane (the island seen from a ship, or the lake shore from a boat).
//
// The paper's steps, in exact integer arithmetic (no arctan, no floating point):
//   1-3   total angles: each vertex's direction from E as a half-plane and cross-product
//         order, with a signed count of whole turns; the configuration (free exterior,
//         blocked exterior, interior) from the net turn and the spread of the total angles;
//   4-6   A1 the most clockwise vertex, Am the most counterclockwise; Proposition 3: the
//         edges after Am and before A1 are invisible (and their vertices need no testing);
//   7-11  a first visible point on the ray E A1 for blocked and interior configurations: the
//         nearest counterclockwise crossing of the boundary with the ray;
//   12-19 the walk from visible point to visible point: Proposition 2 for an edge turning
//         counterclockwise with nothing in front, a backward bay (the edge turns clockwise:
//         the walk resumes where the boundary next crosses the ray E P counterclockwise,
//         nearest first), a forward bay (a vertex inside the triangle E P A(j+1), the most
//         clockwise one, hides the edge from the ray through it to A(j+1));
//   20    the end: at Am for a free exterior, after one full turn otherwise.
//
// Ties (vertices collinear with E, E collinear with an edge) are broken by simulation of
// simplicity: E is moved by (eps, eps^2), infinitesimally, so no two vertices ever lie on one
// ray from E. This changes the visible set by at most finitely many points (edges seen
// exactly edge-on come out invisible, as in the paper's step 13).
//
// Output: each edge's visible parts as exact parameter intervals [s0, s1] along the input
// edge (P[i] -> P[i+1]); visible_span_points() rounds them to steps within 1/2 + 2^-11.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/status/sink.h"
#include "haloplot/status/status.h"

namespace haloplot {

struct Point2 {
  int32_t x, y;
};

struct Ratio {  // num / den, den > 0, both below 2^44 in magnitude
  int64_t num, den;
};

struct VisibleSpan {
  uint32_t edge;  // input edge index: P[edge] -> P[(edge + 1) % n]
  Ratio s0, s1;   // 0 <= s0 < s1 <= 1 along the edge
};

using VisibleSink = Sink<VisibleSpan>;

enum class ViewConfig : uint8_t { kFreeExterior, kBlockedExterior, kInterior };

struct View2dStats {
  ViewConfig config = ViewConfig::kFreeExterior;
  uint32_t prop3_edges = 0;    // edges eliminated by Proposition 3
  uint32_t backward_bays = 0;  // step 14
  uint32_t forward_bays = 0;   // step 19
  uint32_t visible_steps = 0;  // step 18: whole edge pieces seen by Proposition 2
  uint64_t vertex_tests = 0;   // vertices examined for forward bays (steps 15-17)
};

// Coordinates of polygon vertices and of E: within [-2^20, 2^20].
inline constexpr int32_t kView2dLimit = int32_t{1} << 20;

size_t view2d_scratch_bytes(uint32_t n);

// Validates the polygon (at least 3 vertices, coordinates in range, no zero-length edge, no
// two edges meeting except consecutive ones at their shared vertex, E not on the boundary)
// and reports the visible parts. Errors: kBadParameter (fewer than 3 vertices, or E on the
// polygon), kCoordinateOutOfRange, kSelfIntersecting (with *bad_edges set to the pair),
// kWorkspaceTooSmall, kMisalignedBuffer (scratch not on a kBufferAlignment boundary), or the
// sink's own status.
Status view2d(const Point2* polygon, uint32_t n, Point2 eye, void* scratch, size_t scratch_bytes,
              VisibleSink sink, View2dStats* stats, uint32_t bad_edges[2] = nullptr);

// A parameter along an edge rounded to steps: within 1/2 + 2^-11 of the exact point.
void visible_point(Point2 a, Point2 b, Ratio s, int32_t* x, int32_t* y);

}  // namespace haloplot
