#include "cli/job_file.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>

#include "cli/options.h"
#include "cli/page_options.h"
#include "cli/plot_outputs.h"
#include "cli/scene_input.h"
#include "cli/solid_options.h"
#include "io/line_reader.h"
#include "io/mesh_file.h"

namespace haloplot::host {
namespace {

// Every key a job file may hold, with the form of its value (for the message when a value is
// malformed, and for a suggestion when a key is misspelt).
const std::map<std::string, std::string> kKeys = {
    {"scene", "FILE (.edges, .obj, .stl or .ply)"},
    {"drawing", "all | haloed | hidden-removed | hidden-dashed"},
    {"hatch", "SPACING ANGLE TURN (mm, degrees)"},
    {"view", "AZ,EL (degrees)"},
    {"perspective", "D (world units)"},
    {"substep", "S (sub-step bits for an .obj scene)"},
    {"up", "x | y | z | -x | -y | -z (the model file's up axis)"},
    {"eye", "X,Y,Z (a camera, with look-at; the model file's units)"},
    {"look-at", "X,Y,Z (where the camera looks)"},
    {"fov", "DEG (a perspective camera's field of view)"},
    {"roll", "DEG (the picture turned about the view axis)"},
    {"weld", "EPS | off (weld a model's vertices within EPS)"},
    {"crease", "DEG | off (edges between faces within DEG drawn only as contours)"},
    {"method", "auto | qi | fallback"},
    {"dash", "DASH GAP (mm)"},
    {"outline", "on | off"},
    {"intersections", "on | off"},
    {"halo", "W (steps)"},
    {"halo-mode", "paper | exact"},
    {"effects", "acceleration pen-servo backlash | none"},
    {"finish", "home | stay"},
    {"cleanup", "on | off (off: dots and overlaps plotted as found, for tests)"},
    {"kinematics", "cartesian | corexy"},
    {"steps", "N/D (motor steps per plot step)"},
    {"backlash", "A B (motor steps)"},
    {"tick-hz", "HZ"},
    {"min-interval", "TICKS"},
    {"max-step-rate", "STEPS/S"},
    {"draw-speed", "STEPS/S"},
    {"travel-speed", "STEPS/S"},
    {"accel", "STEPS/S^2"},
    {"junction-deviation", "STEPS"},
    {"pen-travel-ticks", "TICKS"},
    {"pen-settle-ticks", "TICKS"},
    {"arena", "BYTES"},
    {"steps-per-mm", "STEPS"},
    {"min-stroke", "MM (strokes shorter are not drawn; default 0.3, 0: all drawn)"},
    {"simplify",
     "MM (points of a stroke within MM of the line drawn left out; default 0: all kept)"},
    {"pen", "servo | z | custom (the G-code's pen commands)"},
    {"servo-down", "S (the M3 S value; marlin: the M280 angle, 0 to 180)"},
    {"servo-up", "ANGLE (marlin: the M280 angle with the pen up)"},
    {"z-up", "MM"},
    {"z-down", "MM"},
    {"z-feed", "MM/MIN"},
    {"pen-up-gcode", "TEXT (G-code lines, \\n between them)"},
    {"pen-down-gcode", "TEXT (G-code lines, \\n between them)"},
    {"draw-feed", "MM/MIN"},
    {"travel-feed", "MM/MIN"},
    {"pen-dwell", "SECONDS"},
    {"gcode-flavor", "grbl | marlin (G4 P in seconds or milliseconds, the servo's commands)"},
    {"gcode-header", "TEXT (G-code lines after G90, \\n between them)"},
    {"gcode-footer", "TEXT (G-code lines before the end, \\n between them)"},
    {"pause-between-layers", "on | off (a pen change between layers: M0 in G-code, SPn in HPGL)"},
    {"page", "a4 | a3 | a5 | letter | legal | tabloid | WxH (mm)"},
    {"landscape", "on | off"},
    {"margin", "MM"},
    {"scale", "fit | S (mm on paper per model unit)"},
};

// What is wrong with a line whose key no branch took.
std::string unknown_or_malformed(const std::vector<std::string>& f) {
  const std::string& key = f[0];
  auto it = kKeys.find(key);
  if (it != kKeys.end()) {
    std::string value;
    for (size_t i = 1; i < f.size(); ++i) value += (i > 1 ? " " : "") + f[i];
    return key + " takes " + it->second + ", not '" + excerpt(value) + "'";
  }
  std::vector<std::string> keys;
  for (const auto& kv : kKeys) keys.push_back(kv.first);
  const std::string best = nearest(key, keys);
  return "unknown setting '" + excerpt(key) + "'" +
         (best.empty() ? "" : " (did you mean '" + best + "'?)");
}

// Why validate() refused the machine, by the settings that broke it, and the line of the one
// most to blame (0 when none was set in the file).
InputError machine_problem(const std::string& path, const Machine& m, Status s,
                           const std::map<std::string, int>& lines) {
  auto at = [&](std::initializer_list<const char*> keys) {
    int line = 0;
    for (const char* k : keys) {
      auto it = lines.find(k);
      if (it != lines.end() && it->second > line) line = it->second;
    }
    return line;
  };
  const std::string ratio = std::to_string(m.steps_num) + "/" + std::to_string(m.steps_den);
  if (s == Status::kStepRateExceeded) {
    const uint32_t fastest = std::max(m.draw_speed, m.travel_speed);
    const double motor = double(fastest) * m.steps_num / m.steps_den *
                         (m.kinematics == Kinematics::kCoreXY ? 1.4142135623730951 : 1.0);
    return {path, at({"steps", "draw-speed", "travel-speed", "max-step-rate", "kinematics"}),
            "a speed of " + std::to_string(fastest) + " steps/s at steps " + ratio +
                (m.kinematics == Kinematics::kCoreXY ? " on CoreXY (x sqrt 2)" : "") + " needs " +
                std::to_string(int64_t(motor)) + " motor steps/s, above max-step-rate " +
                std::to_string(m.max_step_rate)};
  }
  if (s == Status::kTimerFloor)
    return {path, at({"max-step-rate", "min-interval", "tick-hz"}),
            "max-step-rate " + std::to_string(m.max_step_rate) + " needs steps " +
                std::to_string(m.tick_hz / std::max<uint32_t>(m.max_step_rate, 1)) +
                " ticks apart at tick-hz " + std::to_string(m.tick_hz) + ", below min-interval " +
                std::to_string(m.min_interval)};
  if (m.steps_num > 16 * m.steps_den || 64 * m.steps_num < m.steps_den)
    return {path, at({"steps"}),
            "steps " + ratio + ": the motor steps per plot step must lie in [1/64, 16]"};
  return {path, 0, std::string("machine settings rejected: ") + status_name(s)};
}

// One line of a job file: its fields, and where to report a problem with it.
struct JobLine {
  const std::string& path;
  int line;
  const std::vector<std::string>& f;

