// haloplot replay IN.trace -o OUT.svg: the drawing a step trace makes, the pen's strokes
// followed step by step, to check the plotter draws what DRAW decided.
#include <cstdio>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "cli/command_line.h"
#include "cli/commands.h"
#include "io/atomic_file.h"
#include "io/line_reader.h"
#include "render/svg.h"
#include "sim/replay.h"
#include "sim/trace.h"

namespace haloplot::host {

int cmd_replay(int argc, char** argv) {
  const Options o = parse_options(argc, argv, 2, {"-o"}, {"--stats"});
  if (!o.error.empty()) return fail(o.error);
  if (!one_input_and_output(o)) return bad_arguments(o, "replay", kReplayUsage);
  if (const std::string bad = svg_output_problem(o.get("-o")); !bad.empty()) return fail(bad);
  std::ifstream in(o.positional[0]);
  if (const InputError e = open_problem(o.positional[0], in); e.failed()) return fail(e.message());
  Trace t;
  const InputError ie = read_trace(in, o.positional[0], &t);
  if (ie.failed()) return fail(ie.message());
  const Replay rep = replay(t);
  const auto& strokes = rep.strokes;
  std::vector<Span> spans;
  uint64_t down_length = 0;
  for (const auto& stroke : strokes) {
    const auto pts = simplify(stroke, rep.scale, 1);
    for (size_t i = 1; i < pts.size(); ++i)
      down_length += length_floor(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
    if (pts.size() == 1) spans.push_back(Span{{0, 0, 0}, pts[0].x, pts[0].y, pts[0].x, pts[0].y});
    for (size_t i = 1; i < pts.size(); ++i)
      spans.push_back(Span{{0, 0, 0}, pts[i - 1].x, pts[i - 1].y, pts[i].x, pts[i].y});
  }
  const std::string error = write_atomically(o.get("-o"), [&](std::ostream& out) {
    write_svg(out, spans, SvgStyle{});
    return true;
  });
  if (!error.empty()) return fail(error);
  if (o.has("--stats"))
    std::fprintf(
        stderr, "strokes=%zu\npen_down_length=%llu\npen_up_length=%llu\nplot_s=%s\npen_lifts=%u\n",
        strokes.size(), (unsigned long long)down_length, (unsigned long long)rep.pen_up_length,
        thousandths(t.end_tick * 1000 / t.machine.tick_hz).c_str(), rep.pen_lifts);
  return 0;
}

}  // namespace haloplot::host
