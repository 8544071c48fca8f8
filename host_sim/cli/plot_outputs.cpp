#include "cli/plot_outputs.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <utility>

#include "cli/page_options.h"
#include "export/plotter_outputs.h"
#include "io/line_reader.h"

namespace haloplot::host {

const char* const kPlotterOutputOptions[2] = {"--gcode", "--hpgl"};

bool wants_plotter_outputs(const Options& o) {
  return !o.get("--gcode").empty() || !o.get("--hpgl").empty();
}

const char* const kPenOptions[14] = {
    "--pen",          "--servo-down",     "--z-up",         "--z-down",      "--z-feed",
    "--pen-up-gcode", "--pen-down-gcode", "--draw-feed",    "--travel-feed", "--pen-dwell",
    "--gcode-flavor", "--servo-up",       "--gcode-header", "--gcode-footer"};

namespace {

// "12", "-0.5", "1.25" to thousandths, exactly; false if not such a number in [lo, hi].
bool parse_thousandths(const std::string& text, bool sign, int64_t lo, int64_t hi, int64_t* out) {
  std::string t = text;
  const bool neg = sign && !t.empty() && t[0] == '-';
  if (neg) t = t.substr(1);
  const size_t dot = t.find('.');
  std::string whole = t.substr(0, dot), frac = dot == std::string::npos ? "" : t.substr(dot + 1);
  if (frac.size() > 3 || frac.find_first_not_of("0123456789") != std::string::npos) return false;
  int64_t w = 0;
  if (whole.empty() || !parse_int(whole, 0, 100000000, &w)) return false;
  frac.append(3 - frac.size(), '0');
  const int64_t v = (w * 1000 + std::stoll(frac)) * (neg ? -1 : 1);
  if (v < lo || v > hi) return false;
  *out = v;
  return true;
}

// "\n" (backslash, n) in a custom pen command starts a new line.
std::string command_lines(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == 'n')
      out += '\n', ++i;
    else
      out += text[i];
  return out;
}

// Each profile's own options: given with another profile, they are refused by name.
const char* owner_profile(const std::string& option) {
  if (option == "--servo-down" || option == "--servo-up") return "servo";
  if (option == "--z-up" || option == "--z-down" || option == "--z-feed") return "z";
  if (option == "--pen-up-gcode" || option == "--pen-down-gcode") return "custom";
  return nullptr;
}

// The dialect (--gcode-flavor), the servo's values in it and the header and footer text.
bool dialect_of(const Options& o, ExportStyle* style, std::string* error,
                const std::function<std::string(const std::string&)>& name) {
  const auto bad = [&](const std::string& option, const std::string& form) {
    *error = name(option) + " '" + o.get(option) + "' must be " + form;
    return false;
  };
  const std::string flavor = o.get("--gcode-flavor", "grbl");
  if (flavor != "grbl" && flavor != "marlin") return bad("--gcode-flavor", "grbl or marlin");
  const bool marlin = flavor == "marlin";
  style->flavor = marlin ? GcodeFlavor::kMarlin : GcodeFlavor::kGrbl;
  if (!marlin && !o.get("--servo-up").empty()) {
    *error = name("--servo-up") + " is for " + name("--gcode-flavor") +
             " marlin (grbl lifts the pen with M5, no value)";
    return false;
  }
  int64_t v = 0;
  // Marlin's servo takes an angle; a down angle a little off the up one, as pen lifts mount.
  if (marlin) style->pen_down_s = 30;
  if (!o.get("--servo-down").empty()) {
    if (!parse_int(o.get("--servo-down"), 0, marlin ? 180 : 100000, &v))
      return bad("--servo-down", marlin ? "an angle in [0, 180] (the M280 S value)"
                                        : "an integer in [0, 100000] (the M3 S value)");
    style->pen_down_s = int32_t(v);
  }
  if (!o.get("--servo-up").empty()) {
    if (!parse_int(o.get("--servo-up"), 0, 180, &v))
      return bad("--servo-up", "an angle in [0, 180] (the M280 S value)");
    style->servo_up_angle = int32_t(v);
  }
  style->header_text = command_lines(o.get("--gcode-header"));
  style->footer_text = command_lines(o.get("--gcode-footer"));
  return true;
}

}  // namespace

