// The text formats: .edges errors name the file, line and problem; .cut round-trips exactly;
// crossing positions print as exactly rounded decimals.
#include <cmath>
#include <sstream>

#include "../check.h"
#include "../support/scenes.h"
#include "io/cut_file.h"
#include "io/edges_file.h"
#include "pipeline/host_pipeline.h"

using namespace haloplot;
using namespace haloplot::host;

static InputError parse(const std::string& text, std::vector<Edge3>* out) {
  std::istringstream in(text);
  return read_edges(in, "s.edges", out);
}

static InputError parse_curves(const std::string& text, EdgesWithCurves* out) {
  std::istringstream in(text);
  return read_edges_with_curves(in, "s.edges", out);
}

static bool error_is(const InputError& e, int line, const std::string& fragment) {
  return e.failed() && e.line == line &&
         e.message().find("s.edges:" + std::to_string(line) + ": ") == 0 &&
         e.what.find(fragment) != std::string::npos;
}

int main() {
  std::vector<Edge3> e;
  CHECK(!parse("# comment\n\n1 2 3 4 5 6\r\n  7 8 9 10 11 12", &e)
             .failed());  // CRLF, no final newline
  CHECK_EQ(e.size(), size_t{2});
  CHECK_EQ(e[1].b.z, 12);
  CHECK(!parse("", &e).failed() && e.empty());
  // Found by fuzz_cut_file: a line of vertical tabs is blank, not a line with no fields.
  CHECK(!parse("\v\v\v\n\f\n1 2 3 4 5 6\n", &e).failed() && e.size() == 1);
  CHECK(error_is(parse("1 2 3 4 5\n", &e), 1, "expected 6 integers"));
  CHECK(error_is(parse("# x\n1 2 3 4 5 6 7\n", &e), 2, "found 7 fields"));
  CHECK(error_is(parse("1 2 3 4 5 6\n1 2 x 4 5 6\n", &e), 2, "field 3 'x'"));
  CHECK(error_is(parse("1 2 3 4 5 1048576\n", &e), 1, "field 6"));
  CHECK(error_is(parse("-1 2 3 4 5 6\n", &e), 1, "field 1"));
  CHECK(error_is(parse("1.5 2 3 4 5 6\n", &e), 1, "field 1"));
  CHECK(error_is(parse("99999999999999999999 2 3 4 5 6\n", &e), 1, "field 1"));
  CHECK(read_edges_file("/nonexistent/x.edges", &e).message() ==
        "/nonexistent/x.edges: cannot open: no such file");

  // .cut round trip: write a real CUTSET, read it back, get the same records and index.
  const auto edges = scenes::paper_random(1500, 50000, 4);
  CutParams cp;
  cp.reach = 30;
  HostCut c;
  CHECK(ok(host_cut(edges, cp, &c)));
  std::ostringstream out;
  write_cut(out, c.set, "# test\n");
  std::istringstream in(out.str());
  LoadedCut lc;
  const InputError err = read_cut(in, "t.cut", &lc);
  CHECK_MSG(!err.failed(), err.message());
  CHECK_EQ(lc.set.n_edges, c.set.n_edges);
  CHECK_EQ(lc.set.n_crossings, c.set.n_crossings);
  CHECK_EQ(lc.set.reach, 30);
  bool same = lc.set.n_crossings == c.set.n_crossings;
  for (uint32_t i = 0; same && i < c.set.n_crossings; ++i)
    same = lc.crossings[i].behind == c.set.crossings[i].behind &&
           lc.crossings[i].front == c.set.crossings[i].front &&
           lc.crossings[i].t == c.set.crossings[i].t;
  for (uint32_t i = 0; same && i <= c.set.n_edges; ++i) same = lc.first[i] == c.set.first[i];
  CHECK_MSG(same, ".cut did not round-trip");

  auto cut_error = [](const std::string& text, int line, const std::string& fragment) {
    std::istringstream s(text);
    LoadedCut l;
    const InputError e2 = read_cut(s, "t.cut", &l);
    return e2.failed() && e2.line == line && e2.what.find(fragment) != std::string::npos;
  };
  const std::string hdr = "# haloplot cutset v1\n# reach 0\n";
  // e0 and e2 cross at (4, 4), e2 in front; e2 and e1 cross at (6, 4), e1 in front; e3 meets
  // none of them. Records start on line 7.
  const std::string edges4 = hdr +
                             "e 0 0 0 0 10 10 0\ne 1 0 10 20 10 0 20\ne 2 0 4 10 10 4 10\n"
                             "e 3 8 0 5 10 0 5\n";
  const std::string c02 = "c 0 2 4.000 4.000 1717986918 cross\n";
  const std::string c21 = "c 2 1 6.000 4.000 2576980377 cross\n";
  {
    std::istringstream good(edges4 + c02 + c21);
    LoadedCut l;
    const InputError read = read_cut(good, "t.cut", &l);
    CHECK_MSG(!read.failed(), "true records are read: " + read.message());
  }
  CHECK(cut_error(hdr + "e 1 0 0 0 1 1 1\n", 3, "out of order"));
  CHECK(cut_error(edges4 + "c 0 5 4.000 4.000 0 cross\n", 7, "FRONT"));
  CHECK(cut_error(edges4 + "c 0 0 4.000 4.000 0 cross\n", 7, "FRONT"));
  CHECK(cut_error(edges4 + "c 0 2 4.000 4.000 4294967296 cross\n", 7, "T '"));
  CHECK(cut_error(edges4 + "c 0 2 4.000 4.000 1717986918 maybe\n", 7, "KIND"));
  CHECK(cut_error(edges4 + c21 + c02, 8, "grouped"));
  CHECK(cut_error(edges4 + c02 + "e 4 1 1 1 1 1 1\n", 8, "after the first"));
  CHECK(cut_error(edges4 + "x 0 1\n", 7, "unknown record"));
  // What the reader used to accept (issue 17): a bad header or version, a malformed X, a
  // near miss with reach 0, and records that are not true.
  CHECK(cut_error("e 0 0 0 0 10 10 0\n", 1, "first line must be '# haloplot cutset v1'"));
  CHECK(cut_error("# haloplot cutset v9\ne 0 0 0 0 10 10 0\n", 1, "version '9'"));
  CHECK(cut_error(edges4 + "c 0 2 69x1.000 4.000 1717986918 cross\n", 7, "X '69x1.000'"));
  CHECK(cut_error(edges4 + "c 0 2 4.000 4.000 1717986918 near\n", 0, "reach 0"));
  CHECK(cut_error(edges4 + "c 0 3 0.000 0.000 0 cross\n", 7, "do not cross"));
  CHECK(cut_error(edges4 + "c 2 0 4.000 4.000 1717986918 cross\n", 7, "not in front"));
  CHECK(cut_error(edges4 + "c 0 2 4.000 4.000 1717986919 cross\n", 7, "is not where they cross"));
  CHECK(cut_error(edges4 + "c 0 2 4.001 4.000 1717986918 cross\n", 7, "is not where T"));
  {  // the fuzzer's crash input, replayed: no fault, and refused for want of a header
    std::istringstream vt("\v\n");
    LoadedCut l;
    const InputError read = read_cut(vt, "t.cut", &l);
    CHECK(read.failed() && read.what.find("cutset v1") != std::string::npos);
  }

  // Decimal positions against long double, including negative directions.
  scenes::Rng r(3);
  for (int i = 0; i < 20000; ++i) {
    const int32_t a = int32_t(r.uniform(0, kCoordMax)), d = int32_t(r.uniform(-a, kCoordMax - a));
    const uint32_t t = uint32_t(r.next());
    const long double exact = a + (long double)d * t / 4294967296.0L;
    const std::string s = decimal_position(a, d, t);
    CHECK_MSG(std::fabs(std::stold(s) - exact) <= 0.0005L + 1e-9L, s);
  }
  // Bézier records: both kinds in one file, each edge keeping its data line's index.
  EdgesWithCurves wc;
  const InputError ce = parse_curves(
      "# substep 2\n1 2 3 4 5 6\nbezier 0 1 2 3 4 5 6 7 8 9 10 11\r\n7 8 9 10 11 12\n", &wc);
  CHECK_MSG(!ce.failed(), ce.message());
  CHECK(wc.edges.size() == 2 && wc.curves.size() == 1);
  CHECK(wc.edge_index == std::vector<uint32_t>({0, 2}) &&
        wc.curve_index == std::vector<uint32_t>{1});
  CHECK(wc.curves.size() == 1 && wc.curves[0].p[0].x == 0 && wc.curves[0].p[2].z == 8 &&
        wc.curves[0].p[3].z == 11);
  CHECK(error_is(parse_curves("1 2 3 4 5 6\nbezier 0 1 2 3 4 5 6 7 8 9 10\n", &wc), 2,
                 "expected 'bezier' and 12 integers"));
  CHECK(wc.edges.empty() && wc.curves.empty());  // nothing half-read is kept
  CHECK(error_is(parse_curves("bezier 0 1 2 3 4 5 6 7 8 9 10 1048576\n", &wc), 1,
                 "field 13 '1048576'"));
  CHECK(error_is(parse_curves("bezier 0 1 2 3 4 5 6 7 x 9 10 11\n", &wc), 1, "field 10 'x'"));
  // The readers of straight scenes refuse a curve by name, at its line.
  CHECK(error_is(parse("1 2 3 4 5 6\n# c\nbezier 0 1 2 3 4 5 6 7 8 9 10 11\n", &e), 3,
                 "Bézier edge"));
  CHECK(e.empty());
  // Write and read back: the same control points and edges.
  const std::vector<BezierEdge3> curves = {
      BezierEdge3{{{0, 0, 0}, {1048575, 5, 6}, {7, 8, 9}, {10, 11, 1048575}}},
      BezierEdge3{{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}, {10, 11, 12}}}};
  const std::vector<Edge3> straight = {Edge3{{1, 2, 3}, {4, 5, 6}}};
  std::ostringstream cw;
  write_edges_with_curves(cw, curves, straight, "# curves\n");
  const InputError rt = parse_curves(cw.str(), &wc);
  CHECK_MSG(!rt.failed(), rt.message());
  bool same_curves = wc.curves.size() == 2 && wc.edges.size() == 1 && wc.edges[0].b.z == 6;
  for (size_t k = 0; same_curves && k < 2; ++k)
    for (int i = 0; i < 4; ++i)
      same_curves = same_curves && wc.curves[k].p[i].x == curves[k].p[i].x &&
                    wc.curves[k].p[i].y == curves[k].p[i].y &&
                    wc.curves[k].p[i].z == curves[k].p[i].z;
  CHECK(same_curves);
  CHECK(read_edges_with_curves_file("/nonexistent/x.edges", &wc).message() ==
        "/nonexistent/x.edges: cannot open");
  return check::finish("io");
}
