#include "cli/page_options.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "io/atomic_file.h"
#include "io/line_reader.h"

namespace haloplot::host {

namespace {

// "210", "215.9", "0.5" mm to thousandths; false if not such a number (up to 3 decimals).
bool parse_um(const std::string& s, int64_t lo, int64_t hi, int64_t* um) {
  const size_t dot = s.find('.');
  const std::string whole = s.substr(0, dot);
  std::string frac = dot == std::string::npos ? "" : s.substr(dot + 1);
  if (frac.size() > 3 || frac.find_first_not_of("0123456789") != std::string::npos ||
      (dot != std::string::npos && frac.empty()))
    return false;
  int64_t w = 0;
  if (whole.empty() || !parse_int(whole, 0, 100000, &w)) return false;
  while (frac.size() < 3) frac += '0';
  *um = w * 1000 + std::stoll(frac);
  return *um >= lo && *um <= hi;
}

bool named_page(const std::string& name, int64_t* w, int64_t* h) {
  struct Named {
    const char* name;
    int64_t w, h;
  };
  static const Named kPages[] = {{"a5", 148000, 210000},    {"a4", 210000, 297000},
                                 {"a3", 297000, 420000},    {"letter", 215900, 279400},
                                 {"legal", 215900, 355600}, {"tabloid", 279400, 431800}};
  std::string lower = name;
  for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
  for (const Named& p : kPages)
    if (lower == p.name) {
      *w = p.w;
      *h = p.h;
      return true;
    }
  const size_t x = lower.find('x');
  return x != std::string::npos && parse_um(lower.substr(0, x), 1000, 10000000, w) &&
         parse_um(lower.substr(x + 1), 1000, 10000000, h);
}

}  // namespace

bool parse_page(const Options& o, Page* page, std::string* error) {
  Page p;
  const std::string name = o.get("--page");
  if (!name.empty() && !named_page(name, &p.width_um, &p.height_um)) {
    *error = "--page '" + name +
             "' must be a4, a3, a5, letter, legal, tabloid or WxH in mm (e.g. 300x200)";
    return false;
  }
  // Named pages are portrait, as vpype's; without --page the default is A4 landscape.
  if (name.empty() || o.has("--landscape")) {
    if (p.width_um < p.height_um) std::swap(p.width_um, p.height_um);
  }
  const std::string margin = o.get("--margin");
  if (!margin.empty() && !parse_um(margin, 0, 10000000, &p.margin_um)) {
    *error = "--margin '" + margin + "' must be a distance in mm (up to three decimals)";
    return false;
  }
  if (2 * p.margin_um >= std::min(p.width_um, p.height_um)) {
    *error = "--margin " + um_text(p.margin_um) + " mm leaves nothing of a " + um_text(p.width_um) +
             " x " + um_text(p.height_um) + " mm page to draw on";
    return false;
  }
  const std::string scale = o.get("--scale");
  if (!scale.empty()) {
    if (o.has("--fit")) {
      *error = "--fit and --scale exclude each other: fit the page, or draw at a scale";
      return false;
    }
    char* end = nullptr;
    p.scale = std::strtod(scale.c_str(), &end);
    if (end != scale.c_str() + scale.size() || !(p.scale > 0) || p.scale > 1e9) {
      *error = "--scale '" + scale + "' must be a positive number (mm on paper per model unit)";
      return false;
    }
  }
  p.placed = o.has("--fit") || !scale.empty();
  *page = p;
  return true;
}

const char* const kPageValued[6] = {"--page",      "--margin",     "--scale",
                                    "--pen-width", "--min-stroke", "--simplify"};
const char* const kPageFlags[4] = {"--landscape", "--fit", "--background", "--no-cleanup"};

bool parse_path_clean(const Options& o, uint32_t steps_per_mm, PathClean* clean,
                      std::string* error) {
  // The pen's width by default: a stroke shorter than the pen is wide draws a blot, not a line.
  const std::string w = o.get("--min-stroke", o.get("--pen-width", "0.3"));
  char* end = nullptr;
  const double mm = std::strtod(w.c_str(), &end);
  if (w.empty() || end != w.c_str() + w.size() || !(mm >= 0) || mm > 100) {
    *error = "--min-stroke '" + w + "' must be a length in mm in [0, 100] (0: keep every stroke)";
    return false;
  }
  clean->on = !o.has("--no-cleanup");
  clean->min_stroke = uint32_t(std::llround(mm * steps_per_mm));
  // Off unless asked: a plot keeps every point the hidden lines found.
  const std::string t = o.get("--simplify", "0");
  const double tol = std::strtod(t.c_str(), &end);
  if (t.empty() || end != t.c_str() + t.size() || !(tol >= 0) || tol > 10) {
    *error = "--simplify '" + t + "' must be a tolerance in mm in [0, 10] (0: every point kept)";
    return false;
  }
  clean->simplify = uint32_t(std::llround(tol * steps_per_mm));
  return true;
}

bool parse_plot_svg_style(const Options& o, bool model, uint32_t steps_per_mm, PlotSvgStyle* style,
                          std::string* error) {
  PlotSvgStyle s;
  if (!parse_page(o, &s.page, error)) return false;
  if (!model && s.page.placed) {
    *error = std::string(o.has("--fit") ? "--fit" : "--scale") +
             " is for models (.obj, .stl, .ply): an .edges or .cut scene is in plot steps "
             "already, drawn where its coordinates say";
    return false;
  }
  const std::string w = o.get("--pen-width", "0.3");
  char* end = nullptr;
  s.pen_width_mm = std::strtod(w.c_str(), &end);
  if (w.empty() || end != w.c_str() + w.size() || !(s.pen_width_mm > 0) || s.pen_width_mm > 100) {
    *error = "--pen-width '" + w + "' must be a width in mm in (0, 100]";
    return false;
  }
  s.background = o.has("--background");
  s.placement.steps_per_mm = steps_per_mm;
  if (!parse_path_clean(o, steps_per_mm, &s.clean, error)) return false;
  *style = s;
  return true;
}

namespace {

// An .edges or .cut scene is drawn where its steps say: one that leaves the page is most likely
// meant for another page or steps-per-mm, so say so (the SVG is still written, as asked).
void warn_off_page(const std::vector<PathPoint>& path, const PlotSvgStyle& style) {
  const int64_t per = style.placement.steps_per_mm;
  const int64_t w = style.page.width_um * per / 1000, h = style.page.height_um * per / 1000;
  for (size_t i = 1; i < path.size(); ++i)
    for (const PathPoint* p : {&path[i - 1], &path[i]})
      if (path[i].pen_down != 0 && (p->x < 0 || p->y < 0 || p->x > w || p->y > h)) {
        std::cerr << "haloplot: warning: the drawing reaches beyond the "
                  << um_text(style.page.width_um) << " x " << um_text(style.page.height_um)
                  << " mm page (a point at " << mm_text(p->x, uint32_t(per)) << ", "
                  << mm_text(p->y, uint32_t(per))
                  << " mm): give a larger --page or another --steps-per-mm\n";
        return;
      }
}

}  // namespace

std::string write_plot_page(const std::string& path, const std::vector<StrokeLayer>& layers,
                            bool model, PlotSvgStyle* style, std::vector<PathPoint>* joined) {
  std::vector<PlannedLayer> planned;
  const Status s = plan_layers(layers, &planned, style->clean, &style->path_stats);
  if (!ok(s)) return path + ": planning the pen path failed: " + status_name(s);
  return write_planned_page(path, planned, model, style, joined);
}

void print_clean_stats(const PathStats& st, uint32_t steps_per_mm) {
  const double per = steps_per_mm;
  std::fprintf(stderr,
               "clean_dots=%u\nclean_overlaps=%u\nclean_overlap_mm=%.1f\nclean_crumbs=%u\n"
               "clean_crumb_mm=%.1f\nclean_points_simplified=%u\n",
               st.dots_dropped, st.overlaps_merged, double(st.overlap_length) / per,
               st.crumbs_dropped, double(st.crumb_length) / per, st.points_simplified);
}

std::string write_planned_page(const std::string& path, const std::vector<PlannedLayer>& planned,
                               bool model, PlotSvgStyle* style, std::vector<PathPoint>* joined) {
  const std::vector<PathPoint> all = joined_path(planned);
  if (model)
    centring_offset(style->page, style->placement.steps_per_mm, all, &style->placement.offset_x,
                    &style->placement.offset_y);
  if (!model) warn_off_page(all, *style);
  if (joined != nullptr) *joined = all;
  return write_atomically(path, [&](std::ostream& out) {
    write_plot_svg(out, planned, *style);
    return true;
  });
}

}  // namespace haloplot::host
