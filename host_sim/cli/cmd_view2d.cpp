// haloplot view2d POLYGON.txt --from X,Y -o OUT.svg [--spans OUT.spans]: which parts of a
// polygon are visible from a point in its plane (core/view2d, Freeman and Loutrel).
#include <algorithm>
#include <iostream>
#include <sstream>

#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/options.h"
#include "io/atomic_file.h"
#include "io/line_reader.h"
#include "io/polygon_file.h"
#include "render/view2d_svg.h"
#include "sim/simulator.h"

namespace haloplot::host {
namespace {

int view2d_fail(const std::string& m) { return fail("view2d: " + m); }

const char* config_name(ViewConfig c) {
  switch (c) {
    case ViewConfig::kFreeExterior:
      return "free exterior";
    case ViewConfig::kBlockedExterior:
      return "blocked exterior";
    case ViewConfig::kInterior:
      return "interior";
  }
  return "?";
}

// A visible part's ends, on its polygon edge.
void visible_ends(const std::vector<Point2>& poly, const VisibleSpan& v, int32_t* ax, int32_t* ay,
                  int32_t* bx, int32_t* by) {
  const uint32_t n = uint32_t(poly.size());
  visible_point(poly[v.edge], poly[(v.edge + 1) % n], v.s0, ax, ay);
  visible_point(poly[v.edge], poly[(v.edge + 1) % n], v.s1, bx, by);
}

std::string write_spans(const std::string& path, const std::vector<Point2>& poly,
                        const std::vector<VisibleSpan>& visible) {
  return write_atomically(path, [&](std::ostream& out) {
    out << "# haloplot view2d: visible parts, one per line: s EDGE X0 Y0 X1 Y1\n";
    for (const VisibleSpan& v : visible) {
      int32_t ax, ay, bx, by;
      visible_ends(poly, v, &ax, &ay, &bx, &by);
      out << "s " << v.edge << " " << ax << " " << ay << " " << bx << " " << by << "\n";
    }
    return true;
  });
}

// The visible parts through the planner and the step tick, like any drawing: moved so the
// polygon's lower-left corner sits at the plot's 400-step margin (plot steps are >= 0).
int write_trace(const std::string& path, const std::vector<Point2>& poly,
                const std::vector<VisibleSpan>& visible) {
  int32_t x0 = poly[0].x, y0 = poly[0].y;
  for (const Point2& q : poly) x0 = std::min(x0, q.x), y0 = std::min(y0, q.y);
  std::vector<Edge3> lines;
  for (const VisibleSpan& v : visible) {
    int32_t ax, ay, bx, by;
    visible_ends(poly, v, &ax, &ay, &bx, &by);
    lines.push_back({{ax - x0 + 400, ay - y0 + 400, 0}, {bx - x0 + 400, by - y0 + 400, 0}});
  }
  JobSpec spec;
  spec.drawing = DrawingEffect::kAllEdges;
  SimReport report;
  Status sim = Status::kOk;
  const std::string error = write_atomically(path, [&](std::ostream& out) {
    sim = simulate(spec, lines, &out, &report);
    return ok(sim);
  });
  if (!ok(sim)) return view2d_fail(std::string("trace: ") + status_name(sim));
  if (!error.empty()) return view2d_fail(error);
  return 0;
}

}  // namespace

int cmd_view2d(int argc, char** argv) {
  const Options o =
      parse_options(argc, argv, 2, {"--from", "-o", "--spans", "--trace"}, {"--stats"});
  if (!o.error.empty()) return view2d_fail(o.error);
  if (const std::string bad = svg_output_problem(o.get("-o")); !bad.empty())
    return view2d_fail(bad);
  if (o.positional.size() != 1 || o.get("--from").empty() || o.get("-o").empty())
    return view2d_fail(
        "usage: haloplot view2d POLYGON.txt --from X,Y -o OUT.svg [--spans OUT.spans] "
        "[--trace OUT.trace] [--stats]");
  std::vector<Point2> poly;
  const InputError ie = read_polygon_file(o.positional[0], &poly);
  if (ie.failed()) return view2d_fail(ie.message());
  const std::string from = o.get("--from");
  const size_t comma = from.find(',');
  int64_t ex = 0, ey = 0;
  if (comma == std::string::npos ||
      !parse_int(from.substr(0, comma), -kView2dLimit, kView2dLimit, &ex) ||
      !parse_int(from.substr(comma + 1), -kView2dLimit, kView2dLimit, &ey))
    return view2d_fail("--from '" + from + "' must be X,Y with integers in [-1048576, 1048576]");
  const Point2 eye{int32_t(ex), int32_t(ey)};
  std::vector<uint8_t> scratch(view2d_scratch_bytes(uint32_t(poly.size())));
  std::vector<VisibleSpan> visible;
  View2dStats st;
  uint32_t bad[2] = {0, 0};
  const Status s = view2d(poly.data(), uint32_t(poly.size()), eye, scratch.data(), scratch.size(),
                          VisibleSink{[](void* c, const VisibleSpan& v) {
                                        static_cast<std::vector<VisibleSpan>*>(c)->push_back(v);
                                        return Status::kOk;
                                      },
                                      &visible},
                          &st, bad);
  if (s == Status::kSelfIntersecting)
    return view2d_fail(o.positional[0] + ": polygon is not simple: edges " +
                       std::to_string(bad[0] + 1) + " and " + std::to_string(bad[1] + 1) +
                       " (from lines of vertices " + std::to_string(bad[0] + 1) + " and " +
                       std::to_string(bad[1] + 1) + ") meet");
  if (s == Status::kBadParameter)
    return view2d_fail("the vantage point (" + from + ") lies on the polygon");
  if (!ok(s)) return view2d_fail(status_name(s));
  std::string error = write_atomically(o.get("-o"), [&](std::ostream& out) {
    write_view2d_svg(out, poly, eye, visible);
    return true;
  });
  if (!error.empty()) return view2d_fail(error);
  if (!o.get("--spans").empty()) {
    error = write_spans(o.get("--spans"), poly, visible);
    if (!error.empty()) return view2d_fail(error);
  }
  if (!o.get("--trace").empty()) {
    if (const int rc = write_trace(o.get("--trace"), poly, visible)) return rc;
  }
  if (o.has("--stats"))
    std::cout << "configuration=" << config_name(st.config) << "\nvertices=" << poly.size()
              << "\nvisible_pieces=" << visible.size() << "\nprop3_edges=" << st.prop3_edges
              << "\nbackward_bays=" << st.backward_bays << "\nforward_bays=" << st.forward_bays
              << "\nvertex_tests=" << st.vertex_tests << "\n";
  return 0;
}

}  // namespace haloplot::host
