// plot --gcode OUT.gcode --hpgl OUT.hpgl: the plotter outputs of the drawing `plot` makes, from
// the path the job `sim` would run for it, planned and not stepped (export/plotter_outputs.h),
// with the plot time estimated on stderr.
#pragma once
#include <string>
#include <vector>

#include "cli/options.h"
#include "export/exporters.h"
#include "job/job.h"

namespace haloplot::host {

// The options `plot` takes for its plotter outputs (valued).
extern const char* const kPlotterOutputOptions[2];

bool wants_plotter_outputs(const Options& o);

// The exporters' style from the options (--steps-per-mm), and the machine the plot time is
// estimated for. False with *error naming the option.
bool export_style_of(const Options& o, ExportStyle* style, Machine* machine, std::string* error);

// Plans the job's path for these edges, writes the G-code and HPGL the options name and says
// on stderr how long the plot takes. Returns 0 or 1 after reporting.
int write_plot_outputs(const Options& o, const JobSpec& spec, const std::vector<Edge3>& edges,
                       const ExportStyle& style);

}  // namespace haloplot::host
