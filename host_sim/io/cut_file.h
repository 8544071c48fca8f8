// The .cut file: the paper's CUTSET as text, so DRAW can run later, elsewhere, or with other
// halo widths without CUT.
//
//   # haloplot cutset v1          header lines start with '#'
//   # reach R                      near misses were recorded up to R units (0: none)
//   # substep S                    optional: units are 2^-S steps (without it, steps)
//   e I x1 y1 z1 x2 y2 z2          one per edge, I = 0, 1, 2, ... in order
//   c BEHIND FRONT X Y T KIND      one per record, grouped by BEHIND ascending and ordered
//                                  along that edge by (T, FRONT)
//
// X Y: the crossing point in units, 3 decimals. T: the exact stored position along BEHIND,
// floor(t * 2^32); DRAW reads T, so a CUTSET read back draws exactly like the one in memory.
// KIND: "cross" (a proper crossing) or "near" (a near miss within reach).
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

#include "haloplot/cut/cutset.h"
#include "io/input_error.h"

namespace haloplot::host {

// A CUTSET read back from a .cut file, in the same shape.
struct LoadedCut {
  std::vector<Edge3> edges;
  std::vector<uint32_t> first;
  std::vector<Crossing> crossings;
  CutSet set;
  int32_t substep_bits = 0;  // the file's units: 2^-S steps (its '# substep S' header)
  void bind();               // point `set` at the vectors
};

void write_cut(std::ostream& out, const CutSet& set, const std::string& extra_header);
InputError read_cut(std::istream& in, const std::string& name, LoadedCut* out);
InputError read_cut_file(const std::string& path, LoadedCut* out);

// "123.456": a position along an edge, exactly rounded to 3 decimals.
std::string decimal_position(int32_t a, int32_t d, uint32_t t32);

}  // namespace haloplot::host
