// The header line of an .edges or .cut file whose coordinates are in units of 2^-S steps
// (core/include/haloplot/geometry/units.h): "# substep S". Without it the file is in whole steps,
// as every file written before sub-step units was.
#pragma once
#include <cstdint>
#include <string>

namespace haloplot::host {

// "# substep S\n" for S > 0; "" for whole steps.
std::string substep_header(int32_t substep_bits);

// The S of a file's header comments (0 without the line); false with *why when S is not an
// integer in [0, kMaxSubstepBits].
bool read_substep_header(const std::string& comments, int32_t* substep_bits, std::string* why);

}  // namespace haloplot::host
