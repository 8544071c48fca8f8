// haloplot random-scene --edges N --length L [--seed S] -o SCENE.edges: the HALO paper's EDGE
// distribution of random edges, for timing CUT and DRAW against the paper's.
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "cli/command_line.h"
#include "cli/commands.h"
#include "demo/random_scene.h"
#include "io/atomic_file.h"
#include "io/edges_file.h"
#include "io/line_reader.h"

namespace haloplot::host {
namespace {

// "0.01" -> 10000 millionths, without floating point.
bool parse_millionths(const std::string& s, int64_t* out) {
  const size_t dot = s.find('.');
  int64_t whole = 0, frac = 0;
  const std::string w = s.substr(0, dot);
  if (!parse_int(w.empty() ? "0" : w, 0, 1, &whole)) return false;
  std::string f = dot == std::string::npos ? "" : s.substr(dot + 1);
  if (f.size() > 6) return false;
  f.append(6 - f.size(), '0');
  if (!parse_int(f, 0, 999999, &frac)) return false;
  *out = whole * 1000000 + frac;
  return *out > 0 && *out <= 1000000;
}

}  // namespace

int cmd_random_scene(int argc, char** argv) {
  const Options o = parse_options(argc, argv, 2, {"-o", "--edges", "--length", "--seed"}, {});
  if (!o.error.empty()) return fail(o.error);
  for (const char* need : {"-o", "--edges", "--length"})
    if (o.get(need).empty())
      return fail(std::string("random-scene: missing ") + need + "\n" +
                  usage_of(kRandomSceneUsage));
  if (!o.positional.empty())
    return fail("random-scene: takes no input file\n" + usage_of(kRandomSceneUsage));
  int64_t n = 0, seed = 1, l = 0;
  std::string error;
  if (!read_int_option(o, "--edges", 1, 100000000, &n, &error) ||
      !read_int_option(o, "--seed", 0, INT64_MAX, &seed, &error))
    return fail(error);
  if (!parse_millionths(o.get("--length"), &l))
    return fail("--length '" + o.get("--length") +
                "' must be a decimal in (0, 1], at most 6 places");
  const std::vector<Edge3> edges = paper_random(uint32_t(n), l, uint64_t(seed));
  const std::string header =
      "# haloplot random scene (HALO paper EDGE distribution): N=" + o.get("--edges") +
      " L=" + o.get("--length") + " seed=" + std::to_string(seed) + "\n";
  error = write_atomically(o.get("-o"), [&](std::ostream& out) {
    write_edges(out, edges, header);
    return true;
  });
  return error.empty() ? 0 : fail(error);
}

}  // namespace haloplot::host
