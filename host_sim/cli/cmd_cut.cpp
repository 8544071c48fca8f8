// haloplot cut SCENE.edges -o SCENE.cut: the CUTSET of a scene (crossings and near misses),
// for draw to halo again and again at other widths without cutting again.
#include <cstdio>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/haloed_options.h"
#include "cli/haloed_outputs.h"
#include "cli/scene_input.h"
#include "io/atomic_file.h"
#include "io/cut_file.h"
#include "io/substep_header.h"
#include "pipeline/host_pipeline.h"
#include "pipeline/units.h"

namespace haloplot::host {

int cmd_cut(int argc, char** argv) {
  std::set<std::string> valued = kCutValued;
  const Options o = parse_options(argc, argv, 2, valued, {"--stats"});
  if (!o.error.empty()) return fail(o.error);
  if (!one_input_and_output(o)) return bad_arguments(o, "cut", kCutUsage);
  CutParams cp;
  std::string error;
  if (!cut_params(o, &cp, &error)) return fail(error);
  std::vector<Edge3> edges;
  int32_t units = 0;
  if (!load_scene(o, o.positional[0], &edges, &error, &units)) return fail(error);
  HostCut c;
  const Status s = host_cut(std::move(edges), cut_in_units(cp, units), &c);
  if (!ok(s)) return fail_status("CUT", s);
  error = write_atomically(o.get("-o"), [&](std::ostream& out) {
    write_cut(out, c.set, cut_header(c) + substep_header(units));
    return true;
  });
  if (!error.empty()) return fail(error);
  if (o.has("--stats")) print_cut_stats(c);
  return 0;
}

}  // namespace haloplot::host