bool export_style_of(const Options& o, ExportStyle* style, Machine* machine, std::string* error,
                     const std::string& dashes) {
  const auto name = [&](const std::string& option) { return dashes + option.substr(2); };
  const auto bad = [&](const std::string& option, const std::string& form) {
    *error = name(option) + " '" + o.get(option) + "' must be " + form;
    return false;
  };
  int64_t per_mm = 80;
  if (!o.get("--steps-per-mm").empty() && !parse_int(o.get("--steps-per-mm"), 1, 10000, &per_mm))
    return bad("--steps-per-mm", "an integer in [1, 10000]");
  style->steps_per_mm = uint32_t(per_mm);
  const std::string pen = o.get("--pen", "servo");
  if (pen != "servo" && pen != "z" && pen != "custom") return bad("--pen", "servo, z or custom");
  style->pen = pen == "z"        ? PenProfile::kZ
               : pen == "custom" ? PenProfile::kCustom
                                 : PenProfile::kServo;
  for (const char* option : kPenOptions) {
    const char* owner = owner_profile(option);
    if (owner != nullptr && !o.get(option).empty() && pen != owner) {
      *error =
          name(option) + " is for " + name("--pen") + " " + owner + " (the pen is " + pen + ")";
      return false;
    }
  }
  if (!dialect_of(o, style, error, name)) return false;
  int64_t v = 0;
  const std::pair<const char*, int32_t*> heights[] = {{"--z-up", &style->z_up_um},
                                                      {"--z-down", &style->z_down_um}};
  for (const auto& h : heights) {
    if (o.get(h.first).empty()) continue;
    if (!parse_thousandths(o.get(h.first), true, -1000000, 1000000, &v))
      return bad(h.first, "a height in mm (up to three decimals)");
    *h.second = int32_t(v);
  }
  const std::pair<const char*, int64_t*> feeds[] = {{"--z-feed", &style->z_feed_milli},
                                                    {"--draw-feed", &style->draw_feed_milli},
                                                    {"--travel-feed", &style->travel_feed_milli}};
  for (const auto& f : feeds)
    if (!o.get(f.first).empty() &&
        !parse_thousandths(o.get(f.first), false, 1, int64_t(1) << 40, f.second))
      return bad(f.first, "a feed in mm/min (up to three decimals, above 0)");
  style->pen_up_text = command_lines(o.get("--pen-up-gcode"));
  style->pen_down_text = command_lines(o.get("--pen-down-gcode"));
  if (style->pen == PenProfile::kCustom && style->pen_up_text.empty() &&
      style->pen_down_text.empty()) {
    *error = name("--pen") + " custom needs " + name("--pen-up-gcode") + " and " +
             name("--pen-down-gcode") + " (the commands that lift and lower the pen)";
    return false;
  }
  if (!o.get("--pen-dwell").empty()) {
    // The servo's dwell (its G4 P) and, with any profile, the time a pen change takes in the
    // plot-time estimate: the machine's pen travel, no separate settle.
    if (!parse_thousandths(o.get("--pen-dwell"), false, 0, 100000, &v))
      return bad("--pen-dwell", "seconds in [0, 100] (up to three decimals)");
    machine->pen_travel_ticks = uint32_t(v * machine->tick_hz / 1000);
    machine->pen_settle_ticks = 0;
  }
  if (o.has("--pause-between-layers")) style->pause_between_layers = true;
  return apply_feeds(*style, machine, error);
}

int write_plot_outputs(const Options& o, const JobSpec& spec, const std::vector<Edge3>& edges,
                       ExportStyle style, bool model) {
  PlannedJob planned;
  if (!plan_plot_job(spec, edges, &planned)) return 1;
  return write_planned_outputs(o, spec, std::move(planned), style, model);
}

bool plan_plot_job(const JobSpec& spec, const std::vector<Edge3>& edges, PlannedJob* planned) {
  const Status s = plan_job_path(spec, edges, planned);
  if (!ok(s)) std::cerr << "haloplot: path planning failed: " << status_name(s) << "\n";
  return ok(s);
}

int write_planned_outputs(const Options& o, const JobSpec& spec, PlannedJob planned,
                          ExportStyle style, bool model) {
  Page page;
  std::string page_error;
  if (model && !parse_page(o, &page, &page_error)) {
    std::cerr << "haloplot: " << page_error << "\n";
    return 1;
  }
  add_travel_home(spec, &planned.points);
  if (model) centre_on_page(page, spec.finish_home, &planned.points, &style);
  const std::string error = write_plotter_outputs(o.get("--gcode"), o.get("--hpgl"), planned.points,
                                                  spec.machine, style, planned.layer_points);
  if (!error.empty()) {
    std::cerr << "haloplot: " << error << "\n";
    return 1;
  }
  // The summary is the files': their pen-downs, travel and time, not the planner's stats.
  std::cerr << written_summary(spec, planned.points, style) << "\n";
  if (o.has("--stats")) {
    std::fprintf(stderr, "estimate_s=%.3f\n", written_plot_seconds(spec, planned.points, style));
    print_clean_stats(planned.counters.path, style.steps_per_mm);
  }
  return 0;
}

}  // namespace haloplot::host