  InputError bad(const std::string& what) const { return {path, line, what}; }
  // The line's one value, an integer in [lo, hi]; *dst is left alone when it is not one.
  bool number(int64_t lo, int64_t hi, uint32_t* dst) const {
    int64_t v;
    if (f.size() != 2 || !parse_int(f[1], lo, hi, &v)) return false;
    *dst = uint32_t(v);
    return true;
  }
  bool on_off() const { return f.size() == 2 && (f[1] == "on" || f[1] == "off"); }
};

// The settings whose value is one bounded integer: where each goes, and what to say when the
// value is missing or out of range.
struct NumberSetting {
  const char* key;
  int64_t lo, hi;
  uint32_t* (*field)(JobFile*);
  const char* wrong;
};
const NumberSetting kNumberSettings[] = {
    {"tick-hz", 1, 16000000, [](JobFile* j) { return &j->spec.machine.tick_hz; },
     "tick-hz in [1, 16000000]"},
    {"min-interval", 1, 1000000, [](JobFile* j) { return &j->spec.machine.min_interval; },
     "min-interval in [1, 1000000] ticks"},
    {"max-step-rate", 1, 10000000, [](JobFile* j) { return &j->spec.machine.max_step_rate; },
     "max-step-rate in [1, 10000000]"},
    {"draw-speed", 1, 65535, [](JobFile* j) { return &j->spec.machine.draw_speed; },
     "draw-speed in [1, 65535] steps/s"},
    {"travel-speed", 1, 65535, [](JobFile* j) { return &j->spec.machine.travel_speed; },
     "travel-speed in [1, 65535] steps/s"},
    {"accel", 1, 4194303, [](JobFile* j) { return &j->spec.machine.accel; },
     "accel in [1, 4194303] steps/s^2"},
    {"junction-deviation", 0, 65535, [](JobFile* j) { return &j->spec.machine.junction_deviation; },
     "junction-deviation in [0, 65535] steps"},
    {"pen-travel-ticks", 0, 100000000, [](JobFile* j) { return &j->spec.machine.pen_travel_ticks; },
     "pen-travel-ticks in [0, 10^8]"},
    {"pen-settle-ticks", 0, 100000000, [](JobFile* j) { return &j->spec.machine.pen_settle_ticks; },
     "pen-settle-ticks in [0, 10^8]"},
    {"arena", 1024, 1 << 30, [](JobFile* j) { return &j->arena; },
     "arena needs the controller's job arena in bytes, in [1024, 2^30]"},
    {"steps-per-mm", 1, 100000, [](JobFile* j) { return &j->style.steps_per_mm; },
     "steps-per-mm in [1, 100000]"},
};

// drawing all | haloed | hidden-removed | hidden-dashed (the hidden-line ones also set the
// solid drawing's --mode).
InputError read_drawing(const JobLine& l, JobFile* out) {
  const std::string& v = l.f[1];
  if (v == "all") {
    out->spec.drawing = DrawingEffect::kAllEdges;
  } else if (v == "haloed") {
    out->spec.drawing = DrawingEffect::kHaloed;
  } else if (v == "hidden-removed" || v == "hidden-dashed") {
    out->spec.drawing =
        v == "hidden-removed" ? DrawingEffect::kHiddenRemoved : DrawingEffect::kHiddenDashed;
    out->solid_options["--mode"] = v;
  } else if (v == "hatch") {
    return l.bad(
        "hatching is the setting 'hatch SPACING ANGLE TURN' with drawing hidden-removed or "
        "hidden-dashed");
  } else {
    return l.bad("drawing must be all, haloed, hidden-removed or hidden-dashed, not '" +
                 excerpt(v) + "'");
  }
  return {};
}

// hatch SPACING [ANGLE [TURN]]: kept as the plot command's --hatch, checked here so a bad
// value is reported with its line.
InputError read_hatch(const JobLine& l, JobFile* out) {
  std::string v = l.f[1];
  for (size_t k = 2; k < l.f.size(); ++k) v += "," + l.f[k];
  out->solid_options["--hatch"] = v;
  Options o;
  o.values = out->solid_options;
  SolidOptions so;
  std::string error;
  if (!parse_solid_options(o, &so, &error)) return l.bad(error);
  return {};
}

bool is_view_setting(const std::string& key) {
  return key == "view" || key == "perspective" || key == "method" || key == "dash" || key == "up" ||
         key == "substep" || key == "weld" || key == "crease" || key == "page" || key == "margin" ||
         key == "scale" || key == "eye" || key == "look-at" || key == "fov" || key == "roll";
}

// The G-code's pen profile and feeds (cli/plot_outputs.h kPenOptions), checked together once
// the whole file is read.
bool is_pen_setting(const std::string& key) {
  if (key == "min-stroke" || key == "simplify")
    return true;  // in mm: steps once steps-per-mm is known, as these
  for (const char* option : kPenOptions)
    if (key == option + 2) return true;
  return false;
}

// The pen settings into the exporters' style and the machine (the feeds set its speeds).
InputError read_pen_settings(const std::string& path, const std::map<std::string, int>& key_lines,
                             JobFile* out) {
  for (const auto& [ours, theirs] : {std::pair<const char*, const char*>{"draw-feed", "draw-speed"},
                                     {"travel-feed", "travel-speed"},
                                     {"pen-dwell", "pen-travel-ticks"}})
    if (key_lines.count(ours) != 0 && key_lines.count(theirs) != 0)
      return {path, key_lines.at(ours),
              std::string(ours) + " and " + theirs + " set the same thing: give one"};
  Options o;
  o.values = out->pen_options;
  if (out->no_cleanup) o.flags.insert("--no-cleanup");
  o.values["--steps-per-mm"] = std::to_string(out->style.steps_per_mm);
  std::string error;
  // The clean-up as `plot` sets it: the pen's 0.3 mm unless the job says.
  if (export_style_of(o, &out->style, &out->spec.machine, &error, "") &&
      parse_path_clean(o, out->style.steps_per_mm, &out->spec.clean, &error))
    return {};
  int line = 0;
  for (const auto& [key, at] : key_lines)
    if (is_pen_setting(key) && error.rfind(key + " ", 0) == 0) line = at;
  return {path, line, error};
}

// view, perspective, method, dash, up, substep: kept as the plot command's options.
InputError read_view_setting(const JobLine& l, JobFile* out) {
  const std::string& key = l.f[0];
  if (key == "scale" && l.f[1] == "fit")
    out->solid_options.erase("--scale");
  else
    out->solid_options["--" + key] = key == "dash" ? l.f[1] + "," + l.f[2] : l.f[1];
  // Checked here, so a bad value is reported with its line.
  Options o;
  o.values = out->solid_options;
  if (out->landscape) o.flags.insert("--landscape");
  // A camera's keys come in any order (eye before look-at): they are checked together once
  // the file is read (check_camera); here only their own values.
  for (const char* camera : {"--eye", "--look-at", "--fov"}) o.values.erase(camera);
  SolidOptions so;
  View view;
  std::string error;
  UpAxis up;
  double fov = 0, point[3] = {0, 0, 0};
  Options own;
  own.values["--fov"] = key == "fov" ? l.f[1] : "";
  if ((key == "eye" || key == "look-at") &&
      std::sscanf(l.f[1].c_str(), "%lf,%lf,%lf", &point[0], &point[1], &point[2]) != 3)
    return l.bad(key + " '" + l.f[1] + "' must be X,Y,Z (numbers, the model file's units)");
  if (!parse_solid_options(o, &so, &error) || !parse_view(o, &view, &error) ||
      !parse_up(o, &up, &error) || !camera_fov(own, &fov, &error))
    return l.bad(error);
  return {};
}

// The camera keys together (eye with look-at, neither with view or perspective, fov only with
// them), reported at the line of the key named first in the message.
InputError check_camera(const std::string& path, const std::map<std::string, int>& key_lines,
                        const JobFile& jf) {
  Options o;
  o.values = jf.solid_options;
  if (jf.landscape) o.flags.insert("--landscape");
  View view;
  std::string error;
  if (parse_view(o, &view, &error)) return {};
  int line = 0;
  for (const char* key : {"eye", "look-at", "fov", "view", "perspective"})
    if (line == 0 && key_lines.count(key) != 0 && error.rfind(std::string("--") + key, 0) == 0)
      line = key_lines.at(key);
  return {path, line, error};
}

InputError read_effects(const JobLine& l, PlotterEffects* effects) {
  *effects = PlotterEffects{false, false, false};
  for (size_t i = 1; i < l.f.size(); ++i) {
    if (l.f[i] == "acceleration")
      effects->acceleration = true;
    else if (l.f[i] == "pen-servo")
      effects->pen_servo = true;
    else if (l.f[i] == "backlash")
      effects->backlash = true;
    else if (l.f[i] != "none")
      return l.bad("unknown effect '" + excerpt(l.f[i]) +
                   "' (acceleration, pen-servo, backlash, none)");
  }
  return {};
}

// steps N/D: motor steps per plot step.
InputError read_steps(const JobLine& l, Machine* m) {
  const std::string& v = l.f[1];
  const size_t slash = v.find('/');
  int64_t a, b;
  if (slash == std::string::npos || !parse_int(v.substr(0, slash), 1, 1024, &a) ||
      !parse_int(v.substr(slash + 1), 1, 1024, &b))
    return l.bad("steps must be N/D, e.g. 1/1 or 16/5");
  m->steps_num = uint32_t(a);
  m->steps_den = uint32_t(b);
  return {};
}

InputError read_backlash(const JobLine& l, Machine* m) {
  int64_t a, b;
  if (!parse_int(l.f[1], 0, 1000, &a) || !parse_int(l.f[2], 0, 1000, &b))
    return l.bad("backlash needs two step counts in [0, 1000]");
  m->backlash[0] = uint32_t(a);
  m->backlash[1] = uint32_t(b);
  return {};
}

// One "key value..." line into the job. A key whose value has the wrong form falls through
// to the end, which says what the key takes (or that the key is unknown).
InputError read_setting(const JobLine& l, JobFile* out) {
  const std::string& key = l.f[0];
  const std::vector<std::string>& f = l.f;
  JobSpec& j = out->spec;
  if (key == "scene" && f.size() == 2) {  // relative to the job file's folder
    const size_t slash = l.path.find_last_of('/');
    out->scene_path =
        (f[1][0] == '/' || slash == std::string::npos) ? f[1] : l.path.substr(0, slash + 1) + f[1];
    return {};
  }
  if (key == "drawing" && f.size() == 2) return read_drawing(l, out);
  if (key == "hatch" && f.size() >= 2 && f.size() <= 4) return read_hatch(l, out);
  if (is_view_setting(key) && f.size() == (key == "dash" ? 3u : 2u))
    return read_view_setting(l, out);
  if (is_pen_setting(key) && f.size() >= 2) {
    std::string v = f[1];  // a custom command's words, as the line gives them
    for (size_t k = 2; k < f.size(); ++k) v += " " + f[k];
    out->pen_options["--" + key] = v;
    return {};
  }
  if (key == "cleanup" && l.on_off()) {  // off: plot --no-cleanup (a test's control)
    out->no_cleanup = f[1] == "off";
    return {};
  }
  if (key == "outline" && l.on_off()) {
    out->outline = f[1] == "on";
    return {};
  }
  if (key == "pause-between-layers" && l.on_off()) {
    out->style.pause_between_layers = f[1] == "on";
    return {};
  }
  if (key == "landscape" && l.on_off()) {
    out->landscape = f[1] == "on";
    return {};
  }
  if (key == "intersections" && l.on_off()) {
    out->intersections = f[1] == "on";
    j.hidden.intersections = out->intersections;
    return {};
  }
  if (key == "halo") {
    uint32_t v32 = 0;
    if (!l.number(0, 1048575, &v32)) return l.bad("halo needs a width in [0, 1048575] steps");
    j.draw.halo = int32_t(v32);
    return {};
  }
  if (key == "halo-mode" && f.size() == 2 && (f[1] == "paper" || f[1] == "exact")) {
    j.draw.mode = f[1] == "exact" ? HaloMode::kExact : HaloMode::kPaper;
    return {};
  }
  if (key == "effects" && f.size() >= 2) return read_effects(l, &j.effects);
  if (key == "finish") {
    if (f.size() != 2 || (f[1] != "home" && f[1] != "stay"))
      return l.bad("finish is home (end pen up at the origin, the default) or stay");
    j.finish_home = f[1] == "home";
    return {};
  }
  if (key == "kinematics" && f.size() == 2 && (f[1] == "cartesian" || f[1] == "corexy")) {
    j.machine.kinematics = f[1] == "corexy" ? Kinematics::kCoreXY : Kinematics::kCartesian;
    return {};
  }
  if (key == "steps" && f.size() == 2) return read_steps(l, &j.machine);
  if (key == "backlash" && f.size() == 3) return read_backlash(l, &j.machine);
  for (const NumberSetting& s : kNumberSettings)
    if (key == s.key) return l.number(s.lo, s.hi, s.field(out)) ? InputError{} : l.bad(s.wrong);
  return l.bad(unknown_or_malformed(f));
}

// What no one line shows: that there is a scene, that it can make the drawing, and that the
// machine's settings work together.
InputError check_job(const std::string& path, const std::map<std::string, int>& key_lines,
                     JobFile* out) {
  JobSpec& j = out->spec;
  if (out->scene_path.empty()) return {path, 0, "no 'scene' line"};
  if (out->solid_options.count("--mode") != 0 && !is_mesh_path(out->scene_path))
    return {path, 0,
            "drawing " + out->solid_options["--mode"] + " needs a model scene (.obj, .stl, .ply)"};
  // An .edges scene is projected already: a view setting would be ignored, so it is refused.
  if (!is_mesh_path(out->scene_path))
    for (const char* key : {"view", "perspective", "up", "crease", "weld", "substep", "eye",
                            "look-at", "fov", "roll"})
      if (key_lines.count(key) != 0)
        return {path, key_lines.at(key),
                std::string(key) + " is for a model scene (.obj, .stl, .ply): " + out->scene_path +
                    " is an .edges scene, projected already"};
  if (out->solid_options.count("--scale") != 0 && !is_mesh_path(out->scene_path))
    return {path, key_lines.at("scale"),
            "scale is for a model scene (.obj, .stl, .ply): an .edges scene is in plot steps "
            "already"};
  if (j.draw.mode == HaloMode::kExact) j.cut.reach = j.draw.halo;
  if (const InputError camera = check_camera(path, key_lines, *out); camera.failed()) return camera;
  const InputError pen = read_pen_settings(path, key_lines, out);
  if (pen.failed()) return pen;
  if (out->style.pause_between_layers && out->solid_options.count("--mode") == 0)
    return {path, key_lines.at("pause-between-layers"),
            "pause-between-layers needs drawing hidden-removed or hidden-dashed (the drawings "
            "of more than one kind of line)"};
  const Status s = validate(j.machine);
  if (!ok(s)) return machine_problem(path, j.machine, s, key_lines);
  return {};
}

}  // namespace

InputError read_job_file(const std::string& path, JobFile* out) {
  std::ifstream in(path);
  if (const InputError e = open_problem(path, in); e.failed()) return e;
  *out = JobFile{};
  LineReader reader(in);
  std::vector<std::string> f;
  std::map<std::string, int> key_lines;  // where each setting was last made
  while (reader.next(&f)) {
    key_lines[f[0]] = reader.line();
    const InputError e = read_setting(JobLine{path, reader.line(), f}, out);
    if (e.failed()) return e;
  }
  if (!reader.error().empty()) return {path, reader.line(), reader.error()};
  return check_job(path, key_lines, out);
}

}  // namespace haloplot::host
