// pause_check JOB TRACE: is TRACE (a plot of JOB with feed holds in it, for example from the
// controller under QEMU after `haloplot send --pause-after`) the uninterrupted plot of JOB, as
// the pause test asks (tests/unit/test_pause.cpp)? The independent reader and checker decide:
// no speed change at one step beyond the acceleration bound away from the path's vertices, no
// step during a pen dwell or above the step rate, and the same pen drawing as `haloplot sim` of
// JOB without a hold (support/pen_drawing.h). Exit status 0 when it is, 1 with the reason.
#include <cstdio>
#include <fstream>
#include <sstream>

#include "cli/job_file.h"
#include "cli/scene_input.h"
#include "reference/trace_checker.h"
#include "sim/simulator.h"
#include "support/pen_drawing.h"
#include "support/trace_limits.h"

using namespace haloplot;
using namespace haloplot::host;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: pause_check JOB TRACE\n");
    return 2;
  }
  JobFile jf;
  const InputError e = read_job_file(argv[1], &jf);
  if (e.failed()) return std::fprintf(stderr, "%s\n", e.message().c_str()), 1;
  std::vector<Edge3> edges;
  std::string error;
  JobSpec spec = jf.spec;  // as `haloplot sim` runs it
  if (!load_job_scene(jf, &edges, &error, nullptr, &spec.layers))
    return std::fprintf(stderr, "%s\n", error.c_str()), 1;
  if (spec.drawing == DrawingEffect::kHiddenRemoved || spec.drawing == DrawingEffect::kHiddenDashed)
    spec.drawing = DrawingEffect::kAllEdges;
  if (!spec.effects.backlash) spec.machine.backlash[0] = spec.machine.backlash[1] = 0;
  std::ostringstream plain_text;
  SimReport r;
  const Status s = simulate(spec, edges, &plain_text, &r, jf.arena);
  if (!ok(s)) return std::fprintf(stderr, "sim: %s\n", status_name(s)), 1;
  std::ifstream in(argv[2], std::ios::binary);
  std::stringstream paused_text;
  paused_text << in.rdbuf();
  const auto plain = reference::parse_trace_independently(plain_text.str());
  const auto paused = reference::parse_trace_independently(paused_text.str());
  if (!paused.error.empty())
    return std::fprintf(stderr, "%s: %s\n", argv[2], paused.error.c_str()), 1;
  reference::Limits lim = test::trace_limits(spec, r.points);
  lim.dwell =
      spec.effects.pen_servo ? spec.machine.pen_travel_ticks + spec.machine.pen_settle_ticks : 0;
  const auto res = reference::check_trace(paused, lim);
  if (res.step_jumps > 0 || res.dwell_violations > 0 ||
      res.why.find("too fast") != std::string::npos)
    return std::fprintf(stderr, "%s: %s\n", argv[2], res.why.c_str()), 1;
  const size_t extra_pen = paused.pen.size() - plain.pen.size();
  if (paused.pen.size() < plain.pen.size() || extra_pen % 2 != 0)
    return std::fprintf(stderr, "%s: %zu pen changes, unpaused %zu\n", argv[2], paused.pen.size(),
                        plain.pen.size()),
           1;
  if (!test::same_drawing(test::drawn(paused), test::drawn(plain), &error))
    return std::fprintf(stderr, "%s: %s\n", argv[2], error.c_str()), 1;
  std::printf(
      "pause_check: the same drawing as the uninterrupted plot, %zu pen lifts for holds, worst "
      "speed change at one step %.3f of the bound\n",
      extra_pen / 2, res.worst_step_ratio);
  return 0;
}
