// The text formats: .edges errors name the file, line and problem; .cut round-trips exactly;
// crossing positions print as exactly rounded decimals.
#include <cmath>
#include <sstream>

#include "../check.h"
#include "../support/scenes.h"
#include "io/cut_file.h"
#include "io/edges_file.h"

using namespace haloplot;
using namespace haloplot::host;

static InputError parse(const std::string& text, std::vector<Edge3>* out) {
  std::istringstream in(text);
  return read_edges(in, "s.edges", out);
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
        "/nonexistent/x.edges: cannot open");

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
  const std::string two = "e 0 0 0 0 10 10 10\ne 1 0 10 0 10 0 10\n";
  CHECK(cut_error("e 1 0 0 0 1 1 1\n", 1, "out of order"));
  CHECK(cut_error(two + "c 0 5 5 5 0 cross\n", 3, "FRONT"));
  CHECK(cut_error(two + "c 0 0 5 5 0 cross\n", 3, "FRONT"));
  CHECK(cut_error(two + "c 0 1 5 5 4294967296 cross\n", 3, "T '"));
  CHECK(cut_error(two + "c 0 1 5 5 7 maybe\n", 3, "KIND"));
  CHECK(cut_error(two + "c 1 0 5 5 7 cross\nc 0 1 5 5 7 cross\n", 4, "grouped"));
  CHECK(cut_error(two + "c 0 1 5 5 7 cross\ne 2 1 1 1 1 1 1\n", 4, "after the first"));
  CHECK(cut_error(two + "x 0 1\n", 3, "unknown record"));
  {  // the fuzzer's crash input, replayed: no fault, no error
    std::istringstream vt("\v\n");
    LoadedCut l;
    CHECK(!read_cut(vt, "t.cut", &l).failed());
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
  return check::finish("io");
}
