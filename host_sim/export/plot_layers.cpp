#include "export/plot_layers.h"

#include <cstddef>
#include <cstdint>

namespace haloplot::host {

Status plan_layers(const std::vector<StrokeLayer>& layers, std::vector<PlannedLayer>* out,
                   PathClean clean, PathStats* sum) {
  out->clear();
  if (sum != nullptr) *sum = PathStats{};
  int32_t x = 0, y = 0;
  for (const StrokeLayer& l : layers) {
    if (l.spans.empty()) continue;
    const uint32_t n = uint32_t(l.spans.size());
    std::vector<Segment2> segs(n);
    for (uint32_t i = 0; i < n; ++i)
      segs[i] = Segment2{l.spans[i].x0, l.spans[i].y0, l.spans[i].x1, l.spans[i].y1};
    std::vector<uint64_t> work((path_plan_bytes(n) + 7) / 8 + 1);
    PlannedLayer p{l.label, std::vector<PathPoint>(path_points_max(n)), l.pen_width, x, y};
    uint32_t count = 0;
    PathStats stats;
    const Status s =
        plan_path(segs.data(), n, PenAt{x, y}, work.data(), work.size() * 8, p.path.data(),
                  uint32_t(p.path.size()), &count, &stats, PathEnd{}, clean);
    if (!ok(s)) return s;
    if (sum != nullptr) add_path_stats(sum, stats);
    if (count == 0) continue;  // every stroke cleaned away: no layer in the files
    p.path.resize(count);
    if (!p.path.empty()) x = p.path.back().x, y = p.path.back().y;
    out->push_back(std::move(p));
  }
  return Status::kOk;
}

bool cut_planned_layers(const std::vector<StrokeLayer>& layers,
                        const std::vector<PathPoint>& points, const LayerCounts& layer_points,
                        std::vector<PlannedLayer>* out) {
  out->clear();
  if (layers.size() != layer_points.n) return false;
  size_t first = 0;
  int32_t x = 0, y = 0;
  for (size_t k = 0; k < layers.size(); ++k) {
    const size_t count = layer_points.count[k];
    // A layer without strokes plans to nothing (one with strokes may too: all cleaned away).
    if ((layers[k].spans.empty() && count > 0) || count > points.size() - first) {
      out->clear();
      return false;
    }
    if (count == 0) continue;
    const auto begin = points.begin() + std::ptrdiff_t(first);
    out->push_back(PlannedLayer{layers[k].label,
                                std::vector<PathPoint>(begin, begin + std::ptrdiff_t(count)),
                                layers[k].pen_width, x, y});
    first += count;
    x = points[first - 1].x, y = points[first - 1].y;
  }
  if (first == points.size()) return true;
  out->clear();
  return false;
}

std::vector<PathPoint> joined_path(const std::vector<PlannedLayer>& layers) {
  std::vector<PathPoint> all;
  for (const PlannedLayer& l : layers) all.insert(all.end(), l.path.begin(), l.path.end());
  return all;
}

std::vector<StrokeLayer> mode_layers(const ModeDrawing& d) {
  // The job's layers (pipeline/drawing_modes.h layer_spans), so G-code and SVG agree.
  std::vector<std::vector<Span>> spans = layer_spans(d);
  // Moved in one by one (a braced list would copy every span).
  static const char* const kLabels[5] = {"1 visible", "2 hidden", "3 intersections", "4 hatching",
                                         "5 outlines"};
  std::vector<StrokeLayer> layers;
  layers.reserve(5);
  for (size_t k = 0; k < 5; ++k)
    layers.push_back(StrokeLayer{kLabels[k], std::move(spans[k]), k == 4 ? 2.5 : 1});
  return layers;
}

int layer_number(const std::string& label) {
  int n = 0;
  for (size_t i = 0; i < label.size() && i < 4 && label[i] >= '0' && label[i] <= '9'; ++i)
    n = n * 10 + (label[i] - '0');
  return n;
}

const char* layer_colour(int number) {
  static const char* const kPalette[5] = {"#000000", "#0072b2", "#d55e00", "#009e73", "#6a3d9a"};
  return number >= 1 && number <= 5 ? kPalette[number - 1] : "#000000";
}

}  // namespace haloplot::host
