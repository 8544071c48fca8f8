// The usage lines of each command, as `haloplot --help` lists them (main.cpp joins them in
// this order) and as `haloplot CMD --help` and a refused command line print them. Continuation
// lines are indented; plot's block carries the camera and page options that follow its forms.
#include "cli/commands.h"

namespace haloplot::host {

const char* const kDemoSceneUsage =
    "  haloplot demo-scene [--cubes N] -o SCENE.edges|MODEL.obj   (.obj: the cubes as solids)\n"
    "               [--curve trefoil|torus-P-Q|helix [--edges N] [--perspective D]]   (a knot\n"
    "               or a helix as cubic Bézier edges, N of them, for plot's curve path; a knot\n"
    "               seen in perspective from D world units: docs/curves.md)\n";

const char* const kRandomSceneUsage =
    "  haloplot random-scene --edges N --length L [--seed S] -o SCENE.edges\n";

const char* const kCutUsage =
    "  haloplot cut SCENE.edges -o SCENE.cut [--lambda X] [--cell G] [--cover exact|bbox]\n"
    "               [--reach R] [--threads N] [--stats]   (--threads: CUT on N threads, the same\n"
    "               CUTSET; default every core)\n";

const char* const kDrawUsage =
    "  haloplot draw SCENE.cut --halo W [--exact-halo] -o OUT.svg [--spans OUT.spans] [--stats]\n"
    "               [--steps-per-mm N]   (plot steps per mm on the page; default 80)\n"
    "               [page options: --page, --landscape, --margin, --pen-width, --background,\n"
    "               --min-stroke, --simplify, --no-cleanup;\n"
    "               --fit and --scale place a model, and a .cut scene is in steps: refused]\n";

const char* const kPlotUsage =
    "  haloplot plot SCENE.edges|MODEL --halo W [--exact-halo] -o OUT.svg [--spans OUT.spans]\n"
    "               [--cut OUT.cut] [--arena BYTES] [--steps-per-mm N] [--stats]\n"
    "               [--lambda X] [--cell G] [--cover exact|bbox] [--reach R] [--threads N]\n"
    "               (as cut's)\n"
    "               [--view AZ,EL] [--perspective D] [--up AXIS] [--dump-edges OUT.edges]\n"
    "               [--substep S] [--weld EPS|0|off] [--crease DEG|exact|off]   (MODEL: .obj,\n"
    "               .stl or .ply; --up x|y|z|-x|-y|-z: the file's up axis, default z for STL\n"
    "               as 3-D printing writes it, y for OBJ and PLY; --substep: decide in units\n"
    "               of 2^-S steps; by default corners within the file's rounding are welded\n"
    "               and edges between faces flat but for it left out: docs/cli.md)\n"
    "  camera (any MODEL form): [--eye X,Y,Z --look-at X,Y,Z [--fov DEG]] [--roll DEG]\n"
    "               (instead of --view/--perspective: look from the eye (file coordinates)\n"
    "               toward the look-at point; --fov: in perspective, the eye backed off until\n"
    "               the model fills the field of view; --roll: the picture turned\n"
    "               counterclockwise about the view axis)\n"
    "  haloplot plot MODEL --mode all|hidden-removed|hidden-dashed -o OUT.svg [--outline]\n"
    "               [--no-intersections]   (the lines where faces cross are drawn by default)\n"
    "               [--dash LEN,GAP (mm)] [--steps-per-mm N] [--method auto|qi|fallback]\n"
    "               [--hatch SPACING[,ANGLE[,TURN]]] [--spans OUT.spans] [--view AZ,EL]\n"
    "               [--perspective D] [--up AXIS] [--substep S] [--weld EPS|0|off]\n"
    "               [--crease DEG|exact|off] [--threads N] [--stats]   (--threads: the hidden\n"
    "               lines' CUT and QI walks on N threads, the same drawing; default every\n"
    "               core)\n"
    "  haloplot plot SCENE.edges|MODEL ... [--gcode OUT.gcode] [--hpgl OUT.hpgl]   (either form\n"
    "               above: the plotter's files from the planned path, no step simulation, and\n"
    "               the plot time on stderr; the same bytes `sim` writes for the same job;\n"
    "               -o may then be left out: no SVG)\n"
    "               [--pen servo|z|custom] [--servo-down S] [--z-up MM] [--z-down MM]\n"
    "               [--z-feed MM/MIN] [--pen-up-gcode TEXT] [--pen-down-gcode TEXT]\n"
    "               [--draw-feed MM/MIN] [--travel-feed MM/MIN] [--pen-dwell SECONDS]\n"
    "               [--gcode-flavor grbl|marlin] [--servo-up ANGLE] [--gcode-header TEXT]\n"
    "               [--gcode-footer TEXT]\n"
    "               (the G-code's pen commands and feeds; TEXT: G-code, \\n between lines)\n"
    "               [--pause-between-layers]   (hidden-line modes draw layer by layer, as the\n"
    "               SVG's layers; this adds a pen change between layers: M0 in the G-code,\n"
    "               the layer's pen SP1..SP5 in the HPGL)\n"
    "  page options (plot, draw): [--page a4|a3|a5|letter|legal|tabloid|WxH] [--landscape]\n"
    "               [--margin MM] [--fit | --scale S] [--pen-width MM] [--background]\n"
    "               [--min-stroke MM] [--no-cleanup]   (strokes shorter than MM, default\n"
    "               the pen width, are not drawn, 0 keeps all; dots are never drawn and\n"
    "               collinear overlaps once; --no-cleanup: the strokes as found, for tests)\n"
    "               [--simplify MM]   (points of a stroke within MM of the line drawn\n"
    "               instead are left out: fewer, longer moves on a dense mesh; default 0)\n"
    "               (the SVG is the page, default A4 landscape, 10 mm margins; a model is\n"
    "               fitted and centred, or drawn at S mm per model unit; named pages are\n"
    "               portrait; --pen-width: stroke width, default 0.3; --background: a white\n"
    "               page rectangle, for viewing only)\n";

const char* const kSimUsage =
    "  haloplot sim JOB.job -o OUT.trace [--gcode OUT.gcode] [--hpgl OUT.hpgl] [--arena BYTES]\n"
    "               [--binary] [--stats]   (--binary: the compact binary trace)\n"
    "               [--pause-at E1,E2,...] [--resume-at E]   (feed holds; go on from event E)\n"
    "               [--threads N]   (the job's CUT, each band's too, on N threads; the same\n"
    "               plot; default every core)\n";

const char* const kReplayUsage = "  haloplot replay IN.trace -o OUT.svg [--stats]\n";

const char* const kSendUsage =
    "  haloplot send JOB.job --port PATH [--replot W] [--corrupt-every K] [--truncate-every K]\n"
    "               [--test-exit]   (upload to a controller over its serial port or socket)\n"
    "               [--pause-after EVENTS] [--stop-after EVENTS [--stop abort|limit]]\n"
    "               [--resume EVENTS] [--seed S] [--trace-digest]\n"
    "               [--reply-timeout MS]   (how long to wait for each reply before resending,\n"
    "               20 tries in all; default 3000, ample on a serial link: raise it for a\n"
    "               slow emulated controller)\n";

const char* const kView2dUsage =
    "  haloplot view2d POLYGON.txt --from X,Y -o OUT.svg [--spans OUT.spans] [--trace OUT.trace]\n"
    "               [--stats]   (which parts of a polygon are visible from a point)\n";

}  // namespace haloplot::host
