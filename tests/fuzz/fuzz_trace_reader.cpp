// libFuzzer: the trace reader on any bytes; an accepted trace must replay without fault.
#include <sstream>

#include "sim/replay.h"
#include "sim/trace.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 4096) return 0;  // a run line can ask for millions of events: keep runs short
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  haloplot::host::Trace t;
  if (haloplot::host::read_trace(in, "fuzz", &t, 100000).failed()) return 0;
  (void)haloplot::host::replay(t);
  return 0;
}
