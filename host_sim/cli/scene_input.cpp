#include "cli/scene_input.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "cli/job_file.h"
#include "cli/page_options.h"
#include "cli/shells_note.h"
#include "cli/solid_options.h"
#include "export/page.h"
#include "haloplot/view/facing.h"
#include "haloplot/view/projection.h"
#include "io/atomic_file.h"
#include "io/edges_file.h"
#include "io/line_reader.h"
#include "io/mesh_file.h"
#include "io/obj_file.h"
#include "io/substep_header.h"
#include "pipeline/host_memory.h"
#include "pipeline/mesh_repair.h"
#include "pipeline/surface_pipeline.h"
#include "pipeline/units.h"

namespace haloplot::host {

const char* const kSceneOptions[11] = {"--view",    "--perspective", "--dump-edges", "--up",
                                       "--substep", "--weld",        "--crease",     "--eye",
                                       "--look-at", "--fov",         "--roll"};

namespace {

// "30", "-12.5", "40.125" degrees to millidegrees, exactly (no floating point).
bool parse_mdeg(const std::string& s, int32_t* out) {
  const size_t dot = s.find('.');
  const std::string whole = s.substr(0, dot);
  std::string frac = dot == std::string::npos ? "" : s.substr(dot + 1);
  if (frac.size() > 3 || frac.find_first_not_of("0123456789") != std::string::npos) return false;
  int64_t w = 0;
  if (!parse_int(whole == "-" ? "-0" : whole, -360000, 360000, &w)) return false;
  while (frac.size() < 3) frac += '0';
  const int64_t f = std::stoll(frac);
  const bool neg = !whole.empty() && whole[0] == '-';
  *out = int32_t(w * 1000 + (neg ? -f : f));
  return true;
}

// The picture turned counterclockwise by `radians` about the view axis: each point's screen
// coordinates along ex = (cos az, -sin az, 0) and ey = (sin az sin el, cos az sin el, cos el)
// rotated, its depth along w = ex x ey kept (the same frame as
// core/include/haloplot/view/projection.h).
void roll_about_view_axis(const View& view, double radians,
                          std::vector<std::array<double, 3>>* points) {
  const double pi = 3.14159265358979323846;
  const double az = view.azimuth_mdeg * pi / 180000, el = view.elevation_mdeg * pi / 180000;
  const double ex[3] = {std::cos(az), -std::sin(az), 0};
  const double ey[3] = {std::sin(az) * std::sin(el), std::cos(az) * std::sin(el), std::cos(el)};
  const double w[3] = {-std::sin(az) * std::cos(el), -std::cos(az) * std::cos(el), std::sin(el)};
  const double c = std::cos(radians), s = std::sin(radians);
  for (std::array<double, 3>& p : *points) {
    const double x = p[0] * ex[0] + p[1] * ex[1] + p[2] * ex[2];
    const double y = p[0] * ey[0] + p[1] * ey[1] + p[2] * ey[2];
    const double d = p[0] * w[0] + p[1] * w[1] + p[2] * w[2];
    const double x2 = x * c - y * s, y2 = x * s + y * c;
    for (size_t a = 0; a < 3; ++a) p[a] = x2 * ex[a] + y2 * ey[a] + d * w[a];
  }
}

}  // namespace

Options with_model_defaults(const Options& o, const std::string& path) {
  MeshFormat format = MeshFormat::kObj;
  if (!o.get("--up").empty() || !mesh_format_of(path, &format) || format != MeshFormat::kStl)
    return o;
  Options stl = o;
  stl.values["--up"] = "z";  // 3-D printing's convention: OpenSCAD, slicers, Blender's STL
  return stl;
}

bool parse_up(const Options& o, UpAxis* up, std::string* error) {
  if (parse_up_axis(o.get("--up", "y"), up)) return true;
  *error = "--up '" + o.get("--up") +
           "' must be x, y, z, -x, -y or -z (y: most OBJ files, Blender, Maya; z: most STL)";
  return false;
}

namespace {

// --weld EPS (file units; 0: the same position only) or off, into world units (-1: off).
// Default: the file's rounding (weld_distance), in every format: an STL or PLY is a triangle
// soup, and an OBJ may be one too, or repeat corners its exporter computed twice.
bool weld_tolerance(const Options& o, const ObjModel& model, double* tolerance,
                    std::string* error) {
  const std::string w = o.get("--weld");
  *tolerance = -1;
  if (w == "off") return true;
  if (w.empty()) {
    *tolerance = weld_distance(model);
    return true;
  }
  char* end = nullptr;
  const double eps = std::strtod(w.c_str(), &end);
  if (end != w.c_str() + w.size() || !(eps >= 0) || eps > 1e300) {
    *error = "--weld '" + w +
             "' must be a distance in the model's units (0: the same position) "
             "or off";
    return false;
  }
  *tolerance = eps * model.scale;
  return true;
}

// --crease DEG (0 to 180: faces within DEG degrees, or flat but for the file's rounding), exact
// (exactly coplanar faces only) or off. Default 0: flat but for the rounding. The rounding is
// the model's, filled in by read_model.
bool crease_rule(const Options& o, CreaseRule* rule, bool* exact, std::string* error) {
  const std::string c = o.get("--crease", "0");
  *rule = CreaseRule{};
  *exact = c == "exact";
  rule->keep_all = c == "off";
  if (rule->keep_all || *exact) return true;
  char* end = nullptr;
  rule->deg = std::strtod(c.c_str(), &end);
  if (c.empty() || end != c.c_str() + c.size() || !(rule->deg >= 0 && rule->deg <= 180)) {
    *error = "--crease '" + c + "' must be an angle in degrees in [0, 180], exact or off";
    return false;
  }
  return true;
}

}  // namespace

bool read_model(const Options& given, const std::string& path, ObjModel* model,
                RepairReport* repair, std::string* error) {
  const Options o = with_model_defaults(given, path);
  UpAxis up;
  CreaseRule crease;
  bool exact = false;
  double tolerance = -1;
  if (!parse_up(o, &up, error) || !weld_tolerance(o, ObjModel{}, &tolerance, error) ||
      !crease_rule(o, &crease, &exact, error))
    return false;
  const InputError ie = read_mesh_file(path, model);
  // The reading's and the orientation's freed arrays (a vector's copies as it grew, the
  // sides and links between faces) given back, as after the whole reading (cmd_plot_solid):
  // kept for reuse, each step after took fresh pages on top of them, and the orientation's
  // were the 1.1M-triangle Blender export's peak (223 MB, 80 MB of it freed). Only a large
  // model's (host_memory.h): a small one's are reused as they are.
  give_back_freed_memory();
  if (ie.failed()) {
    *error = ie.message();
    return false;
  }
  RepairReport report;
  weld_tolerance(o, *model, &tolerance, error);  // checked above: now in this model's units
  if (tolerance >= 0) weld_vertices(model, tolerance, &report);
  orient_shells(model, &report);
  give_back_freed_memory();  // its sides and neighbours (see above)
  // A weld asked for that leaves a shell not closed: the file read again (not kept: a closed
  // model's plot pays nothing) and welded at EPS and at the default, for the message to say
  // when the weld asked for did worse.
  ObjModel again;
  if (repair != nullptr && tolerance >= 0 && !o.get("--weld").empty() &&
      report.shells > report.closed_shells && !read_mesh_file(path, &again).failed()) {
    report.compared = true;
    report.with_given = try_weld(again, tolerance);
    report.with_default = try_weld(std::move(again), weld_distance(*model));
  }
  // Open shells after the default weld: are they gaps a larger weld closes, or open as made?
  // (Measured only for the message, where a caller asks for the report.)
  if (repair != nullptr && repair->measure_open && o.get("--weld").empty() &&
      report.shells > report.closed_shells + report.unorientable_shells) {
    report.measured = true;
    report.open = measure_open_sides(*model);
    report.weld = weld_hint(*model, report.open);
    give_back_freed_memory();  // the measure's (see above)
  }
  if (!exact) crease.rounding = vertex_rounding(*model);
  drop_flat_edges(model, crease, &report);
  find_regions(model);
  if (repair != nullptr) *repair = report;
  make_z_up(model, up);
  return true;
}

namespace {

// Reads a model, welds and orients it (mesh_repair.h) and projects it; on failure *error is
// complete. *repair (may be null) says what the cleaning did.
bool project_obj(const Options& given, const std::string& path, ObjModel* model,
                 std::vector<Point3>* screen, View* view_out, std::string* error,
                 RepairReport* repair = nullptr) {
  const Options o = with_model_defaults(given, path);
  View view;
  if (!parse_view(o, &view, error)) return false;
  if (!read_model(o, path, model, repair, error) || !aim_view(o, model, &view, error) ||
      !scale_view(o, *model, &view, error))
    return false;
  *view_out = view;
  screen->resize(model->vertices.size());
  const Status s =
      project_points(view, model->vertices.data(), uint32_t(screen->size()), screen->data());
  if (s == Status::kCoordinateOutOfRange && view.perspective > 0) {
    *error = path +
             ": a vertex lies within 1 unit of the eye plane or behind it: move the eye "
             "back (--perspective larger than the model's depth, about 524288 units)";
    return false;
  }
  if (!ok(s)) {
    *error = path + ": projection failed: " + status_name(s);
    return false;
  }
  return true;
}

// The view options as given, for the dump's header.
std::string view_words(const Options& o) {
  std::string words = o.get("--eye").empty()
                          ? "--view " + o.get("--view", "30,40")
                          : "--eye " + o.get("--eye") + " --look-at " + o.get("--look-at");
  for (const char* option : {"--perspective", "--fov", "--roll", "--up"})
    if (!o.get(option).empty()) words += std::string(" ") + option + " " + o.get(option);
  return words;
}

bool dump_edges(const Options& o, const std::string& path, const std::vector<Edge3>& edges,
                int32_t substep_bits, std::string* error) {
  if (o.get("--dump-edges").empty()) return true;
  *error = write_atomically(o.get("--dump-edges"), [&](std::ostream& out) {
    write_edges(out, edges,
                "# projected from " + path + " with " + view_words(o) + "\n" +
                    substep_header(substep_bits));
    return true;
  });
  return error->empty();
}

}  // namespace

bool scale_view(const Options& o, const ObjModel& model, View* view, std::string* error) {
  Page page;
  if (!parse_page(o, &page, error)) return false;
  if (page.scale <= 0 || model.vertices.empty()) return true;
  // The projected extents in world units, as core/include/haloplot/view/projection.h projects (in
  // doubles: a scale needs no exactness, the fit itself stays the core's).
  const double pi = 3.14159265358979323846;
  const double az = view->azimuth_mdeg * pi / 180000, el = view->elevation_mdeg * pi / 180000;
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
  for (const Point3& p : model.vertices) {
    const double x = p.x * std::cos(az) - p.y * std::sin(az);
    const double y1w = p.x * std::sin(az) + p.y * std::cos(az);
    double y = p.z * std::cos(el) + y1w * std::sin(el);
    const double d = p.z * std::sin(el) - y1w * std::cos(el);
    const double k = view->perspective > 0 ? view->perspective / (view->perspective - d) : 1;
    x0 = std::min(x0, x * k), x1 = std::max(x1, x * k);
    y0 = std::min(y0, y * k), y1 = std::max(y1, y * k);
  }
  // Steps per world unit: S mm per file unit, the model's world units per file unit.
  int64_t per_mm = 80;
  parse_int(o.get("--steps-per-mm", "80"), 1, 100000, &per_mm);
  const double per_world = page.scale * double(per_mm) / model.scale;
  const double w = (x1 - x0) * per_world, h = (y1 - y0) * per_world;
  if (w > view->width || h > view->height) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "--scale %s draws the model %.1f x %.1f mm, larger than the page's drawable "
                  "area, %.1f x %.1f mm",
                  o.get("--scale").c_str(), w / double(per_mm), h / double(per_mm),
                  view->width / double(per_mm), view->height / double(per_mm));
    *error = text;
    return false;
  }
  // Both sides the larger extent: the core's fit fills it, at exactly this scale.
  view->width = view->height = std::max<int32_t>(1, int32_t(std::lround(std::max(w, h))));
  return true;
}

