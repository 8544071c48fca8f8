#include "cli/haloed_outputs.h"

#include <cstdio>
#include <iostream>
#include <sstream>

#include "cli/command_line.h"
#include "cli/page_options.h"
#include "cli/plot_outputs.h"
#include "io/atomic_file.h"
#include "io/line_reader.h"
#include "io/spans_file.h"

namespace haloplot::host {

namespace {

std::string grid_text(const CutPlan& plan) {
  return std::to_string(plan.grid.nx) + "x" + std::to_string(plan.grid.ny);
}

}  // namespace

std::string cut_header(const HostCut& c) {
  std::ostringstream h;
  h << "# stats edges=" << c.set.n_edges << " crossings=" << c.stats.crossings
    << " near=" << c.stats.near_misses << " grid=" << grid_text(c.plan)
    << " cell=" << c.plan.grid.cell << " cell_pairs=" << c.stats.cell_pairs
    << " pairs_tested=" << c.stats.pairs_tested << " rejected=" << c.stats.rejected
    << " equal_depth=" << c.stats.equal_depth << "\n";
  return h.str();
}

void print_cut_stats(const HostCut& c) {
  // Each rounded up to 8 bytes, as CutStage carves them: their sum is what it asks for.
  auto carved = [](size_t bytes) { return (bytes + 7) & ~size_t{7}; };
  std::fprintf(stderr,
               "edges=%u\ncrossings=%llu\nnear=%llu\ngrid=%s\ncell=%d\ncell_pairs=%u\n"
               "pairs_tested=%llu\nrejected=%llu\nequal_depth=%llu\ncut_ms=%.3f\n"
               "cut_retries=%d\ncut_scratch_bytes=%zu\ncutset_bytes=%zu\n",
               c.set.n_edges, (unsigned long long)c.stats.crossings,
               (unsigned long long)c.stats.near_misses, grid_text(c.plan).c_str(), c.plan.grid.cell,
               c.stats.cell_pairs, (unsigned long long)c.stats.pairs_tested,
               (unsigned long long)c.stats.rejected, (unsigned long long)c.stats.equal_depth,
               c.cut_ms, c.retries, carved(c.scratch_bytes),
               carved(cutset_bytes(c.set.n_edges, c.set.n_crossings)));
}

void print_draw_stats(const HostDraw& d) {
  std::fprintf(stderr,
               "draw_ms=%.3f\nspans=%llu\ngaps=%llu\nhidden_edges=%llu\ndraw_scratch_bytes=%zu\n",
               d.draw_ms, (unsigned long long)d.stats.spans, (unsigned long long)d.stats.gaps,
               (unsigned long long)d.stats.hidden_edges, d.scratch_bytes);
}

int write_drawing(const Options& o, const HostDraw& d, bool model) {
  int64_t per_mm = 80;
  if (!o.get("--steps-per-mm").empty() && !parse_int(o.get("--steps-per-mm"), 1, 10000, &per_mm))
    return fail("--steps-per-mm '" + o.get("--steps-per-mm") +
                "' must be an integer in [1, 10000]");
  PlotSvgStyle style;
  std::string err;
  if (!parse_plot_svg_style(o, model, uint32_t(per_mm), &style, &err)) return fail(err);
  if (!o.get("-o").empty())
    err = write_plot_page(o.get("-o"), {StrokeLayer{"1 visible", d.spans, 1}}, model, &style);
  if (!err.empty()) return fail(err);
  // With --gcode or --hpgl the job's own plan reports its clean-up (write_planned_outputs).
  if (o.has("--stats") && !wants_plotter_outputs(o))
    print_clean_stats(style.path_stats, style.placement.steps_per_mm);
  if (!o.get("--spans").empty()) {
    err = write_atomically(o.get("--spans"), [&](std::ostream& out) {
      write_spans(out, d.spans);
      return true;
    });
    if (!err.empty()) return fail(err);
  }
  return 0;
}

void warn_reach(const HostDraw& d, int32_t halo, int32_t reach) {
  if (d.stats.reach_short)
    std::cerr << "haloplot: warning: exact halo " << halo << " exceeds the near-miss reach "
              << reach << " CUT used; near misses between " << reach << " and " << halo
              << " steps are not haloed (rerun cut with --reach " << halo << ")\n";
}

}  // namespace haloplot::host
