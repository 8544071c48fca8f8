// haloplot draw SCENE.cut --halo W -o OUT.svg: the haloed drawing of a scene cut before, DRAW
// alone.
#include <cstdio>
#include <iterator>
#include <set>
#include <string>

#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/haloed_options.h"
#include "cli/haloed_outputs.h"
#include "cli/page_options.h"
#include "io/cut_file.h"
#include "pipeline/host_pipeline.h"
#include "pipeline/units.h"

namespace haloplot::host {

int cmd_draw(int argc, char** argv) {
  std::set<std::string> valued = {"-o", "--halo", "--spans", "--steps-per-mm"},
                        flags = {"--exact-halo", "--stats"};
  valued.insert(std::begin(kPageValued), std::end(kPageValued));
  flags.insert(std::begin(kPageFlags), std::end(kPageFlags));
  const Options o = parse_options(argc, argv, 2, valued, flags);
  if (!o.error.empty()) return fail(o.error);
  if (!one_input_and_output(o)) return bad_arguments(o, "draw", kDrawUsage);
  if (const std::string bad = svg_output_problem(o.get("-o")); !bad.empty()) return fail(bad);
  DrawParams dp;
  std::string error;
  if (!draw_params(o, &dp, &error)) return fail(error);
  LoadedCut lc;
  const InputError ie = read_cut_file(o.positional[0], &lc);
  if (ie.failed()) return fail(ie.message());
  HostDraw d;
  const Status s = host_draw(lc.set, draw_in_units(dp, lc.substep_bits), &d);
  if (!ok(s)) return fail_status("DRAW", s);
  warn_reach(d, dp.halo, lc.set.reach >> lc.substep_bits);
  spans_to_steps(&d.spans, lc.substep_bits);
  if (const int rc = write_drawing(o, d, false)) return rc;
  if (o.has("--stats")) {
    std::fprintf(stderr, "edges=%u\ncrossings=%u\ncut_ran=0\ncut_ms=0\n", lc.set.n_edges,
                 lc.set.n_crossings);
    print_draw_stats(d);
  }
  return 0;
}

}  // namespace haloplot::host
