#include "io/job_file.h"

#include <algorithm>
#include <fstream>
#include <map>

#include "cli/options.h"
#include "cli/solid_options.h"
#include "io/line_reader.h"
#include "io/mesh_file.h"
#include "pipeline/scene_input.h"

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
    {"up", "y | z (the OBJ file's up axis)"},
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

}  // namespace

InputError read_job_file(const std::string& path, JobFile* out) {
  std::ifstream in(path);
  if (!in) return {path, 0, "cannot open"};
  *out = JobFile{};
  JobSpec& j = out->spec;
  LineReader reader(in);
  std::vector<std::string> f;
  std::map<std::string, int> key_lines;  // where each setting was last made
  while (reader.next(&f)) {
    const int line = reader.line();
    const std::string& key = f[0];
    key_lines[key] = line;
    auto bad = [&](const std::string& what) { return InputError{path, line, what}; };
    auto number = [&](int64_t lo, int64_t hi, uint32_t* dst) -> bool {
      int64_t v;
      if (f.size() != 2 || !parse_int(f[1], lo, hi, &v)) return false;
      *dst = uint32_t(v);
      return true;
    };
    uint32_t v32 = 0;
    if (key == "scene" && f.size() == 2) {
      const size_t slash = path.find_last_of('/');
      out->scene_path =
          (f[1][0] == '/' || slash == std::string::npos) ? f[1] : path.substr(0, slash + 1) + f[1];
    } else if (key == "drawing" && f.size() == 2) {
      if (f[1] == "all")
        j.drawing = DrawingEffect::kAllEdges;
      else if (f[1] == "haloed")
        j.drawing = DrawingEffect::kHaloed;
      else if (f[1] == "hidden-removed" || f[1] == "hidden-dashed") {
        j.drawing =
            f[1] == "hidden-removed" ? DrawingEffect::kHiddenRemoved : DrawingEffect::kHiddenDashed;
        out->solid_options["--mode"] = f[1];
      } else if (f[1] == "hatch")
        return bad(
            "hatching is the setting 'hatch SPACING ANGLE TURN' with drawing hidden-removed or "
            "hidden-dashed");
      else
        return bad("drawing must be all, haloed, hidden-removed or hidden-dashed, not '" +
                   excerpt(f[1]) + "'");
    } else if (key == "hatch" && f.size() >= 2 && f.size() <= 4) {
      std::string v = f[1];
      for (size_t k = 2; k < f.size(); ++k) v += "," + f[k];
      out->solid_options["--hatch"] = v;
      Options o;
      o.values = out->solid_options;
      SolidOptions so;
      std::string error;
      if (!parse_solid_options(o, &so, &error)) return bad(error);
    } else if ((key == "view" || key == "perspective" || key == "method" || key == "dash" ||
                key == "up" || key == "substep" || key == "weld" || key == "crease") &&
               f.size() == (key == "dash" ? 3u : 2u)) {
      out->solid_options["--" + key] = key == "dash" ? f[1] + "," + f[2] : f[1];
      // Checked here, so a bad value is reported with its line.
      Options o;
      o.values = out->solid_options;
      SolidOptions so;
      View view;
      std::string error;
      UpAxis up;
      if (!parse_solid_options(o, &so, &error) || !parse_view(o, &view, &error) ||
          !parse_up(o, &up, &error))
        return bad(error);
    } else if (key == "outline" && f.size() == 2 && (f[1] == "on" || f[1] == "off")) {
      out->outline = f[1] == "on";
    } else if (key == "intersections" && f.size() == 2 && (f[1] == "on" || f[1] == "off")) {
      out->intersections = f[1] == "on";
      j.hidden.intersections = out->intersections;
    } else if (key == "halo") {
      if (!number(0, 1048575, &v32)) return bad("halo needs a width in [0, 1048575] steps");
      j.draw.halo = int32_t(v32);
    } else if (key == "halo-mode" && f.size() == 2 && (f[1] == "paper" || f[1] == "exact")) {
      j.draw.mode = f[1] == "exact" ? HaloMode::kExact : HaloMode::kPaper;
    } else if (key == "effects" && f.size() >= 2) {
      j.effects = PlotterEffects{false, false, false};
      for (size_t i = 1; i < f.size(); ++i) {
        if (f[i] == "acceleration")
          j.effects.acceleration = true;
        else if (f[i] == "pen-servo")
          j.effects.pen_servo = true;
        else if (f[i] == "backlash")
          j.effects.backlash = true;
        else if (f[i] != "none")
          return bad("unknown effect '" + excerpt(f[i]) +
                     "' (acceleration, pen-servo, backlash, none)");
      }
    } else if (key == "finish") {
      if (f.size() != 2 || (f[1] != "home" && f[1] != "stay"))
        return bad("finish is home (end pen up at the origin, the default) or stay");
      j.finish_home = f[1] == "home";
    } else if (key == "kinematics" && f.size() == 2 && (f[1] == "cartesian" || f[1] == "corexy")) {
      j.machine.kinematics = f[1] == "corexy" ? Kinematics::kCoreXY : Kinematics::kCartesian;
    } else if (key == "steps" && f.size() == 2) {
      const size_t slash = f[1].find('/');
      int64_t a, b;
      if (slash == std::string::npos || !parse_int(f[1].substr(0, slash), 1, 1024, &a) ||
          !parse_int(f[1].substr(slash + 1), 1, 1024, &b))
        return bad("steps must be N/D, e.g. 1/1 or 16/5");
      j.machine.steps_num = uint32_t(a);
      j.machine.steps_den = uint32_t(b);
    } else if (key == "backlash" && f.size() == 3) {
      int64_t a, b;
      if (!parse_int(f[1], 0, 1000, &a) || !parse_int(f[2], 0, 1000, &b))
        return bad("backlash needs two step counts in [0, 1000]");
      j.machine.backlash[0] = uint32_t(a);
      j.machine.backlash[1] = uint32_t(b);
    } else if (key == "tick-hz") {
      if (!number(1, 16000000, &j.machine.tick_hz)) return bad("tick-hz in [1, 16000000]");
    } else if (key == "min-interval") {
      if (!number(1, 1000000, &j.machine.min_interval))
        return bad("min-interval in [1, 1000000] ticks");
    } else if (key == "max-step-rate") {
      if (!number(1, 10000000, &j.machine.max_step_rate))
        return bad("max-step-rate in [1, 10000000]");
    } else if (key == "draw-speed") {
      if (!number(1, 65535, &j.machine.draw_speed)) return bad("draw-speed in [1, 65535] steps/s");
    } else if (key == "travel-speed") {
      if (!number(1, 65535, &j.machine.travel_speed))
        return bad("travel-speed in [1, 65535] steps/s");
    } else if (key == "accel") {
      if (!number(1, 4194303, &j.machine.accel)) return bad("accel in [1, 4194303] steps/s^2");
    } else if (key == "junction-deviation") {
      if (!number(0, 65535, &j.machine.junction_deviation))
        return bad("junction-deviation in [0, 65535] steps");
    } else if (key == "pen-travel-ticks") {
      if (!number(0, 100000000, &j.machine.pen_travel_ticks))
        return bad("pen-travel-ticks in [0, 10^8]");
    } else if (key == "pen-settle-ticks") {
      if (!number(0, 100000000, &j.machine.pen_settle_ticks))
        return bad("pen-settle-ticks in [0, 10^8]");
    } else if (key == "arena") {
      if (!number(1024, 1 << 30, &out->arena))
        return bad("arena needs the controller's job arena in bytes, in [1024, 2^30]");
    } else if (key == "steps-per-mm") {
      if (!number(1, 100000, &out->style.steps_per_mm)) return bad("steps-per-mm in [1, 100000]");
    } else {
      return bad(unknown_or_malformed(f));
    }
  }
  if (!reader.error().empty()) return {path, reader.line(), reader.error()};
  if (out->scene_path.empty()) return {path, 0, "no 'scene' line"};
  if (out->solid_options.count("--mode") != 0 && !is_mesh_path(out->scene_path))
    return {path, 0,
            "drawing " + out->solid_options["--mode"] + " needs a model scene (.obj, .stl, .ply)"};
  if (j.draw.mode == HaloMode::kExact) j.cut.reach = j.draw.halo;
  const Status s = validate(j.machine);
  if (!ok(s)) return machine_problem(path, j.machine, s, key_lines);
  return {};
}

}  // namespace haloplot::host
