// Helpers that run the core (the code under test) and flatten its CUTSET for comparison
// with the reference.
#pragma once
#include <vector>

#include "pipeline/host_pipeline.h"
#include "reference/brute_cut.h"

namespace support {

inline std::vector<reference::Record> records_of(const haloplot::CutSet& s,
                                                 bool include_near = false) {
  std::vector<reference::Record> out;
  for (uint32_t e = 0; e < s.n_edges; ++e)
    for (uint32_t k = 0; k < s.count(e); ++k) {
      const haloplot::Crossing& c = s.begin(e)[k];
      if (c.near_miss() && !include_near) continue;
      out.push_back({c.behind, c.front_edge(), c.t});
    }
  return out;
}

// The CUTSET's own invariants: an index entry for every edge (C9), groups in edge order,
// records ordered along each edge, no self-crossings.
inline bool cutset_well_formed(const haloplot::CutSet& s) {
  if (s.first[0] != 0 || s.first[s.n_edges] != s.n_crossings) return false;
  for (uint32_t e = 0; e < s.n_edges; ++e) {
    if (s.first[e] > s.first[e + 1]) return false;
    for (uint32_t k = 0; k < s.count(e); ++k) {
      const haloplot::Crossing& c = s.begin(e)[k];
      if (c.behind != e || c.front_edge() == e || c.front_edge() >= s.n_edges) return false;
      if (k > 0) {
        const haloplot::Crossing& p = s.begin(e)[k - 1];
        if (p.t > c.t || (p.t == c.t && p.front > c.front)) return false;
      }
    }
  }
  return true;
}

}  // namespace support
