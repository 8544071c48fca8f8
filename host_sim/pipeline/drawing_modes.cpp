#include "pipeline/drawing_modes.h"

namespace haloplot::host {

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

ModeDrawing make_mode_drawing(const SolidRun& run, const ModeSpec& spec) {
  ModeDrawing d;
  // About a span a piece (dashes make more): room up front, not regrown by copying.
  const size_t pieces = run.pieces.size() + run.contour_diagonals.size() + run.intersections.size();
  d.spans.reserve(pieces);
  d.qi.reserve(pieces);
  d.kind.reserve(pieces);
  const StrokeStyle style{spec.mode, spec.dash_steps, spec.gap_steps};
  // As the core's job strokes them: a hidden run's dashes from its start, across its pieces.
  DashedRuns runs;
  auto keep = [&](const Span& s, int32_t q) {
    d.spans.push_back(s);
    d.qi.push_back(q);
    return Status::kOk;
  };
  // A piece's call first strokes the hidden run held before it (dashes), then the piece's own
  // stroke, if it makes one now (one span: a visible piece, or any piece in mode all).
  auto add = [&](const SolidPiece& p, PieceKind kind) {
    // keep() only appends (it cannot fail), so neither can the strokes.
    // The sink is this drawing's vectors, which never refuse a stroke: nothing to report.
    (void)runs.piece(run.edges[p.edge], p.edge, kind, p.t0, p.t1, p.hidden, p.q, style, keep);
    const bool all = spec.mode == SolidMode::kAll;
    const bool intersection = kind == PieceKind::kLine;
    const bool own = !(all && kind != PieceKind::kEdge) && (!p.hidden || all);
    const size_t before = d.kind.size();
    d.kind.resize(d.spans.size(), LineKind::kHidden);
    if (own && d.kind.size() > before)
      d.kind.back() = intersection ? LineKind::kIntersection
                                   : (p.hidden ? LineKind::kHidden : LineKind::kVisible);
  };
  for (const SolidPiece& p : run.pieces) add(p, PieceKind::kEdge);
  // Contour diagonals: visible parts, and in hidden-dashed their hidden parts dashed.
  for (const SolidPiece& p : run.contour_diagonals) add(p, PieceKind::kContour);
  // Intersection lines as the core's job draws them: visible parts only.
  for (const SolidPiece& p : run.intersections) add(p, PieceKind::kLine);
  (void)runs.finish(style, keep);  // keep() cannot fail
  d.kind.resize(d.spans.size(), LineKind::kHidden);
  // Hatching likewise, after them (Span::edge = the polygon).
  for (size_t k = 0; k < run.hatch.size(); ++k) {
    const SolidPiece& p = run.hatch[k];
    // The sink below only collects (always kOk): nothing to report.
    (void)piece_strokes(run.edges[p.edge], p.edge, PieceKind::kLine, p.t0, p.t1, p.hidden, style,
                        [&](Span s) {
                          s.edge = run.hatch_polygons[k];
                          d.hatch.push_back(s);
                          return Status::kOk;
                        });
  }
  if (spec.outline)
    for (const OutlineSegment& o : run.outline)
      d.outline.push_back(make_stroke(run.edges[o.edge], o.edge, o.t0, o.t1));
  return d;
}

std::vector<std::vector<Span>> layer_spans(const ModeDrawing& d) {
  std::vector<std::vector<Span>> layers(kMaxLayers);
  std::vector<size_t> count(kMaxLayers, 0);
  for (size_t i = 0; i < d.spans.size(); ++i) ++count[i < d.kind.size() ? size_t(d.kind[i]) : 0];
  for (size_t k = 0; k < kMaxLayers; ++k) layers[k].reserve(count[k]);
  for (size_t i = 0; i < d.spans.size(); ++i)
    layers[i < d.kind.size() ? size_t(d.kind[i]) : 0].push_back(d.spans[i]);
  layers[3] = d.hatch;
  layers[4] = d.outline;
  return layers;
}

std::vector<Edge3> mode_strokes(const ModeDrawing& d, LayerCounts* layers) {
  std::vector<Edge3> edges;
  LayerCounts counts;
  counts.n = kMaxLayers;
  const std::vector<std::vector<Span>> by_layer = layer_spans(d);
  size_t total = 0;
  for (const std::vector<Span>& l : by_layer) total += l.size();
  edges.reserve(total);
  for (size_t k = 0; k < by_layer.size(); ++k) {
    counts.count[k] = uint32_t(by_layer[k].size());
    for (const Span& x : by_layer[k]) edges.push_back(Edge3{{x.x0, x.y0, 0}, {x.x1, x.y1, 0}});
  }
  if (layers != nullptr) *layers = counts;
  return edges;
}

}  // namespace haloplot::host
