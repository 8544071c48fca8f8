// The HALO paper's Figure 1 drawing modes for solid models, from the hidden-line pieces, by
// the core's strokes (solid/modes.h, the same the controller draws); haloed lines are not
// here: HALO needs no faces (CUT and DRAW on the edges).
// --outline adds Kira's outlines as a second pass (a second pen, or the same pen again).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "haloplot/draw/draw.h"
#include "haloplot/motion/path_plan.h"
#include "haloplot/solid/modes.h"
#include "pipeline/solid_pipeline.h"

namespace haloplot::host {

struct ModeSpec {
  SolidMode mode = SolidMode::kHiddenRemoved;
  int32_t dash_steps = 160, gap_steps = 80;  // 2 mm and 1 mm at 80 steps/mm
  bool outline = false;
  bool intersections = true;  // the visible parts of the lines where faces cross
};

// What a first-pen span draws: a visible piece (a contour diagonal too), a hidden one (a dash,
// or a whole hidden edge in mode all), or a visible part of a line where faces cross.
enum class LineKind : uint8_t { kVisible = 0, kHidden = 1, kIntersection = 2 };

struct ModeDrawing {
  std::vector<Span> spans;     // first pen, in edge order then along each edge
  std::vector<int32_t> qi;     // QI of each span, in halves (kQiUnknown when not counted)
  std::vector<LineKind> kind;  // of each span (the SVG's layers)
  std::vector<Span> outline;   // second pass
  std::vector<Span> hatch;     // hatching of the visible faces (Span::edge = polygon)
};

// "all", "hidden-removed", "hidden-dashed"; false for anything else.
bool parse_solid_mode(const std::string& s, SolidMode* out);

ModeDrawing make_mode_drawing(const SolidRun& run, const ModeSpec& spec);

// The drawing's strokes by layer (motion/path_plan.h LayerCounts, the plot SVG's layers):
// visible pieces, hidden dashes, intersection lines (each in the first pen's order), the
// hatching, then the outline pass.
std::vector<std::vector<Span>> layer_spans(const ModeDrawing& d);

// The drawing's strokes as the edges a job draws whole (drawing all), layer after layer, and
// how many each layer has (*layers, may be null): a hidden-line job and `plot --gcode` plan
// these one layer after the other, as the controller's job plans the same strokes.
std::vector<Edge3> mode_strokes(const ModeDrawing& d, LayerCounts* layers = nullptr);

}  // namespace haloplot::host
