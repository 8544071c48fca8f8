// libFuzzer: the .edges reader on any bytes. It must return an error or edges in range.
#include <cstdlib>
#include <sstream>

#include "io/edges_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  std::vector<haloplot::Edge3> edges;
  const haloplot::host::InputError e = haloplot::host::read_edges(in, "fuzz", &edges);
  if (e.failed()) {
    if (e.message().rfind("fuzz", 0) != 0) std::abort();  // errors name the file
    return 0;
  }
  for (const auto& x : edges)
    if (!haloplot::in_range(x)) std::abort();
  return 0;
}
