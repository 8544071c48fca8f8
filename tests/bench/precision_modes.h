// Section 3 of docs/reports/accuracy.md: every precision mode of the core on the same scenes, error
// against an exact (long double) reference and time, and the error-against-time front.
//   DRAW:       square root (exact, Newton, table) x position grid (Q0.32, Q0.16);
//   projection: Q16.16 and Q2.30 in the core; float and double here, benchmark-only (the
//               Cortex-M4 has no double-precision FPU: the firmware gate forbids them).
// Host only.
#pragma once
#include <sstream>
#include <string>

namespace bench {

// Appends the section to md and writes precision_pareto.svg into dir.
void precision_modes_section(const std::string& dir, int runs, std::ostringstream& md);

// For callgrind (tools/bench_accuracy.sh): CUT the demo cube array, then one DRAW in mode k
// (0..5: exact, Newton, table roots with Q0.32, then with Q0.16), once. Returns the spans.
size_t draw_once_in_mode(int k);

}  // namespace bench
