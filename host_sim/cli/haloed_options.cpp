#include "cli/haloed_options.h"

#include <unistd.h>

#include <cstdio>

#include "cli/command_line.h"
#include "io/line_reader.h"

namespace haloplot::host {

const std::set<std::string> kCutValued = {"-o",      "--lambda", "--cell",
                                          "--cover", "--reach",  "--threads"};

void cut_progress(void*, uint32_t done, uint32_t total) {
  static uint32_t last_pct = 101;
  const uint32_t pct = total ? uint32_t(uint64_t(done) * 100 / total) : 100;
  if (pct == last_pct) return;
  last_pct = pct;
  std::fprintf(stderr, "\rCUT: %3u%% of %u cells%s", pct, total, pct == 100 ? "\n" : "");
}

namespace {

// --lambda accepts a decimal like 1.5; stored as Q8.8 without floating point.
bool parse_lambda(const std::string& s, uint32_t* q8) {
  const size_t dot = s.find('.');
  int64_t whole = 0, frac = 0;
  const std::string w = s.substr(0, dot);
  if (!parse_int(w.empty() ? "0" : w, 0, 1000, &whole)) return false;
  uint64_t scale = 1;
  if (dot != std::string::npos) {
    const std::string f = s.substr(dot + 1);
    if (f.empty() || f.size() > 6 || !parse_int(f, 0, 999999, &frac)) return false;
    for (size_t i = 0; i < f.size(); ++i) scale *= 10;
  }
  const uint64_t v = uint64_t(whole) * 256 + (uint64_t(frac) * 256 + scale / 2) / scale;
  if (v == 0) return false;
  *q8 = uint32_t(v);
  return true;
}

}  // namespace

bool cut_params(const Options& o, CutParams* p, std::string* error) {
  if (!o.get("--lambda").empty() && !parse_lambda(o.get("--lambda"), &p->grid.lambda_q8)) {
    *error = "--lambda '" + o.get("--lambda") + "' must be a positive decimal up to 1000";
    return false;
  }
  int64_t cell = 0, reach = 0;
  if (!read_int_option(o, "--cell", 1, kCoordLimit, &cell, error)) return false;
  if (!read_int_option(o, "--reach", 0, kCoordMax, &reach, error)) return false;
  p->grid.cell = int32_t(cell);
  p->reach = int32_t(reach);
  const std::string cover = o.get("--cover", "exact");
  if (cover == "exact")
    p->cover = CellCover::kExact;
  else if (cover == "bbox")
    p->cover = CellCover::kBoundingBox;
  else {
    *error = "--cover must be 'exact' or 'bbox'";
    return false;
  }
  if (!read_threads_option(o, &p->parts, error)) return false;
  if (isatty(2)) p->progress = &cut_progress;
  return true;
}

bool draw_params(const Options& o, DrawParams* p, std::string* error) {
  if (o.get("--halo").empty()) {
    *error = "--halo W (steps) is required";
    return false;
  }
  int64_t halo = 0;
  if (!read_int_option(o, "--halo", 0, kCoordMax, &halo, error)) return false;
  p->halo = int32_t(halo);
  p->mode = o.has("--exact-halo") ? HaloMode::kExact : HaloMode::kPaper;
  return true;
}

}  // namespace haloplot::host