namespace {

// Three numbers "X,Y,Z" (the model file's units).
bool parse_point(const std::string& text, double out[3]) {
  std::string rest = text;
  for (int a = 0; a < 3; ++a) {
    const size_t comma = rest.find(',');
    if ((a < 2) != (comma != std::string::npos)) return false;
    const std::string f = rest.substr(0, comma);
    char* end = nullptr;
    out[a] = std::strtod(f.c_str(), &end);
    if (f.empty() || end != f.c_str() + f.size() || !std::isfinite(out[a])) return false;
    rest = a < 2 ? rest.substr(comma + 1) : "";
  }
  return true;
}

// --eye and --look-at (file coordinates) to the view's azimuth and elevation: the direction
// from the look-at point to the eye, turned into the Z-up world (--up), is the view's
// direction toward the viewer, w = (-sin az cos el, -cos az cos el, sin el); both angles are
// rounded to millidegrees, as --view gives them.
bool camera_direction(const Options& o, View* view, std::string* error) {
  double eye[3], at[3], v[3], w[3];
  if (!parse_point(o.get("--eye"), eye) || !parse_point(o.get("--look-at"), at)) {
    *error = "--eye and --look-at must each be X,Y,Z (numbers, the model file's units): got '" +
             o.get("--eye") + "' and '" + o.get("--look-at") + "'";
    return false;
  }
  UpAxis up;
  if (!parse_up(o, &up, error)) return false;
  for (int a = 0; a < 3; ++a) v[a] = eye[a] - at[a];
  turn_z_up(up, v, w);
  const double len = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  if (!(len > 0)) {
    *error = "--eye and --look-at are the same point: the camera has no direction";
    return false;
  }
  const double deg = 180 / 3.14159265358979323846;
  const double el = std::asin(std::max(-1.0, std::min(1.0, w[2] / len))) * deg;
  const double az = std::atan2(-w[0], -w[1]) * deg;
  view->azimuth_mdeg = int32_t(std::lround(az * 1000));
  view->elevation_mdeg = int32_t(std::lround(el * 1000));
  return true;
}

// The camera options: --eye with --look-at instead of --view/--perspective, --fov only with
// them, --roll with either.
bool parse_camera(const Options& o, View* view, std::string* error) {
  const bool eye = !o.get("--eye").empty(), at = !o.get("--look-at").empty();
  int32_t mdeg = 0;
  if (!o.get("--roll").empty() && !parse_mdeg(o.get("--roll"), &mdeg)) {
    *error = "--roll '" + o.get("--roll") + "' must be an angle in degrees (up to three decimals)";
    return false;
  }
  if (!eye && !at) {
    if (o.get("--fov").empty()) return true;
    *error = "--fov is for a camera: give --eye X,Y,Z --look-at X,Y,Z with it";
    return false;
  }
  if (eye != at) {
    *error = eye ? "--eye needs --look-at X,Y,Z (the point the camera looks at)"
                 : "--look-at needs --eye X,Y,Z (where the camera is)";
    return false;
  }
  for (const char* other : {"--view", "--perspective"})
    if (!o.get(other).empty()) {
      *error = std::string(other) +
               " and --eye/--look-at both set the view: give one (--fov for a perspective "
               "camera)";
      return false;
    }
  double fov = 0;
  if (!camera_fov(o, &fov, error)) return false;
  return camera_direction(o, view, error);
}

}  // namespace

