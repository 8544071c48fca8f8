// The .edges scene format: text; '#' starts a comment line; each data line holds six integers
// "x1 y1 z1 x2 y2 z2" in [0, 2^20). Edge index = 0-based order of the data lines. A header
// line "# substep S" says the coordinates are in units of 2^-S steps (io/substep_header.h).
// A line "bezier x0 y0 z0 x1 y1 z1 x2 y2 z2 x3 y3 z3" is a cubic Bézier edge (docs/curves.md):
// read_edges() refuses it by name (the stages it feeds take straight edges only);
// read_edges_with_curves() reads both kinds.
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

#include "haloplot/curve/bezier.h"
#include "haloplot/geometry/contract.h"
#include "io/input_error.h"

namespace haloplot::host {

// *substep_bits (may be null) gets the file's units.
InputError read_edges(std::istream& in, const std::string& name, std::vector<Edge3>* edges,
                      int32_t* substep_bits = nullptr);
InputError read_edges_file(const std::string& path, std::vector<Edge3>* edges,
                           int32_t* substep_bits = nullptr);
void write_edges(std::ostream& out, const std::vector<Edge3>& edges, const std::string& header);

// A scene with curved edges. Every edge keeps the index of its data line: edge_index[k] is
// straight edge k's, curve_index[k] curve k's.
struct EdgesWithCurves {
  std::vector<Edge3> edges;
  std::vector<uint32_t> edge_index;
  std::vector<BezierEdge3> curves;
  std::vector<uint32_t> curve_index;
};
InputError read_edges_with_curves(std::istream& in, const std::string& name, EdgesWithCurves* out,
                                  int32_t* substep_bits = nullptr);
InputError read_edges_with_curves_file(const std::string& path, EdgesWithCurves* out,
                                       int32_t* substep_bits = nullptr);
// The curves first, then the straight edges.
void write_edges_with_curves(std::ostream& out, const std::vector<BezierEdge3>& curves,
                             const std::vector<Edge3>& edges, const std::string& header);

}  // namespace haloplot::host
