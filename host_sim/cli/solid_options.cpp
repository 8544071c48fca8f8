#include "cli/solid_options.h"

#include <vector>

#include "io/line_reader.h"
#include "pipeline/units.h"

namespace haloplot::host {

bool mm_to_steps(const std::string& text, uint32_t steps_per_mm, int32_t* steps) {
  const size_t dot = text.find('.');
  std::string whole = text.substr(0, dot),
              frac = dot == std::string::npos ? "" : text.substr(dot + 1);
  if (frac.size() > 3 || frac.find_first_not_of("0123456789") != std::string::npos) return false;
  int64_t w = 0;
  if (whole.empty() || !parse_int(whole, 0, 10000, &w)) return false;
  while (frac.size() < 3) frac += '0';
  const int64_t thousandths = w * 1000 + std::stoll(frac);
  const int64_t s = (thousandths * steps_per_mm + 500) / 1000;
  if (s < 1 || s > kCoordMax) return false;
  *steps = int32_t(s);
  return true;
}

bool parse_solid_options(const Options& o, SolidOptions* out, std::string* error) {
  SolidOptions so;
  if (!parse_solid_mode(o.get("--mode", "hidden-removed"), &so.spec.mode)) {
    *error =
        "--mode '" + o.get("--mode") + "' must be all, hidden-removed, hidden-dashed or haloed";
    return false;
  }
  int64_t spm = 80;
  if (!o.get("--steps-per-mm").empty() && !parse_int(o.get("--steps-per-mm"), 1, 10000, &spm)) {
    *error = "--steps-per-mm '" + o.get("--steps-per-mm") + "' must be an integer in [1, 10000]";
    return false;
  }
  so.steps_per_mm = uint32_t(spm);
  const std::string dash = o.get("--dash", "2,1");
  const size_t comma = dash.find(',');
  if (comma == std::string::npos ||
      !mm_to_steps(dash.substr(0, comma), so.steps_per_mm, &so.spec.dash_steps) ||
      !mm_to_steps(dash.substr(comma + 1), so.steps_per_mm, &so.spec.gap_steps)) {
    *error =
        "--dash '" + dash + "' must be LENGTH,GAP in mm (up to three decimals, at least a step)";
    return false;
  }
  const std::string m = o.get("--method", "auto");
  if (m == "auto")
    so.method = HiddenMethod::kAuto;
  else if (m == "qi")
    so.method = HiddenMethod::kQi;
  else if (m == "fallback")
    so.method = HiddenMethod::kFallback;
  else {
    *error = "--method '" + m + "' must be auto, qi or fallback";
    return false;
  }
  so.spec.outline = o.has("--outline");
  so.spec.intersections = !o.has("--no-intersections");
  if (!o.get("--hatch").empty()) {
    // SPACING in mm, then the angle and the turn across the depth range in whole degrees.
    std::vector<std::string> f;
    std::string h = o.get("--hatch");
    for (size_t at = 0;;) {
      const size_t next = h.find(',', at);
      f.push_back(h.substr(at, next == std::string::npos ? std::string::npos : next - at));
      if (next == std::string::npos) break;
      at = next + 1;
    }
    int64_t angle = 45, turn = 90;
    if (f.size() > 3 || !mm_to_steps(f[0], so.steps_per_mm, &so.hatch_params.spacing) ||
        (f.size() > 1 && !parse_int(f[1], -360, 360, &angle)) ||
        (f.size() > 2 && !parse_int(f[2], -360, 360, &turn))) {
      *error =
          "--hatch '" + h + "' must be SPACING[,ANGLE[,DEGREES_ACROSS_DEPTH]] (mm; whole degrees)";
      return false;
    }
    so.hatch = true;
    so.hatch_params.angle_mdeg = int32_t(angle * 1000);
    so.hatch_params.mdeg_per_depth = int32_t(turn * 1000);
  }
  *out = so;
  return true;
}

Status run_solid_options(const SolidScene& scene, const SolidOptions& so, SolidRun* run) {
  FallbackParams kira;
  kira.use_classes = kira.use_vc = true;
  // The hatch spacing in the scene's units, like every length the run decides with.
  const HatchParams hatch = hatch_in_units(so.hatch_params, scene.substep_bits);
  return run_hidden_lines(scene, so.method, kira, run, so.spec.outline, so.spec.intersections,
                          so.hatch ? &hatch : nullptr, so.parts);
}

}  // namespace haloplot::host
