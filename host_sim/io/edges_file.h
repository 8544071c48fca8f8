// The .edges scene format: text; '#' starts a comment line; each data line holds six integers
// "x1 y1 z1 x2 y2 z2" in [0, 2^20). Edge index = 0-based order of the data lines. A header
// line "# substep S" says the coordinates are in units of 2^-S steps (io/substep_header.h).
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

#include "geometry/contract.h"
#include "io/input_error.h"

namespace haloplot::host {

// *substep_bits (may be null) gets the file's units.
InputError read_edges(std::istream& in, const std::string& name, std::vector<Edge3>* edges,
                      int32_t* substep_bits = nullptr);
InputError read_edges_file(const std::string& path, std::vector<Edge3>* edges,
                           int32_t* substep_bits = nullptr);
void write_edges(std::ostream& out, const std::vector<Edge3>& edges, const std::string& header);

}  // namespace haloplot::host
