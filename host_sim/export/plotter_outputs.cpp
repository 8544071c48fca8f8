#include "export/plotter_outputs.h"

#include <cmath>
#include <cstdio>

#include "export/exporters.h"
#include "haloplot/memory/sized_stage.h"
#include "haloplot/motion/planner.h"
#include "io/atomic_file.h"
#include "pipeline/host_memory.h"

namespace haloplot::host {

Status plan_job_path(const JobSpec& spec, const std::vector<Edge3>& edges, PlannedJob* out,
                     const std::vector<BezierEdge3>* curves) {
  *out = PlannedJob{};
  const uint32_t n = uint32_t(edges.size());
  // The job buffer from the core's own query; a second run if CUT needs more records.
  StageNeeds needs;
  needs.crossings = 4 * n + 1024;
  PreparedJob job;
  HostMemory memory;
  int rounds = 0;
  Status s = Status::kOk;
  if (curves != nullptr && !curves->empty()) {
    // The controller's first guess of the hit count (job_server.cpp plot_curves): the same
    // runs, so the counters match too.
    needs.crossings = 64;
    CurveJobStage stage{&spec,
                        CurveJobScene{curves->data(), uint32_t(curves->size()), edges.data(), n},
                        &job, &out->counters};
    s = run_sized(stage, memory.memory(), &needs, &rounds);
  } else {
    EdgeJobStage stage{&spec, Edges{edges.data(), n}, &job, &out->counters, &out->bytes};
    s = run_sized(stage, memory.memory(), &needs, &rounds);
  }
  out->retries = rounds - 1;
  if (!ok(s)) return s;
  out->points.assign(job.points, job.points + job.n_points);
  out->spans.assign(job.spans, job.spans + job.n_spans);
  out->layer_points = job.layer_points;
  return Status::kOk;
}

void add_travel_home(const JobSpec& spec, std::vector<PathPoint>* points) {
  if (spec.finish_home && !points->empty() && (points->back().x != 0 || points->back().y != 0))
    points->push_back(PathPoint{0, 0, 0});
}

namespace {

// Seconds one committed move takes: the trapezoid from its entry to its exit speed through its
// top speed, the top lowered to the peak the length allows (step_prep.cpp set_profile).
double move_seconds(const MotionItem& it) {
  const double length = double(it.length_q8) / 256;
  const double top2 = double(it.top_v2) / 256;
  if (length <= 0 || top2 <= 0) return 0;
  if (it.accel == 0) return length / std::sqrt(top2);
  const double a = it.accel, entry2 = double(it.entry_v2) / 256, exit2 = double(it.exit_v2) / 256;
  const double peak2 = std::max(std::min(top2, (2 * a * length + entry2 + exit2) / 2), entry2);
  const double exit2_reached = std::min(exit2, peak2);
  const double accel_len = (peak2 - entry2) / (2 * a),
               brake_len = (peak2 - exit2_reached) / (2 * a);
  const double cruise = std::max(0.0, length - accel_len - brake_len);
  const double peak = std::sqrt(peak2);
  return (peak - std::sqrt(entry2)) / a + (peak - std::sqrt(exit2_reached)) / a + cruise / peak;
}

}  // namespace

double estimate_plot_seconds(const JobSpec& spec, const std::vector<PathPoint>& points) {
  std::vector<uint64_t> workspace(MotionPlanner::workspace_bytes(spec.effects) / 8 + 1);
  PreparedJob job;
  job.points = points.data();
  job.n_points = uint32_t(points.size());
  MotionPlanner planner;
  if (!ok(init_planner(&planner, spec, job, workspace.data(), workspace.size() * 8))) return 0;
  double seconds = 0;
  MotionItem it;
  while (planner.next(&it))
    seconds += it.kind == MotionItem::kPen ? double(it.dwell_ticks) / spec.machine.tick_hz
                                           : move_seconds(it);
  return seconds;
}

WrittenFigures written_figures(const std::vector<PathPoint>& points, const ExportStyle& style) {
  WrittenFigures f;
  double x = -double(style.offset_x), y = -double(style.offset_y);
  bool down = false;
  for (const PathPoint& p : points) {
    const double length = std::hypot(p.x - x, p.y - y);
    if (p.pen_down != 0 && !down) ++f.strokes;
    down = p.pen_down != 0;
    (down ? f.pen_down : f.pen_up) += length;
    x = p.x, y = p.y;
  }
  return f;
}

double written_plot_seconds(const JobSpec& spec, const std::vector<PathPoint>& points,
                            const ExportStyle& style) {
  std::vector<PathPoint> paper;
  paper.reserve(points.size());
  for (const PathPoint& p : points)
    paper.push_back(PathPoint{p.x + style.offset_x, p.y + style.offset_y, p.pen_down});
  // The motion planner adds the travel home itself when the job ends there.
  if (spec.finish_home && !paper.empty() && paper.back().pen_down == 0 && paper.back().x == 0 &&
      paper.back().y == 0)
    paper.pop_back();
  return estimate_plot_seconds(spec, paper);
}

std::string written_summary(const JobSpec& spec, const std::vector<PathPoint>& points,
                            const ExportStyle& style) {
  const double seconds = written_plot_seconds(spec, points, style);
  const WrittenFigures f = written_figures(points, style);
  const long whole = long(seconds + 0.5);
  char time[112];
  if (whole >= 3600)  // hours, not "151 min"
    std::snprintf(time, sizeof time,
                  "plot time about %ld h %02ld min %02ld s (%.1f s by the motion planner's model)",
                  whole / 3600, whole / 60 % 60, whole % 60, seconds);
  else
    std::snprintf(time, sizeof time,
                  "plot time about %ld min %02ld s (%.1f s by the motion planner's model)",
                  whole / 60, whole % 60, seconds);
  return "haloplot: " + std::string(time) + "; " + std::to_string(f.strokes) +
         (f.strokes == 1 ? " stroke" : " strokes") + ", pen down " +
         mm_text(std::llround(f.pen_down), style.steps_per_mm) + " mm, pen up " +
         mm_text(std::llround(f.pen_up), style.steps_per_mm) + " mm";
}

void centre_on_page(const Page& page, bool finish_home, std::vector<PathPoint>* points,
                    ExportStyle* style) {
  centring_offset(page, style->steps_per_mm, *points, &style->offset_x, &style->offset_y);
  if (finish_home && !points->empty() && points->back().pen_down == 0 && points->back().x == 0 &&
      points->back().y == 0)
    points->back() = PathPoint{-style->offset_x, -style->offset_y, 0};
}

std::string write_plotter_outputs(const std::string& gcode_path, const std::string& hpgl_path,
                                  const std::vector<PathPoint>& points, const Machine& m,
                                  const ExportStyle& style, const LayerCounts& layers) {
  if (!gcode_path.empty()) {
    const std::string error = write_atomically(gcode_path, [&](std::ostream& out) {
      write_gcode(out, points, m, style, layers);
      return true;
    });
    if (!error.empty()) return error;
  }
  if (!hpgl_path.empty())
    return write_atomically(hpgl_path, [&](std::ostream& out) {
      write_hpgl(out, points, style, layers);
      return true;
    });
  return "";
}

}  // namespace haloplot::host
