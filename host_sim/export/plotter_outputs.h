// A job's plotter outputs (G-code, HPGL) and its plot time, from the planned path alone: the
// core's job stage plans the path as `sim` plans it before stepping, and no motor step is
// simulated. `plot --gcode` and `sim --gcode` both write through here, so for the same job
// they write the same bytes.
#pragma once
#include <string>
#include <vector>

#include "export/exporters.h"
#include "export/page.h"
#include "haloplot/job/job.h"

namespace haloplot::host {

// The path the job plans for these edges: the core's job stage (CUT and DRAW when the drawing
// needs them, then the path planner) in a buffer sized by the stage's own query, as the
// simulator and the controller run it. *retries: runs beyond the first (a CUT that needed more
// records). The travel home is not in *points (the motion planner adds it; add_travel_home).
// With `curves` (not empty) the scene has Bézier edges and `edges` are its straight ones: the
// core's curve job (job_prepare_curves) instead of CUT and DRAW, as the controller runs it.
struct PlannedJob {
  std::vector<PathPoint> points;
  std::vector<Segment2> spans;  // what DRAW emitted
  LayerCounts layer_points;     // the points of each layer (job.h PreparedJob)
  JobCounters counters;
  JobBytes bytes;
  int retries = 0;
};
Status plan_job_path(const JobSpec& spec, const std::vector<Edge3>& edges, PlannedJob* out,
                     const std::vector<BezierEdge3>* curves = nullptr);

// The travel home as the path's last point when the job ends at the origin (spec.finish_home)
// and the path does not end there already: the exporters' G-code and HPGL end where the plot does.
void add_travel_home(const JobSpec& spec, std::vector<PathPoint>* points);

// How long the plot of `points` (without the travel home) takes by the motion planner's own
// model: its committed moves (entry, top and exit speeds, the junction speeds between them) as
// trapezoids, as the step generator times them, plus the pen dwells; no step is made. The
// travel home is included when the job asks for it. A step simulation's end time differs from
// this by the timing of whole steps only (tests/cli/plot_gcode.sh bounds the difference).
double estimate_plot_seconds(const JobSpec& spec, const std::vector<PathPoint>& points);

// A model's drawing centred on the page as the plot's SVG centres it (export/page.h): the
// style's offset from the path's pen-down box, and a travel home (the path's last point, pen up
// at the origin, when the job ends there) moved to the paper's origin, where the plotter began.
void centre_on_page(const Page& page, bool finish_home, std::vector<PathPoint>* points,
                    ExportStyle* style);

// What the plotter's files draw, read off the path as they write it (after add_travel_home and
// centre_on_page): the pen-downs, and the lengths pen down and pen up in plot steps, the pen-up
// travel starting at the paper's origin (where the plotter starts: the path's point minus the
// style's offset) and ending with the trip home. The planner's own PathStats count the strokes
// before consecutive ones that meet are drawn as one and its travel from the unplaced origin.
struct WrittenFigures {
  uint32_t strokes = 0;
  double pen_down = 0, pen_up = 0;
};
WrittenFigures written_figures(const std::vector<PathPoint>& points, const ExportStyle& style);

// The plot's time as the files move it: estimate_plot_seconds() of the path in paper
// coordinates, from the paper's origin, its travel home (if any) left to the motion planner.
double written_plot_seconds(const JobSpec& spec, const std::vector<PathPoint>& points,
                            const ExportStyle& style);

// The line stderr gives for the files: "haloplot: plot time about M min SS s (S s by the
// motion planner's model); N strokes, pen down D mm, pen up U mm" (from an hour on, "H h MM
// min SS s"; "1 stroke"), from written_figures and written_plot_seconds, so `plot` and `sim`
// (whole or in bands) say what their files draw.
std::string written_summary(const JobSpec& spec, const std::vector<PathPoint>& points,
                            const ExportStyle& style);

// Writes the G-code to `gcode_path` and the HPGL to `hpgl_path` (each when not empty), through
// the command's output set (io/atomic_file.h), with the path's layers (pen changes between
// them when the style asks). "" or the error.
std::string write_plotter_outputs(const std::string& gcode_path, const std::string& hpgl_path,
                                  const std::vector<PathPoint>& points, const Machine& m,
                                  const ExportStyle& style, const LayerCounts& layers);

}  // namespace haloplot::host
