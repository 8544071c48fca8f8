// plot and sim of a scene with Bézier edges (docs/curves.md): the curve stages of the core
// (curve/curve_cross.h, curve/curve_draw.h) instead of CUT and DRAW; the drawing's chords are
// then planned as any drawing's strokes. A scene without Bézier records never comes here: the
// straight-edge path is unchanged. The commands themselves, cmd_plot_curves and cmd_demo_curve,
// are declared in cli/commands.h.
#pragma once
#include <string>
#include <vector>

#include "cli/options.h"
#include "haloplot/geometry/contract.h"
#include "haloplot/job/job.h"
#include "io/edges_file.h"

namespace haloplot::host {

// True when `path` is an .edges file with a line starting with the word 'bezier'; anything else
// (a model, a file that does not open) is left to the straight path.
bool edges_file_has_curves(const std::string& path);

// A job's curve scene for the core's curve job (job/job.h job_prepare_curves), which `sim` and
// `send` (the controller) run alike, whole or (with the job's arena) in bands: read, with the
// job's settings checked (haloed, the paper's gap). False with *error saying what is wrong.
bool load_curve_job(const std::string& scene_path, const JobSpec& spec, EdgesWithCurves* scene,
                    int32_t* substep_bits, std::string* error);

}  // namespace haloplot::host
