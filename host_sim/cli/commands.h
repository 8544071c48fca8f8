// Every command of the haloplot tool, one file each (cli/cmd_<name>.cpp), and its usage lines
// (cli/usage.cpp). main.cpp's table pairs each name with these; a command's run function reads
// its options from argv[2] on and returns the exit code, having said on stderr why it failed.
// The only place a cmd_ function is declared (tests/rules/cli_layout.sh keeps it so).
#pragma once
#include "cli/options.h"

namespace haloplot::host {

// The lines of `haloplot --help` that give each command, in the order it lists them: a
// command's --help prints its own after "usage:\n".
extern const char* const kDemoSceneUsage;
extern const char* const kRandomSceneUsage;
extern const char* const kCutUsage;
extern const char* const kDrawUsage;
extern const char* const kPlotUsage;
extern const char* const kSimUsage;
extern const char* const kReplayUsage;
extern const char* const kSendUsage;
extern const char* const kView2dUsage;

int cmd_demo_scene(int argc, char** argv);
int cmd_random_scene(int argc, char** argv);
int cmd_cut(int argc, char** argv);
int cmd_draw(int argc, char** argv);
int cmd_plot(int argc, char** argv);
int cmd_sim(int argc, char** argv);
int cmd_replay(int argc, char** argv);
int cmd_send(int argc, char** argv);
int cmd_view2d(int argc, char** argv);

// The forms of plot and demo-scene carried out in files of their own, once their command has
// parsed the options:
// `plot MODEL --mode all|hidden-removed|hidden-dashed ...`, the hidden lines of a solid model.
int cmd_plot_solid(const Options& o);
// `plot SCENE.edges --halo W ...` of a scene with Bézier edges: SVG, --spans, --gcode, --hpgl.
int cmd_plot_curves(const Options& o);
// `demo-scene --curve trefoil|torus-P-Q|helix [--edges N] -o SCENE.edges`: the demo curve
// scenes (demo/curve_scenes.h) as an .edges file with 'bezier' records, sized for an A4 page.
int cmd_demo_curve(const Options& o);

}  // namespace haloplot::host
