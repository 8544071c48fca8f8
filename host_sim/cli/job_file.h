// The .job file: what `haloplot sim` plots and how. One "key value..." per line, '#' comments.
//
//   scene demo.edges          the scene, relative to the job file's folder (required)
//   drawing haloed            all | haloed | hidden-removed | hidden-dashed (the last two need
//                             an .obj scene with faces; hatch arrives with hidden surfaces)
//   view 30,25                for an .obj scene: azimuth,elevation in degrees (README)
//   perspective 1500000       for an .obj scene: eye distance (default orthographic)
//   dash 2 1                  hidden-dashed: dash and gap in mm
//   outline on                hidden-line modes: redraw Kira's outlines in a second pass
//   intersections off         hidden-line modes: leave out the lines where faces cross (on
//                             by default)
//   method auto               hidden-line method: auto | qi | fallback
//   hatch 1.5 45 90           hidden-line modes: hatch the visible faces, spacing in mm, angle
//                             and the turn across the depth range in degrees
//   halo 50                   halo width, plot steps
//   halo-mode paper           paper | exact
//   effects acceleration pen-servo    plotter effects to simulate: any of acceleration,
//                             pen-servo, backlash; or "none"
//   kinematics corexy         cartesian | corexy
//   steps 1/1                 motor steps per plot step
//   tick-hz 1000000   min-interval 25   max-step-rate 25000
//   draw-speed 6000   travel-speed 12000   accel 60000   junction-deviation 4
//   pen-travel-ticks 150000   pen-settle-ticks 50000   backlash 0 0
//   steps-per-mm 80           for the G-code and HPGL exporters
//   pause-between-layers on   hidden-line drawings: a pen change between the layers in the
//                             G-code (M0) and HPGL (SPn); not with an arena
//   pen servo                 the G-code's pen: servo | z | custom, with servo-down S, z-up MM,
//                             z-down MM, z-feed MM/MIN, pen-up-gcode TEXT, pen-down-gcode TEXT
//   draw-feed 4500            feeds in mm/min (instead of draw-speed, travel-speed), and
//   travel-feed 9000          pen-dwell SECONDS (instead of pen-travel-ticks): as `plot` takes
//   page a4                   the paper (export/page.h): a4 | a3 | a5 | letter | legal |
//                             tabloid | WxH in mm; default A4 landscape
//   landscape on              the page's longer side across (on | off)
//   margin 10                 mm on every side of the page (default 10)
//   scale fit                 a model: fit and centre it on the page (the default), or S mm on
//                             paper per unit of the model file
//   arena 65536               plot in bands in a job arena of this many bytes, as a controller
//                             with that arena does (haloed and all; default: one band); `send`
//                             then streams the scene band by band
#pragma once
#include <map>
#include <string>

#include "export/exporters.h"
#include "haloplot/job/job.h"
#include "io/input_error.h"

namespace haloplot::host {

struct JobFile {
  std::string scene_path;
  JobSpec spec;
  ExportStyle style;
  // Hidden-line settings, as the plot command's options (--mode, --view, --dash, ...): the
  // simulator hands them to the same parser.
  std::map<std::string, std::string> solid_options;
  // The G-code's pen profile and feeds, as the plot command's options (--pen, --z-up, ...).
  std::map<std::string, std::string> pen_options;
  bool no_cleanup = false;  // `cleanup off`
  bool outline = false;
  bool intersections = true;
  bool landscape = false;  // `landscape on` (the page options are kept in solid_options)
  uint32_t arena = 0;      // bytes; 0: the whole scene in one job buffer
};

InputError read_job_file(const std::string& path, JobFile* out);

}  // namespace haloplot::host
