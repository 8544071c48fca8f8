#include "job/job.h"

namespace haloplot {
namespace {

size_t align8(size_t v) { return (v + 7) & ~size_t{7}; }

bool needs_faces(DrawingEffect d) {
  return d != DrawingEffect::kAllEdges && d != DrawingEffect::kHaloed;
}

struct SpanCollector {
  Segment2* out;
  uint32_t capacity, count;
  static Status emit(void* ctx, const Span& s) {
    auto* self = static_cast<SpanCollector*>(ctx);
    if (self->count == self->capacity) return Status::kSinkFull;
    self->out[self->count++] = Segment2{s.x0, s.y0, s.x1, s.y1};
    return Status::kOk;
  }
};

}  // namespace

Status job_bytes(const JobSpec& spec, const Edge3* edges, uint32_t n, uint32_t crossing_capacity,
                 JobBytes* bytes) {
  if (needs_faces(spec.drawing)) return Status::kBadParameter;
  JobBytes b;
  uint64_t max_spans = n;
  if (spec.drawing == DrawingEffect::kHaloed) {
    CutPlan plan;
    const Status s = plan_cut(edges, n, spec.cut, &plan);
    if (!ok(s)) return s;
    b.cut_scratch = align8(plan.scratch_bytes);
    b.cutset = align8(cutset_bytes(n, crossing_capacity));
    // DRAW's scratch is at most one Gap per record of the busiest edge: bounded by all records.
    b.draw_scratch = align8(size_t{crossing_capacity} * sizeof(Gap));
    max_spans += crossing_capacity;  // each gap splits an edge at most once more
  } else {
    for (uint32_t i = 0; i < n; ++i)
      if (!in_range(edges[i])) return Status::kCoordinateOutOfRange;
  }
  if (max_spans > 0x7fffffffu) return Status::kTooManyEdges;
  b.spans = align8(size_t(max_spans) * sizeof(Segment2));
  b.path = align8(path_plan_bytes(uint32_t(max_spans)));
  b.points = align8(size_t{path_points_max(uint32_t(max_spans))} * sizeof(PathPoint));
  *bytes = b;
  return Status::kOk;
}

Status job_prepare(const JobSpec& spec, const Edge3* edges, uint32_t n, uint32_t crossing_capacity,
                   void* buffer, size_t buffer_bytes, PreparedJob* out, JobCounters* counters) {
  JobCounters c;
  JobBytes b;
  Status s = job_bytes(spec, edges, n, crossing_capacity, &b);
  if (!ok(s)) return s;
  if (buffer_bytes < b.total()) return Status::kWorkspaceTooSmall;
  s = validate(spec.machine);
  if (!ok(s)) return s;
  uint8_t* p = static_cast<uint8_t*>(buffer);
  uint8_t* cut_scratch = p;
  uint8_t* cutset_mem = cut_scratch + b.cut_scratch;
  uint8_t* draw_scratch = cutset_mem + b.cutset;
  Segment2* spans = reinterpret_cast<Segment2*>(draw_scratch + b.draw_scratch);
  uint8_t* path_ws = reinterpret_cast<uint8_t*>(spans) + b.spans;
  PathPoint* points = reinterpret_cast<PathPoint*>(path_ws + b.path);
  const uint32_t span_capacity = uint32_t(b.spans / sizeof(Segment2));

  SpanCollector collect{spans, span_capacity, 0};
  PreparedJob job;
  if (spec.drawing == DrawingEffect::kHaloed) {
    CutPlan plan;
    s = plan_cut(edges, n, spec.cut, &plan);
    if (!ok(s)) return s;
    ++c.cut_runs;
    s = run_cut(plan, edges, cut_scratch, b.cut_scratch, cutset_mem, b.cutset, &job.cutset, &c.cut);
    if (!ok(s)) {
      if (counters) *counters = c;
      return s;
    }
    ++c.draw_runs;
    s = draw(job.cutset, spec.draw, draw_scratch, b.draw_scratch,
             SpanSink{&SpanCollector::emit, &collect}, &c.draw);
    if (!ok(s)) return s;
  } else {
    for (uint32_t i = 0; i < n; ++i)
      spans[collect.count++] = Segment2{edges[i].a.x, edges[i].a.y, edges[i].b.x, edges[i].b.y};
  }
  ++c.path_runs;
  uint32_t n_points = 0;
  s = plan_path(spans, collect.count, spec.start_x, spec.start_y, path_ws, b.path, points,
                path_points_max(collect.count), &n_points, &c.path);
  if (!ok(s)) return s;
  job.points = points;
  job.n_points = n_points;
  job.spans = spans;
  job.n_spans = collect.count;
  *out = job;
  if (counters) *counters = c;
  return Status::kOk;
}

}  // namespace haloplot