bool camera_fov(const Options& o, double* deg, std::string* error) {
  *deg = 0;
  const std::string f = o.get("--fov");
  if (f.empty()) return true;
  char* end = nullptr;
  *deg = std::strtod(f.c_str(), &end);
  if (end != f.c_str() + f.size() || !(*deg > 0 && *deg <= 170)) {
    *error = "--fov '" + f + "' must be an angle in degrees in (0, 170]";
    return false;
  }
  return true;
}

bool aim_view(const Options& o, ObjModel* model, View* view, std::string* error) {
  double fov = 0;
  int32_t roll_mdeg = 0;
  if (!o.get("--roll").empty()) parse_mdeg(o.get("--roll"), &roll_mdeg);
  if (!o.get("--eye").empty() && !camera_fov(o, &fov, error)) return false;
  const double pi = 3.14159265358979323846;
  std::vector<std::array<double, 3>> p(model->vertices.size());
  for (size_t i = 0; i < p.size(); ++i)
    p[i] = {double(model->vertices[i].x), double(model->vertices[i].y),
            double(model->vertices[i].z)};
  if (fov > 0) {
    // The look-at point becomes the world origin (the core's eye sits on the view axis through
    // it) and the eye backs off until the model's bounding sphere about that point fills the
    // field of view: D = ceil(R / sin(fov / 2)).
    double at[3], rel[3], shift[3];
    parse_point(o.get("--look-at"), at);
    for (int a = 0; a < 3; ++a) rel[a] = (at[a] - model->centre[a]) * model->scale;
    UpAxis up;
    parse_up(o, &up, error);
    turn_z_up(up, rel, shift);
    double r2 = 0;
    for (std::array<double, 3>& q : p) {
      for (int a = 0; a < 3; ++a) q[size_t(a)] -= std::round(shift[a]);
      r2 = std::max(r2, q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
    }
    const double d = std::ceil(std::sqrt(r2) / std::sin(fov * pi / 360));
    if (!(d <= 2 * kWorldLimit)) {
      *error = "--fov " + o.get("--fov") + " puts the eye beyond the world's range: widen it";
      return false;
    }
    view->perspective = std::max<int32_t>(1, int32_t(d));
  }
  if (roll_mdeg != 0) roll_about_view_axis(*view, roll_mdeg * pi / 180000, &p);
  for (size_t i = 0; i < p.size(); ++i) {
    for (int a = 0; a < 3; ++a)
      if (!(std::fabs(p[i][size_t(a)]) <= kWorldLimit)) {
        *error =
            "--look-at or --roll moves the model beyond the world's range: look at a point "
            "nearer the model";
        return false;
      }
    model->vertices[i] = Point3{int32_t(std::lround(p[i][0])), int32_t(std::lround(p[i][1])),
                                int32_t(std::lround(p[i][2]))};
  }
  return true;
}

bool parse_view(const Options& o, View* out, std::string* error) {
  View view;
  if (!parse_camera(o, &view, error)) return false;
  const std::string v = o.get("--view", "30,40");
  const size_t comma = v.find(',');
  if (o.get("--eye").empty() &&
      (comma == std::string::npos || !parse_mdeg(v.substr(0, comma), &view.azimuth_mdeg) ||
       !parse_mdeg(v.substr(comma + 1), &view.elevation_mdeg))) {
    *error = "--view '" + v + "' must be AZ,EL in degrees (up to three decimals)";
    return false;
  }
  if (!o.get("--perspective").empty()) {
    int64_t d = 0;
    if (!parse_int(o.get("--perspective"), 1, 2 * kWorldLimit, &d)) {
      *error = "--perspective '" + o.get("--perspective") + "' must be an integer in [1, 2097152]";
      return false;
    }
    view.perspective = int32_t(d);
  }
  // The plot area is the page's drawable area (export/page.h).
  Page page;
  int64_t per_mm = 80;
  if (!parse_page(o, &page, error)) return false;
  if (!o.get("--steps-per-mm").empty() && !parse_int(o.get("--steps-per-mm"), 1, 100000, &per_mm)) {
    *error = "--steps-per-mm '" + o.get("--steps-per-mm") + "' must be an integer in [1, 100000]";
    return false;
  }
  if (!page_area(page, uint32_t(per_mm), &view.margin, &view.width, &view.height)) {
    *error = "the page's drawable area at " + std::to_string(per_mm) +
             " steps/mm leaves the plotter's coordinate range";
    return false;
  }
  // Without --substep, the default where the plot area leaves room for it, else the most that
  // fits (a plot area near 2^20 steps has no bits to spare).
  view.substep_bits = kDefaultSubstepBits;
  while (view.substep_bits > 0 && !ok(validate(view))) --view.substep_bits;
  if (!o.get("--substep").empty()) {
    int64_t bits = 0;
    if (!parse_int(o.get("--substep"), 0, kMaxSubstepBits, &bits)) {
      *error = "--substep '" + o.get("--substep") + "' must be an integer in [0, " +
               std::to_string(kMaxSubstepBits) + "]";
      return false;
    }
    view.substep_bits = int32_t(bits);
    if (!ok(validate(view))) {
      *error = "--substep " + o.get("--substep") + ": the plot area times 2^" + o.get("--substep") +
               " leaves the coordinate range [0, 2^20)";
      return false;
    }
  }
  *out = view;
  return true;
}

namespace {

// Nothing at all to draw is an error, not an empty picture: no edges, or every edge seen
// end-on (all vertices equal, or a model of lines along the view direction).
// A model whose every edge the crease angle left out, drawn without its faces' contours.
std::string no_edges_left(const Options& o, const std::string& path) {
  return path + ": every edge lies within --crease " + o.get("--crease", "0") +
         " degrees of flat (or is flat but for the file's rounding), and a drawing of the edges "
         "alone (haloed, or --mode all) has no faces to find contours with: lower --crease, or "
         "draw it with --mode hidden-removed or hidden-dashed (contours kept)";
}

// The edges-only drawings (haloed, --mode all) have no hidden-line stage to find contours:
// where --crease left out a smooth surface's bends, its outline went with them, silently.
std::string no_contours_note(const Options& o, const std::string& path, const RepairReport& r,
                             const char* drawing) {
  if (r.bent_edges == 0) return "";
  return path + ": --crease " + o.get("--crease") + " left out " + std::to_string(r.bent_edges) +
         " edges where the surface bends, and " + drawing +
         " draws edges only, with no contours in their place, so the outline goes with them: "
         "--mode hidden-removed or hidden-dashed draws the contours (or lower --crease)";
}

bool something_to_draw(const std::string& path, const std::vector<Edge3>& edges,
                       std::string* error) {
  if (edges.empty()) {
    *error = path + ": no edges: nothing to draw";
    return false;
  }
  for (const Edge3& e : edges)
    if (e.a.x != e.b.x || e.a.y != e.b.y) return true;
  *error = path + ": all " + std::to_string(edges.size()) +
           " edges project to single points: nothing to draw";
  return false;
}

}  // namespace

bool load_scene(const Options& o, const std::string& path, std::vector<Edge3>* edges,
                std::string* error, int32_t* substep_bits) {
  int32_t units = 0;
  if (substep_bits != nullptr) *substep_bits = 0;
  if (!is_mesh_path(path)) {
    if (!o.get("--substep").empty()) {
      *error =
          "--substep is for .obj models: an .edges file is in steps, or says its units in "
          "a '# substep S' header";
      return false;
    }
    if (!o.get("--weld").empty()) {
      *error = "--weld is for models (.obj, .stl, .ply): an .edges file has no vertices to weld";
      return false;
    }
    // An .edges file is projected already: the view options have nothing to act on.
    for (const char* view : {"--view", "--perspective", "--up", "--crease", "--dump-edges", "--eye",
                             "--look-at", "--fov", "--roll"})
      if (!o.get(view).empty()) {
        *error = std::string(view) +
                 " is for models (.obj, .stl, .ply): an .edges file is a scene projected "
                 "already, drawn as it is";
        return false;
      }
    const InputError ie = read_edges_file(path, edges, &units);
    if (ie.failed()) *error = ie.message();
    if (substep_bits != nullptr) *substep_bits = units;
    return !ie.failed() && something_to_draw(path, *edges, error);
  }
  ObjModel model;
  std::vector<Point3> screen;
  View view;
  RepairReport repair;
  repair.measure_open = false;  // no shells message here: only the bent edges are counted
  if (!project_obj(o, path, &model, &screen, &view, error, &repair)) return false;
  units = view.substep_bits;
  if (substep_bits != nullptr) *substep_bits = units;
  Status s = Status::kOk;
  edges->resize(model.edge_pairs.size() / 2);
  if (ok(s))
    s = edges_from_indices(screen.data(), uint32_t(screen.size()), model.edge_pairs.data(),
                           uint32_t(edges->size()), edges->data());
  if (!ok(s)) {
    *error = path + ": projection failed: " + status_name(s);
    return false;
  }
  if (edges->empty() && !model.faces.empty()) {  // every side within the crease angle
    *error = no_edges_left(o, path);
    return false;
  }
  // Said once: a haloed plot reads the model here once; --mode all's pen outputs read it again
  // (cmd_plot_solid.cpp), after load_solid_scene said it.
  if (!o.get("--halo").empty()) {
    const std::string note = no_contours_note(o, path, repair, "a haloed drawing");
    if (!note.empty()) std::cerr << "haloplot: " << note << "\n";
  }
  return something_to_draw(path, *edges, error) && dump_edges(o, path, *edges, units, error);
}

std::string not_simple_message(const std::string& path, const ObjModel& model,
                               const TriangulateStats& stats) {
  const size_t f = size_t(stats.first_not_simple);
  const bool known = f < model.face_lines.size() && model.face_lines[f] > 0;
  return path +
         (known ? ":" + std::to_string(model.face_lines[f]) : ": face " + std::to_string(f)) +
         ": this face's boundary crosses itself, so no triangulation of it is right (" +
         std::to_string(stats.not_simple) + " such face" + (stats.not_simple > 1 ? "s" : "") +
         " in the model); split it into simple polygons";
}

// A dense smooth model plotted without --crease draws every facet, a blot where the surface is
// fine: say so when nearly every drawn edge bends gently (at least 10,000 of them, nine in ten).
std::string crease_hint(const std::string& path, const RepairReport& r) {
  if (r.gentle_edges < 10000 || uint64_t{r.gentle_edges} * 10 < uint64_t{r.kept_edges} * 9)
    return "";
  return path + ": " + std::to_string(r.gentle_edges) + " of the " + std::to_string(r.kept_edges) +
         " edges drawn join faces less than " + std::to_string(int(kGentleDegrees)) +
         " degrees apart, the facets of a smooth surface: --crease 40 draws its contours and "
         "the creases sharper than 40 degrees instead";
}

bool load_solid_scene(const Options& o, const std::string& path, SolidScene* scene,
                      TriangulateStats* stats, std::string* error) {
  if (!is_mesh_path(path)) {
    *error = path + ": hidden-line modes need faces: give a model (.obj, .stl or .ply)";
    return false;
  }
  ObjModel model;
  View view;
  // --mode all hides nothing: an open shell, or one that cannot be oriented, changes nothing
  // it draws, so it is not measured and not said (the fresh user read "so the hidden lines
  // are right" under a drawing with no hidden lines).
  const bool all = o.get("--mode") == "all";
  RepairReport repair;
  repair.measure_open = !all;
  if (!project_obj(o, path, &model, &scene->vertices, &view, error, &repair)) return false;
  scene->repair_note = all ? "" : shells_note(path, repair, o.get("--weld"));
  scene->repair_stats = shells_stats(repair, model.scale);
  // The hint leads to --crease, which only the hidden-line modes answer with contours.
  const std::string crease =
      all ? no_contours_note(o, path, repair, "--mode all") : crease_hint(path, repair);
  if (!crease.empty())
    scene->repair_note += (scene->repair_note.empty() ? "" : "\nhaloplot: ") + crease;
  scene->substep_bits = view.substep_bits;
  scene->edge_pairs = model.edge_pairs;
  TriangulateStats ts;
  scene->triangles = triangulate(model.vertices, model.faces, model.face_region, &ts);
  if (stats != nullptr) *stats = ts;
  if (ts.first_not_simple >= 0) {
    *error = not_simple_message(path, model, ts);
    return false;
  }
  if (!model_facing_of(view, model.vertices, scene, error)) return false;
  std::vector<Edge3> edges(model.edge_pairs.size() / 2);
  const Status s =
      edges_from_indices(scene->vertices.data(), uint32_t(scene->vertices.size()),
                         model.edge_pairs.data(), uint32_t(edges.size()), edges.data());
  if (!ok(s)) {
    *error = path + ": " + status_name(s);
    return false;
  }
  // Every edge may lie within the crease angle (a smooth model, --crease above its facets'
  // angle): the faces still have their contours, which the hidden-line stage finds itself.
  // The edges-only mode finds none.
  if (edges.empty() && !scene->triangles.empty()) {
    if (o.get("--mode") != "all") return dump_edges(o, path, edges, scene->substep_bits, error);
    *error = no_edges_left(o, path);
    return false;
  }
  return something_to_draw(path, edges, error) &&
         dump_edges(o, path, edges, scene->substep_bits, error);
}

bool model_facing_of(const View& view, const std::vector<Point3>& world, SolidScene* scene,
                     std::string* error) {
  scene->facing.clear();
  if (view.substep_bits == 0) return true;  // whole steps: the facing the geometry shows
  scene->facing.resize(scene->triangles.size());
  const Status s = model_facing(view, world.data(), uint32_t(world.size()), scene->triangles.data(),
                                uint32_t(scene->triangles.size()), scene->facing.data());
  if (!ok(s)) *error = "facing from the model failed: " + std::string(status_name(s));
  return ok(s);
}

namespace {

Options job_options(const JobFile& jf) {
  Options o;
  o.values = jf.solid_options;
  o = with_model_defaults(o, jf.scene_path);
  o.values["--steps-per-mm"] = std::to_string(jf.style.steps_per_mm);
  if (jf.outline) o.flags.insert("--outline");
  if (!jf.intersections) o.flags.insert("--no-intersections");
  if (jf.landscape) o.flags.insert("--landscape");
  return o;
}

}  // namespace

void say_repair_note(const SolidScene& scene) {
  if (!scene.repair_note.empty()) std::cerr << "haloplot: " << scene.repair_note << "\n";
}

bool job_solid_settings(const JobFile& jf, SolidOptions* so, View* view, std::string* error) {
  const Options o = job_options(jf);
  return parse_solid_options(o, so, error) && parse_view(o, view, error);
}

HiddenJob hidden_job(const SolidOptions& so) {
  return HiddenJob{so.method,
                   so.spec.outline,
                   so.spec.dash_steps,
                   so.spec.gap_steps,
                   so.hatch,
                   so.hatch_params.spacing,
                   so.hatch_params.angle_mdeg,
                   so.hatch_params.mdeg_per_depth,
                   so.spec.intersections};
}

bool load_solid_job_scene(const JobFile& jf, SolidScene* scene, HiddenJob* hidden,
                          std::string* error) {
  const Options o = job_options(jf);
  SolidOptions so;
  if (!parse_solid_options(o, &so, error)) return false;
  *hidden = hidden_job(so);
  if (!load_solid_scene(o, jf.scene_path, scene, nullptr, error)) return false;
  say_repair_note(*scene);
  return true;
}

bool load_job_scene(const JobFile& jf, std::vector<Edge3>* edges, std::string* error,
                    int32_t* substep_bits, LayerCounts* layers) {
  const Options o = job_options(jf);
  if (substep_bits != nullptr) *substep_bits = 0;
  if (layers != nullptr) *layers = LayerCounts{};
  if (jf.spec.drawing != DrawingEffect::kHiddenRemoved &&
      jf.spec.drawing != DrawingEffect::kHiddenDashed)
    return load_scene(o, jf.scene_path, edges, error, substep_bits);
  SolidOptions so;
  if (!parse_solid_options(o, &so, error)) return false;
  SolidScene scene;
  if (!load_solid_scene(o, jf.scene_path, &scene, nullptr, error)) return false;
  say_repair_note(scene);
  SolidRun run;
  const Status s = run_solid_options(scene, so, &run);
  if (!ok(s)) {
    *error = jf.scene_path + ": hidden lines failed: " + status_name(s);
    return false;
  }
  // Decided in the scene's units, drawn in steps: the strokes come out rounded (units 0).
  ModeDrawing d = make_mode_drawing(run, mode_in_units(so.spec, scene.substep_bits));
  drawing_to_steps(&d, scene.substep_bits);
  *edges = mode_strokes(d, layers);
  return true;
}

}  // namespace haloplot::host
