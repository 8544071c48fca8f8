// Run CUT then DRAW through the host pipeline (the code under test) and return the spans.
#pragma once
#include <string>
#include <vector>

#include "../check.h"
#include "pipeline/host_pipeline.h"

namespace support {

struct Plot {
  std::vector<haloplot::Span> spans;
  haloplot::DrawStats stats;
};

inline Plot plot(const std::vector<haloplot::Edge3>& edges, int32_t halo, haloplot::HaloMode mode,
                 int32_t reach = 0) {
  haloplot::CutParams cp;
  cp.reach = reach;
  haloplot::host::HostCut c;
  Plot out;
  haloplot::Status s = haloplot::host::host_cut(edges, cp, &c);
  CHECK_MSG(ok(s), std::string("CUT: ") + haloplot::status_name(s));
  if (!ok(s)) return out;
  haloplot::host::HostDraw d;
  s = haloplot::host::host_draw(c.set, haloplot::DrawParams{halo, mode}, &d);
  CHECK_MSG(ok(s), std::string("DRAW: ") + haloplot::status_name(s));
  out.spans = d.spans;
  out.stats = d.stats;
  return out;
}

// Spans of one edge as "x0,y0-x1,y1;..." for readable comparisons.
inline std::string spans_of(const Plot& p, uint32_t edge) {
  std::string s;
  for (const haloplot::Span& sp : p.spans)
    if (sp.edge == edge)
      s += std::to_string(sp.x0) + "," + std::to_string(sp.y0) + "-" + std::to_string(sp.x1) + "," +
           std::to_string(sp.y1) + ";";
  return s;
}

}  // namespace support
