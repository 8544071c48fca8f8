#include "pipeline/drawing_modes.h"

#include "geometry/wide.h"

namespace haloplot::host {
namespace {

Span make_span(const Edge3& e, uint32_t edge, int64_t t0, int64_t t1) {
  Span s{edge, t0, t1, 0, 0, 0, 0};
  span_point(e, t0, &s.x0, &s.y0);
  span_point(e, t1, &s.x1, &s.y1);
  return s;
}

// Length of the edge on paper, in whole steps (at least 1).
int64_t paper_length(const Edge3& e) {
  const int64_t dx = e.b.x - e.a.x, dy = e.b.y - e.a.y;
  const int64_t l = isqrt_u64(uint64_t(dx * dx + dy * dy));
  return l > 0 ? l : 1;
}

}  // namespace

bool parse_solid_mode(const std::string& s, SolidMode* out) {
  if (s == "all")
    *out = SolidMode::kAll;
  else if (s == "hidden-removed")
    *out = SolidMode::kHiddenRemoved;
  else if (s == "hidden-dashed")
    *out = SolidMode::kHiddenDashed;
  else
    return false;
  return true;
}

std::string qi_text(int32_t halves) {
  if (halves == kQiUnknown) return "?";
  return std::to_string(halves / 2) + (halves % 2 != 0 ? ".5" : "");
}

ModeDrawing make_mode_drawing(const SolidRun& run, const ModeSpec& spec) {
  ModeDrawing d;
  auto add = [&](const SolidPiece& p, bool contour_diagonal) {
    if (spec.mode == SolidMode::kAll && contour_diagonal) return;  // not an input edge
    const Edge3& e = run.edges[p.edge];
    if (!p.hidden) {
      d.spans.push_back(make_span(e, p.edge, p.t0, p.t1));
      d.qi.push_back(p.q);
      return;
    }
    if (spec.mode == SolidMode::kAll && !contour_diagonal) {
      d.spans.push_back(make_span(e, p.edge, p.t0, p.t1));
      d.qi.push_back(p.q);
    } else if (spec.mode == SolidMode::kHiddenDashed && !contour_diagonal) {
      // Dashes measured along the piece from its start, in Q0.32 of this edge.
      const int64_t len = paper_length(e);
      const int64_t dash = (int64_t(spec.dash_steps) << 32) / len + 1;
      const int64_t period = dash + (int64_t(spec.gap_steps) << 32) / len;
      for (int64_t t = p.t0; t < p.t1; t += period) {
        const int64_t end = t + dash < p.t1 ? t + dash : p.t1;
        d.spans.push_back(make_span(e, p.edge, t, end));
        d.qi.push_back(p.q);
      }
    }
  };
  for (const SolidPiece& p : run.pieces) add(p, false);
  for (const SolidPiece& p : run.contour_diagonals) add(p, true);
  if (spec.outline)
    for (const OutlineSegment& o : run.outline)
      d.outline.push_back(make_span(run.edges[o.edge], o.edge, o.t0, o.t1));
  return d;
}

}  // namespace haloplot::host
