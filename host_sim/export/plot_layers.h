// A plot as pen layers: each kind of line (visible edges, hidden dashes, intersection lines,
// hatching, outlines) planned on its own by the core's path planner (motion/path_plan.h: the
// same joins and order the controller and the G-code use), so a pen change between layers
// never mixes kinds. The SVG writes each layer as an Inkscape layer, one subpath per pen-down
// stroke; the joined path is what a G-code or HPGL of the same plot draws.
#pragma once
#include <string>
#include <vector>

#include "haloplot/draw/draw.h"
#include "haloplot/motion/path_plan.h"
#include "pipeline/drawing_modes.h"

namespace haloplot::host {

struct StrokeLayer {
  std::string label;        // "1 visible", ...: the AxiDraw extension plots layer N by its number
  std::vector<Span> spans;  // in whole steps
  double pen_width = 1;     // times --pen-width in the SVG (outlines: a wider pen)
};

struct PlannedLayer {
  std::string label;
  std::vector<PathPoint> path;  // pen-up travel and pen-down strokes, plot steps
  double pen_width = 1;
  int32_t start_x = 0, start_y = 0;  // where the pen is before path[0]
};

// Plans each non-empty layer, in order, the first from (0, 0) (where the controller's job
// starts), each next from where the previous one ended: the path the controller's job plans
// for the same strokes, layer by layer (motion/path_plan.h plan_path_layers).
// A planner failure (a coordinate out of its range) is returned as its status.
// `clean`: the planner's clean-up; *stats (may be null): the layers' path stats added up.
Status plan_layers(const std::vector<StrokeLayer>& layers, std::vector<PlannedLayer>* out,
                   PathClean clean = PathClean{}, PathStats* stats = nullptr);

// The same layers cut from the path a job planned for their strokes, grouped layer by layer
// (pipeline/drawing_modes.h mode_strokes, then motion/path_plan.h plan_path_layers, as `sim` plans
// it): what plan_layers() would plan again, without planning it twice. `layer_points`: the points
// each layer took. False (and *out empty) when the counts do not fit the layers.
bool cut_planned_layers(const std::vector<StrokeLayer>& layers,
                        const std::vector<PathPoint>& points, const LayerCounts& layer_points,
                        std::vector<PlannedLayer>* out);

// The layers' paths one after the other: the plot as one pen path (for G-code or HPGL).
std::vector<PathPoint> joined_path(const std::vector<PlannedLayer>& layers);

// The layers of a hidden-line drawing (by ModeDrawing::kind), then hatching and outlines.
std::vector<StrokeLayer> mode_layers(const ModeDrawing& d);

// A layer's number is the one its label starts with ("3 intersections": 3; 0 if none): the
// SVG layer's id (layer3), the HPGL pen (SP3) and the G-code's pen-change comment, so a layer
// is the same pen in every file whichever layers before it are empty.
int layer_number(const std::string& label);
// Its stroke colour in the SVG, a palette apart in print and for the common colour-blindnesses
// (after Okabe and Ito): 1 visible black, 2 hidden blue, 3 intersections vermilion, 4 hatching
// bluish green, 5 outlines dark purple; black outside it.
const char* layer_colour(int number);

}  // namespace haloplot::host
