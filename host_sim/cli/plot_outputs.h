// plot --gcode OUT.gcode --hpgl OUT.hpgl: the plotter outputs of the drawing `plot` makes, from
// the path the job `sim` would run for it, planned and not stepped (export/plotter_outputs.h),
// with the plot time estimated on stderr.
#pragma once
#include <string>
#include <vector>

#include "cli/options.h"
#include "export/exporters.h"
#include "export/plotter_outputs.h"
#include "haloplot/job/job.h"

namespace haloplot::host {

// The options `plot` takes for its plotter outputs (valued).
extern const char* const kPlotterOutputOptions[2];

bool wants_plotter_outputs(const Options& o);

// The G-code's pen profile and feeds (valued): --pen servo|z|custom, --servo-down S,
// --z-up MM, --z-down MM, --z-feed MM/MIN, --pen-up-gcode TEXT, --pen-down-gcode TEXT,
// --draw-feed MM/MIN, --travel-feed MM/MIN, --pen-dwell SECONDS, --gcode-flavor grbl|marlin,
// --servo-up ANGLE (marlin), --gcode-header TEXT, --gcode-footer TEXT. A job file takes the
// same as keys without the dashes.
extern const char* const kPenOptions[14];

// The exporters' style from the options (the pen profile, the feeds, --steps-per-mm), and the
// machine's speeds and pen dwell set from them. `dashes`: how the options are named in
// messages ("--" on the command line, "" in a job file). False with *error naming the option.
bool export_style_of(const Options& o, ExportStyle* style, Machine* machine, std::string* error,
                     const std::string& dashes = "--");

// Plans the job's path for these edges, writes the G-code and HPGL the options name and says
// on stderr how long the plot takes. `model`: the scene is a model the projection fitted, its
// drawing centred on the page the options give (as the SVG and `sim` place it). Returns 0 or 1
// after reporting.
int write_plot_outputs(const Options& o, const JobSpec& spec, const std::vector<Edge3>& edges,
                       ExportStyle style, bool model);
// The two halves of it, for a command that also draws its SVG from the planned path: the path
// planned (false after reporting a failure), then the files written from it.
bool plan_plot_job(const JobSpec& spec, const std::vector<Edge3>& edges, PlannedJob* planned);
int write_planned_outputs(const Options& o, const JobSpec& spec, PlannedJob planned,
                          ExportStyle style, bool model);

}  // namespace haloplot::host
