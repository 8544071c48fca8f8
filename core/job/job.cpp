#include "haloplot/job/job.h"

#include "haloplot/geometry/units.h"
#include "haloplot/solid/modes.h"
#include "memory/carve.h"

namespace haloplot {
namespace {

bool needs_faces(DrawingEffect d) {
  return d != DrawingEffect::kAllEdges && d != DrawingEffect::kHaloed;
}

bool hidden_line_drawing(DrawingEffect d) {
  return d == DrawingEffect::kHiddenRemoved || d == DrawingEffect::kHiddenDashed;
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

// The job's lengths in the scene's units (JobSpec::substep_bits); everything else as given.
JobSpec in_units(const JobSpec& spec) {
  const int s = spec.substep_bits;
  JobSpec u = spec;
  u.draw.halo = steps_to_units(spec.draw.halo, s);
  u.cut.reach = steps_to_units(spec.cut.reach, s);
  u.hidden.dash = steps_to_units(spec.hidden.dash, s);
  u.hidden.gap = steps_to_units(spec.hidden.gap, s);
  u.hidden.hatch_spacing = steps_to_units(spec.hidden.hatch_spacing, s);
  return u;
}

bool units_ok(const JobSpec& spec) {
  return spec.substep_bits >= 0 && spec.substep_bits <= kMaxSubstepBits;
}

// Layers group the edges of a drawing-all job (one span each), all of them; DRAW's spans and
// a hidden-line job's strokes are grouped by the job itself.
bool layers_ok(const JobSpec& spec, uint32_t n) {
  if (spec.layers.n <= 1) return spec.layers.n == 0 || spec.layers.count[0] == n;
  if (spec.drawing != DrawingEffect::kAllEdges || spec.layers.n > kMaxLayers) return false;
  uint64_t total = 0;
  for (uint32_t k = 0; k < spec.layers.n; ++k) total += spec.layers.count[k];
  return total == n;
}

// The peak of the three stages (see job.h).
size_t peak_of(const JobBytes& b) {
  size_t peak = b.cut_scratch;
  if (b.spans + b.draw_scratch > peak) peak = b.spans + b.draw_scratch;
  if (b.spans + b.points + b.path > peak) peak = b.spans + b.points + b.path;
  return b.cutset + peak;
}

// Span and path bytes for at most `spans` spans.
void size_path_stages(uint64_t spans, JobBytes* b) {
  b->spans = carve_round(size_t(spans) * sizeof(Segment2));
  b->path = carve_round(path_plan_bytes(uint32_t(spans)));
  b->points = carve_round(size_t{path_points_max(uint32_t(spans))} * sizeof(PathPoint));
}

}  // namespace

namespace {

// The job's hatching, in the scene's units (`spec` converted): no line shorter than a step.
HatchParams hatch_params(const JobSpec& spec) {
  const HiddenJob& h = spec.hidden;
  HatchParams p;
  p.min_length = int32_t{1} << spec.substep_bits;
  p.spacing = h.hatch_spacing;
  p.angle_mdeg = h.hatch_angle_mdeg;
  p.mdeg_per_depth = h.hatch_mdeg_per_depth;
  return p;
}

}  // namespace

BandSpec band_spec(const JobSpec& steps) {
  const JobSpec spec = in_units(steps);
  BandSpec bs;
  bs.substep_bits = spec.substep_bits;
  bs.haloed = spec.drawing == DrawingEffect::kHaloed;
  bs.draw = spec.draw;
  bs.cut = spec.cut;
  bs.start_x = spec.start_x;
  bs.start_y = spec.start_y;
  // No minimum stroke in a band (a border cuts strokes a band cannot see whole); the
  // simplification holds for each part as for a whole stroke.
  bs.clean = PathClean{spec.clean.on, 0, spec.clean.simplify};
  bs.style = StrokeStyle{spec.drawing == DrawingEffect::kHiddenDashed ? SolidMode::kHiddenDashed
                                                                      : SolidMode::kHiddenRemoved,
                         spec.hidden.dash, spec.hidden.gap};
  bs.outline = spec.hidden.outline;
  bs.intersections = spec.hidden.intersections;
  bs.hatch = spec.hidden.hatch;
  bs.hatch_params = hatch_params(spec);
  return bs;
}

Status job_bytes(const JobSpec& steps, Edges in, uint32_t crossing_capacity, JobBytes* bytes) {
  const Edge3* edges = in.data;
  const uint32_t n = in.count;
  if (needs_faces(steps.drawing) || !units_ok(steps) || !layers_ok(steps, n))
    return Status::kBadParameter;
  const JobSpec spec = in_units(steps);
  JobBytes b;
  uint64_t max_spans = n;
  if (spec.drawing == DrawingEffect::kHaloed) {
    CutPlan plan;
    const Status s = plan_cut(edges, n, spec.cut, &plan);
    if (!ok(s)) return s;
    b.cut_scratch = carve_round(plan.scratch_bytes);
    b.cutset = carve_round(cutset_bytes(n, crossing_capacity));
    // DRAW's scratch is one Gap per record of the busiest edge: at most all records.
    b.draw_scratch = carve_round(size_t{crossing_capacity} * sizeof(Gap));
    max_spans += crossing_capacity;  // each gap splits an edge at most once more
  } else {
    for (uint32_t i = 0; i < n; ++i)
      if (!in_range(edges[i])) return Status::kCoordinateOutOfRange;
  }
  if (max_spans > 0x7fffffffu) return Status::kTooManyEdges;
  size_path_stages(max_spans, &b);
  b.peak = peak_of(b);
  *bytes = b;
  return Status::kOk;
}

Status job_crossings(const JobSpec& steps, Edges in, void* buffer, size_t buffer_bytes,
                     uint32_t* capacity) {
  const Edge3* edges = in.data;
  const uint32_t n = in.count;
  *capacity = 0;
  if (needs_faces(steps.drawing) || !units_ok(steps) || !layers_ok(steps, n))
    return Status::kBadParameter;
  if (buffer_misaligned(buffer)) return Status::kMisalignedBuffer;
  if (steps.drawing != DrawingEffect::kHaloed) return Status::kOk;
  const JobSpec spec = in_units(steps);
  CutPlan plan;
  Status s = plan_cut(edges, n, spec.cut, &plan);
  if (!ok(s)) return s;
  // A CUTSET of no records: run_cut() counts every record past the capacity and stores none.
  const size_t cutset_size = carve_round(cutset_bytes(n, 0));
  const size_t scratch = carve_round(plan.scratch_bytes);
  if (buffer_bytes < cutset_size + scratch) return Status::kWorkspaceTooSmall;
  uint8_t* base = static_cast<uint8_t*>(buffer);
  CutSet cs;
  CutStats st;
  s = run_cut(plan, edges, base + cutset_size, scratch, base, cutset_size, &cs, &st);
  if (!ok(s) && s != Status::kCrossingCapacity) return s;
  const uint64_t records = st.crossings + st.near_misses;
  if (records > 0xffffffffu) return Status::kCrossingCapacity;
  *capacity = uint32_t(records);
  return Status::kOk;
}

namespace {

// Stage 3: the path, after the spans (DRAW's scratch is dead by now).
Status plan_stage(const JobSpec& spec, uint8_t* base, size_t spans_offset, size_t spans_size,
                  size_t buffer_bytes, const SpanCollector& collect, const LayerCounts& layers,
                  PreparedJob* job, JobCounters* c) {
  JobBytes stage;
  size_path_stages(collect.count, &stage);
  uint8_t* points_mem = base + spans_offset + spans_size;
  if (buffer_bytes < spans_offset + spans_size + stage.points + stage.path)
    return Status::kWorkspaceTooSmall;
  ++c->path_runs;
  // The spans to whole steps: the one rounding between the scene's units and the pen.
  round_to_steps(collect.out, collect.count, spec.substep_bits);
  uint32_t n_points = 0;
  LayerCounts layer_points;
  const Status s = plan_path_layers(
      collect.out, collect.count, layers, spec.start_x, spec.start_y, points_mem + stage.points,
      stage.path, reinterpret_cast<PathPoint*>(points_mem), path_points_max(collect.count),
      &n_points, &layer_points, &c->path, spec.clean);
  if (!ok(s)) return s;
  job->layer_points = layer_points;
  job->points = reinterpret_cast<PathPoint*>(points_mem);
  job->n_points = n_points;
  job->spans = collect.out;
  job->n_spans = collect.count;
  return Status::kOk;
}

// Stages 2 and 3 for a haloed drawing: DRAW from the CUTSET at the start of the buffer (into
// the space CUT's scratch held), then the path.
Status draw_stage(const JobSpec& spec, uint32_t n, size_t cutset_size, uint8_t* base,
                  size_t buffer_bytes, PreparedJob* job, JobCounters* c) {
  const uint64_t span_bound = uint64_t{n} + job->cutset.n_crossings;
  const size_t spans_size = carve_round(size_t(span_bound) * sizeof(Segment2));
  const size_t draw_size = carve_round(draw_scratch_bytes(job->cutset));
  if (buffer_bytes < cutset_size + spans_size + draw_size) return Status::kWorkspaceTooSmall;
  SpanCollector collect{reinterpret_cast<Segment2*>(base + cutset_size), uint32_t(span_bound), 0};
  ++c->draw_runs;
  const Status s = draw(job->cutset, spec.draw, base + cutset_size + spans_size, draw_size,
                        SpanSink{&SpanCollector::emit, &collect}, &c->draw);
  if (!ok(s)) return s;
  return plan_stage(spec, base, cutset_size, spans_size, buffer_bytes, collect, LayerCounts{}, job,
                    c);
}

}  // namespace

namespace {
// A failed call leaves no drawing behind: the PreparedJob of an earlier call, left in place,
// would be taken for this one's (its points may lie in memory the failed run overwrote).
// job_redraw keeps the CUTSET it reads, so another halo can still be tried.
void clear_drawing(PreparedJob* job, bool keep_cutset) {
  const CutSet cutset = job->cutset;
  *job = PreparedJob{};
  if (keep_cutset) job->cutset = cutset;
}
}  // namespace

Status job_prepare(const JobSpec& steps, Edges in, uint32_t crossing_capacity, void* buffer,
                   size_t buffer_bytes, PreparedJob* out, JobCounters* counters) {
  const Edge3* edges = in.data;
  const uint32_t n = in.count;
  clear_drawing(out, false);
  JobCounters c;
  if (needs_faces(steps.drawing) || !units_ok(steps) || !layers_ok(steps, n))
    return Status::kBadParameter;
  if (buffer_misaligned(buffer)) return Status::kMisalignedBuffer;
  const JobSpec spec = in_units(steps);
  Status s = validate(spec.machine);
  if (!ok(s)) return s;
  uint8_t* base = static_cast<uint8_t*>(buffer);
  PreparedJob job;
  if (spec.drawing == DrawingEffect::kHaloed) {
    // Stage 1: CUT. The CUTSET first (it outlives CUT), its scratch after it.
    CutPlan plan;
    s = plan_cut(edges, n, spec.cut, &plan);
    if (!ok(s)) return s;
    const size_t cutset_size = carve_round(cutset_bytes(n, crossing_capacity));
    const size_t scratch = carve_round(plan.scratch_bytes);
    if (buffer_bytes < cutset_size + scratch) return Status::kWorkspaceTooSmall;
    ++c.cut_runs;
    s = run_cut(plan, edges, base + cutset_size, scratch, base, cutset_size, &job.cutset, &c.cut);
    if (ok(s)) s = draw_stage(spec, n, cutset_size, base, buffer_bytes, &job, &c);
  } else {
    for (uint32_t i = 0; i < n; ++i)
      if (!in_range(edges[i])) return Status::kCoordinateOutOfRange;
    const size_t spans_size = carve_round(size_t{n} * sizeof(Segment2));
    if (buffer_bytes < spans_size) return Status::kWorkspaceTooSmall;
    SpanCollector collect{reinterpret_cast<Segment2*>(base), n, 0};
    for (uint32_t i = 0; i < n; ++i)
      collect.out[collect.count++] =
          Segment2{edges[i].a.x, edges[i].a.y, edges[i].b.x, edges[i].b.y};
    s = plan_stage(spec, base, 0, spans_size, buffer_bytes, collect, spec.layers, &job, &c);
  }
  if (counters) *counters = c;
  if (!ok(s)) return s;
  *out = job;
  return Status::kOk;
}

Status job_redraw(const JobSpec& steps, Edges edges, uint32_t crossing_capacity, void* buffer,
                  size_t buffer_bytes, PreparedJob* job, JobCounters* counters) {
  clear_drawing(job, true);
  const uint32_t n = edges.count;
  if (steps.drawing != DrawingEffect::kHaloed || job->cutset.edges == nullptr ||
      job->cutset.n_edges != n || !units_ok(steps))
    return Status::kBadParameter;
  if (buffer_misaligned(buffer)) return Status::kMisalignedBuffer;
  const JobSpec spec = in_units(steps);
  Status s = validate(spec.machine);
  if (!ok(s)) return s;
  JobCounters c;
  PreparedJob next;
  next.cutset = job->cutset;
  s = draw_stage(spec, n, carve_round(cutset_bytes(n, crossing_capacity)),
                 static_cast<uint8_t*>(buffer), buffer_bytes, &next, &c);
  if (counters) *counters = c;
  if (!ok(s)) return s;
  *job = next;
  return Status::kOk;
}

namespace {

// The layers a hidden-line job draws in turn (motion/path_plan.h LayerCounts), as the plot
// SVG orders them.
enum StrokeLayer : uint8_t { kVisible, kHidden, kIntersection, kHatching, kOutline };

// Strokes gathered in the hidden-line run's free tail: upwards from its start, and each
// stroke's layer (a byte) downwards from its end.
struct StrokeCollector {
  Segment2* out = nullptr;
  uint8_t* layer_end = nullptr;  // stroke i's layer is layer_end[-1 - i]
  uint32_t capacity = 0, count = 0;
  StrokeStyle style;
  uint32_t n_drawn = 0;
  DashedRuns runs;        // a hidden run's dashes from its start, across its pieces (solid/modes.h)
  bool counting = false;  // job_solid_bytes(): strokes counted, none stored
  uint8_t* tail = nullptr;  // where the run's free tail began

  Status add(const Span& s, uint8_t layer) {
    if (counting) {
      ++count;
      return Status::kOk;
    }
    if (count == capacity) return Status::kSinkFull;
    layer_end[-1 - int64_t{count}] = layer;
    out[count++] = Segment2{s.x0, s.y0, s.x1, s.y1};
    return Status::kOk;
  }
  static void begin(void* ctx, uint8_t* tail, size_t bytes, const Edge3*) {
    auto* self = static_cast<StrokeCollector*>(ctx);
    self->tail = tail;
    self->out = reinterpret_cast<Segment2*>(tail);
    self->layer_end = tail + bytes;
    const size_t n = bytes / (sizeof(Segment2) + 1);
    self->capacity = n > 0x7fffffffu ? 0x7fffffffu : uint32_t(n);
    self->runs.clear();
  }
  // A piece's call first strokes the hidden run held before it (dashes), then the piece's own
  // stroke when it is visible (one span): the host's drawing (pipeline/drawing_modes.cpp)
  // sorts its strokes into layers the same way.
  static Status piece(void* ctx, const HiddenPiece& p) {
    auto* self = static_cast<StrokeCollector*>(ctx);
    const uint32_t before = self->count;
    const PieceKind kind = p.edge < self->n_drawn ? PieceKind::kEdge
                           : p.face[0] != kNoFace ? PieceKind::kLine
                                                  : PieceKind::kContour;
    const Status s = self->runs.piece(*p.geometry, p.edge, kind, p.t0, p.t1, p.hidden, p.q,
                                      self->style, Emit{self});
    if (ok(s) && !p.hidden && self->count > before && !self->counting)
      self->layer_end[-int64_t{self->count}] = p.hatch                ? kHatching
                                               : p.face[0] != kNoFace ? kIntersection
                                                                      : kVisible;
    return s;
  }
  static Status outline(void* ctx, const OutlinePiece& p) {
    auto* self = static_cast<StrokeCollector*>(ctx);
    const Status s = self->finish();
    return ok(s) ? self->add(make_stroke(*p.geometry, p.edge, p.t0, p.t1), kOutline) : s;
  }
  // The last hidden run's dashes.
  Status finish() { return runs.finish(style, Emit{this}); }
  struct Emit {
    StrokeCollector* self;
    Status operator()(const Span& s, int32_t) const { return self->add(s, kHidden); }
  };
};

// The strokes from the tail to the front of the buffer, layer by layer (in the order they came
// within each), through scratch after them; the layers' bytes stay at the tail's end until the
// move is done. kWorkspaceTooSmall when the scratch does not fit: the path would not either.
Status strokes_to_front(const StrokeCollector& c, uint8_t* base, LayerCounts* layers) {
  *layers = LayerCounts{};
  if (c.count == 0) return Status::kOk;
  Segment2* front = reinterpret_cast<Segment2*>(base);
  // Forward copy: the strokes move down.
  for (uint32_t i = 0; i < c.count; ++i) front[i] = c.out[i];
  const size_t front_bytes = carve_round(size_t{c.count} * sizeof(Segment2));
  Segment2* scratch = reinterpret_cast<Segment2*>(base + front_bytes);
  if (2 * front_bytes > size_t(c.layer_end - base) - c.count) return Status::kWorkspaceTooSmall;
  layers->n = kMaxLayers;
  for (uint32_t i = 0; i < c.count; ++i) ++layers->count[c.layer_end[-1 - int64_t{i}]];
  uint32_t at[kMaxLayers] = {};
  for (uint32_t k = 1; k < kMaxLayers; ++k) at[k] = at[k - 1] + layers->count[k - 1];
  for (uint32_t i = 0; i < c.count; ++i) scratch[at[c.layer_end[-1 - int64_t{i}]]++] = front[i];
  for (uint32_t i = 0; i < c.count; ++i) front[i] = scratch[i];
  return Status::kOk;
}

// The hidden-line run of a solid job with its strokes gathered by `collect` (or counted).
Status solid_lines(const JobSpec& spec, const SolidInput& in, uint32_t crossing_capacity,
                   uint32_t incidence_capacity, uint8_t* base, size_t buffer_bytes,
                   StrokeCollector* collect, HiddenReport* report) {
  HiddenParams hp;
  hp.method = spec.hidden.method;
  hp.outline = spec.hidden.outline;
  hp.intersections = spec.hidden.intersections;
  hp.hatch = spec.hidden.hatch;
  hp.hatch_params = hatch_params(spec);
  hp.cut = spec.cut;
  hp.crossing_capacity = crossing_capacity;
  hp.incidence_capacity = incidence_capacity;
  collect->style =
      StrokeStyle{spec.drawing == DrawingEffect::kHiddenDashed ? SolidMode::kHiddenDashed
                                                               : SolidMode::kHiddenRemoved,
                  spec.hidden.dash, spec.hidden.gap};
  collect->n_drawn = in.n_edges;
  const Status s = hidden_lines(in, hp, base, buffer_bytes,
                                HiddenSink{&StrokeCollector::begin, &StrokeCollector::piece,
                                           &StrokeCollector::outline, collect},
                                report);
  return ok(s) ? collect->finish() : s;  // into the tail still: nothing else uses it now
}

// A solid job's settings in units, checked.
Status solid_job_spec(const JobSpec& steps, const void* buffer, JobSpec* spec) {
  if (!hidden_line_drawing(steps.drawing) || !units_ok(steps)) return Status::kBadParameter;
  if (buffer_misaligned(buffer)) return Status::kMisalignedBuffer;
  *spec = in_units(steps);
  if (spec->hidden.dash < 1 || spec->hidden.gap < 1 || spec->hidden.dash > kCoordMax ||
      spec->hidden.gap > kCoordMax)
    return Status::kBadParameter;
  return validate(spec->machine);
}

}  // namespace

Status job_prepare_solid(const JobSpec& steps, const SolidInput& in, uint32_t crossing_capacity,
                         uint32_t incidence_capacity, void* buffer, size_t buffer_bytes,
                         PreparedJob* out, JobCounters* counters, HiddenReport* report) {
  clear_drawing(out, false);
  JobSpec spec;
  Status s = solid_job_spec(steps, buffer, &spec);
  if (!ok(s)) return s;
  uint8_t* base = static_cast<uint8_t*>(buffer);
  StrokeCollector collect;
  JobCounters c;
  s = solid_lines(spec, in, crossing_capacity, incidence_capacity, base, buffer_bytes, &collect,
                  report);
  c.cut = report->cut;
  ++c.cut_runs;
  if (counters) *counters = c;
  if (!ok(s)) return s;
  // The strokes to the front (the run's memory is dead now), grouped by layer.
  LayerCounts layers;
  s = strokes_to_front(collect, base, &layers);
  if (!ok(s)) return s;
  SpanCollector spans{reinterpret_cast<Segment2*>(base), collect.count, collect.count};
  PreparedJob job;
  s = plan_stage(spec, base, 0, carve_round(size_t{collect.count} * sizeof(Segment2)), buffer_bytes,
                 spans, layers, &job, &c);
  if (counters) *counters = c;
  if (!ok(s)) return s;
  *out = job;
  return Status::kOk;
}

Status job_solid_bytes(const JobSpec& steps, const SolidInput& in, void* buffer,
                       size_t buffer_bytes, StageNeeds* needs, HiddenReport* report) {
  *needs = StageNeeds{};
  JobSpec spec;
  Status s = solid_job_spec(steps, buffer, &spec);
  if (!ok(s)) return s;
  uint8_t* base = static_cast<uint8_t*>(buffer);
  StrokeCollector collect;
  StageNeeds n;
  // From no capacity up to what the run reports: records, incidences, then a run that fits.
  for (int pass = 0; pass < kSizedRounds; ++pass) {
    collect = StrokeCollector{};
    collect.counting = true;
    s = solid_lines(spec, in, n.crossings, n.incidences, base, buffer_bytes, &collect, report);
    StageNeeds want = n;
    hidden_lines_needs(s, *report, buffer_bytes, &want);
    if (s != Status::kCrossingCapacity && s != Status::kIncidenceCapacity) break;
    if (!raise_needs(&n, want)) break;
  }
  if (!ok(s)) return s;
  // The job's three checks: the run below its tail with the strokes and their layer bytes in
  // it; the move to the front through scratch of the same size; the strokes and the path.
  const size_t strokes = carve_round(size_t{collect.count} * sizeof(Segment2));
  JobBytes path;
  size_path_stages(collect.count, &path);
  const size_t below = collect.tail != nullptr ? size_t(collect.tail - base) : 0;  // no sink call
  // The run's own high-water mark may lie above the tail it gave the sink: CUT's scratch and
  // full CUTSET capacity, given back before the tail was handed on (solid/hidden_lines.cpp).
  const size_t strokes_run = below + size_t{collect.count} * (sizeof(Segment2) + 1);
  const size_t run = strokes_run > report->bytes_used ? strokes_run : report->bytes_used;
  const size_t move = 2 * strokes + collect.count;
  const size_t plan = strokes + path.points + path.path;
  n.bytes = run > move ? run : move;
  if (plan > n.bytes) n.bytes = plan;
  *needs = n;
  return Status::kOk;
}

void curve_job_params(const JobSpec& steps, CurveCrossParams* cross, CurveDrawParams* draw) {
  const JobSpec spec = in_units(steps);
  *cross = CurveCrossParams{};
  cross->segment_pairs = true;
  cross->flat_tol = uint64_t(steps_to_units(kCurveJobPieceSteps, spec.substep_bits))
                    << kCurveFracBits;
  *draw = CurveDrawParams{};
  draw->halo = spec.draw.halo;
}

namespace {

struct ChordCounter {
  static Status emit(void* ctx, const Span&) {
    ++*static_cast<uint32_t*>(ctx);
    return Status::kOk;
  }
};

// Says what a retry needs, and that this buffer is too small for it.
Status short_of(size_t bytes, size_t* need_bytes) {
  if (need_bytes != nullptr) *need_bytes = bytes;
  return Status::kWorkspaceTooSmall;
}

// The crossings, hits at the buffer's front (`steps`: the job in steps, as given).
Status curve_cross_stage(const JobSpec& steps, const CurveJobScene& sc, uint32_t hit_capacity,
                         uint8_t* base, size_t buffer_bytes, uint32_t* n_hits, JobCounters* c,
                         size_t* need_bytes) {
  CurveCrossParams cp;
  CurveDrawParams dp;
  curve_job_params(steps, &cp, &dp);
  CurveCrossPlan plan;
  const Status s = plan_curve_cross(sc.curves, sc.n_curves, sc.segments, sc.n_segments, cp, &plan);
  if (!ok(s)) return s;
  const size_t hits_size = carve_round(size_t{hit_capacity} * sizeof(CurveHit));
  const size_t scratch = carve_round(plan.scratch_bytes);
  if (buffer_bytes < hits_size + scratch) return short_of(hits_size + scratch, need_bytes);
  ++c->cut_runs;
  return run_curve_cross(plan, sc.curves, sc.segments, base + hits_size, scratch,
                         reinterpret_cast<CurveHit*>(base), hit_capacity, n_hits, &c->curve_cross);
}

// DRAW of the hits at the buffer's front: counting the chords first, so the buffer is checked
// for them and for the path before one is stored; then the chords down to just after the
// hits, which stay for a re-plot (job_redraw_curves), and the path.
Status curve_draw_stage(const JobSpec& steps, const CurveJobScene& sc, uint32_t n_hits,
                        uint8_t* base, size_t buffer_bytes, PreparedJob* job, JobCounters* c,
                        size_t* need_bytes, bool count_only = false) {
  CurveCrossParams cp;
  CurveDrawParams dp;
  curve_job_params(steps, &cp, &dp);
  const CurveHit* hits = reinterpret_cast<const CurveHit*>(base);
  CurveDrawPlan plan;
  Status s =
      plan_curve_draw(sc.curves, sc.n_curves, sc.segments, sc.n_segments, hits, n_hits, dp, &plan);
  if (!ok(s)) return s;
  const size_t hits_size = carve_round(size_t{n_hits} * sizeof(CurveHit));
  const size_t draw_size = carve_round(plan.scratch_bytes);
  if (buffer_bytes < hits_size + draw_size) return short_of(hits_size + draw_size, need_bytes);
  uint8_t* scratch = base + hits_size;
  uint32_t n_chords = 0;
  s = run_curve_draw(plan, sc.curves, sc.segments, hits, n_hits, scratch, draw_size,
                     SpanSink{&ChordCounter::emit, &n_chords}, nullptr, nullptr);
  if (!ok(s)) return s;
  JobBytes path;
  size_path_stages(n_chords, &path);
  size_t need = hits_size + draw_size + path.spans;
  if (hits_size + path.spans + path.points + path.path > need)
    need = hits_size + path.spans + path.points + path.path;
  if (count_only) {  // job_curves_bytes(): the buffer the whole job needs, nothing stored
    *need_bytes = need;
    return Status::kOk;
  }
  if (buffer_bytes < need) return short_of(need, need_bytes);
  SpanCollector collect{reinterpret_cast<Segment2*>(scratch + draw_size), n_chords, 0};
  ++c->draw_runs;
  s = run_curve_draw(plan, sc.curves, sc.segments, hits, n_hits, scratch, draw_size,
                     SpanSink{&SpanCollector::emit, &collect}, nullptr, &c->curve_draw);
  if (!ok(s)) return s;
  // The chords move down over DRAW's scratch (dead now), after the hits: a forward copy
  // through a local, so overlapping records are read before they are overwritten.
  Segment2* front = reinterpret_cast<Segment2*>(scratch);
  for (uint32_t i = 0; i < collect.count; ++i) {
    const Segment2 chord = collect.out[i];
    front[i] = chord;
  }
  collect.out = front;
  return plan_stage(in_units(steps), base, hits_size, path.spans, buffer_bytes, collect,
                    LayerCounts{}, job, c);
}

}  // namespace

namespace {

// What both curve entries ask of a job: haloed on paper, one layer, units and a machine that
// hold, an aligned buffer.
Status curve_job_fits(const JobSpec& steps, const void* buffer) {
  if (steps.drawing != DrawingEffect::kHaloed || steps.draw.mode != HaloMode::kPaper ||
      !units_ok(steps) || steps.layers.n > 1)
    return Status::kBadParameter;
  if (buffer_misaligned(buffer)) return Status::kMisalignedBuffer;
  return validate(steps.machine);
}

}  // namespace

Status curve_band_spec(const JobSpec& steps, CurveBandSpec* out) {
  *out = CurveBandSpec{};
  const Status s = curve_job_fits(steps, nullptr);
  if (!ok(s)) return s;
  curve_job_params(steps, &out->cross, &out->draw);
  out->substep_bits = steps.substep_bits;
  out->start_x = steps.start_x;
  out->start_y = steps.start_y;
  out->clean = steps.clean;
  out->clean.min_stroke = 0;
  return Status::kOk;
}

Status job_prepare_curves(const JobSpec& steps, const CurveJobScene& scene, uint32_t hit_capacity,
                          void* buffer, size_t buffer_bytes, PreparedJob* out,
                          JobCounters* counters, size_t* need_bytes) {
  clear_drawing(out, false);
  JobCounters c;
  Status s = curve_job_fits(steps, buffer);
  if (!ok(s)) return s;
  uint8_t* base = static_cast<uint8_t*>(buffer);
  uint32_t n_hits = 0;
  PreparedJob job;
  s = curve_cross_stage(steps, scene, hit_capacity, base, buffer_bytes, &n_hits, &c, need_bytes);
  if (ok(s)) s = curve_draw_stage(steps, scene, n_hits, base, buffer_bytes, &job, &c, need_bytes);
  if (counters) *counters = c;
  if (!ok(s)) return s;
  *out = job;
  return Status::kOk;
}

Status job_curves_bytes(const JobSpec& steps, const CurveJobScene& scene, void* buffer,
                        size_t buffer_bytes, uint32_t* hit_capacity, size_t* bytes) {
  *hit_capacity = 0;
  *bytes = 0;
  Status s = curve_job_fits(steps, buffer);
  if (!ok(s)) return s;
  uint8_t* base = static_cast<uint8_t*>(buffer);
  uint32_t n_hits = 0, capacity = 0;
  size_t need = 0;
  JobCounters c;
  // From no capacity: the raw records' count, then the hits' (clustering halves them, both
  // directions double them), then a pass that fits.
  for (int pass = 0; pass < 3; ++pass) {
    c = JobCounters{};
    s = curve_cross_stage(steps, scene, capacity, base, buffer_bytes, &n_hits, &c, &need);
    if (s != Status::kCrossingCapacity) break;
    if (c.curve_cross.needed > 0xffffffffu) return Status::kCrossingCapacity;
    capacity = uint32_t(c.curve_cross.needed);
  }
  if (ok(s))
    s = curve_draw_stage(steps, scene, n_hits, base, buffer_bytes, nullptr, &c, &need, true);
  *bytes = need;  // on kWorkspaceTooSmall: what the pass needs, as far as it got
  if (ok(s)) *hit_capacity = capacity;
  return s;
}

Status job_redraw_curves(const JobSpec& steps, const CurveJobScene& scene, uint32_t n_hits,
                         void* buffer, size_t buffer_bytes, PreparedJob* out,
                         JobCounters* counters) {
  Status s = curve_job_fits(steps, buffer);
  if (!ok(s)) return s;
  JobCounters c;
  if (counters) c.curve_cross = counters->curve_cross;  // the crossings found by the plot before
  PreparedJob job;
  s = curve_draw_stage(steps, scene, n_hits, static_cast<uint8_t*>(buffer), buffer_bytes, &job, &c,
                       nullptr);
  if (counters) *counters = c;
  if (!ok(s)) return s;
  *out = job;
  return Status::kOk;
}

size_t CurveJobStage::bytes(const StageNeeds& needs) const {
  CurveCrossParams cp;
  CurveDrawParams dp;
  curve_job_params(*spec, &cp, &dp);
  CurveCrossPlan plan;
  if (!ok(plan_curve_cross(scene.curves, scene.n_curves, scene.segments, scene.n_segments, cp,
                           &plan)))
    return 0;
  return carve_round(size_t{needs.crossings} * sizeof(CurveHit)) + carve_round(plan.scratch_bytes);
}

Status CurveJobStage::run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want) {
  size_t need = 0;
  const Status s =
      job_prepare_curves(*spec, scene, needs.crossings, buffer, bytes, out, counters, &need);
  cut_runs += counters->cut_runs;
  draw_runs += counters->draw_runs;
  if (s == Status::kCrossingCapacity) want->crossings = need_count(counters->curve_cross.needed);
  if (s == Status::kWorkspaceTooSmall) want->bytes = need;
  return s;
}

size_t EdgeJobStage::bytes(const StageNeeds& needs) {
  JobBytes b;
  if (!ok(job_bytes(*spec, edges, needs.crossings, &b))) return 0;
  if (sized != nullptr) *sized = b;
  return b.total();
}

Status EdgeJobStage::run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want) {
  const Status s = job_prepare(*spec, edges, needs.crossings, buffer, bytes, out, counters);
  cut_runs += counters->cut_runs;
  draw_runs += counters->draw_runs;
  if (s == Status::kCrossingCapacity)
    want->crossings = need_count(counters->cut.crossings + counters->cut.near_misses);
  return s;
}

Status SolidJobStage::run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want) {
  const Status s = job_prepare_solid(*spec, *in, needs.crossings, needs.incidences, buffer, bytes,
                                     out, counters, report);
  cut_runs += counters->cut_runs;
  hidden_lines_needs(s, *report, bytes, want);
  return s;
}

Status init_planner(MotionPlanner* planner, const JobSpec& spec, const PreparedJob& job,
                    void* workspace, size_t workspace_bytes) {
  const Status s = planner->init(spec.machine, spec.effects, job.points, job.n_points, workspace,
                                 workspace_bytes);
  if (!ok(s)) return s;
  if (job.feed.more != nullptr) planner->set_feed(job.feed);
  planner->set_finish_home(spec.finish_home);
  return Status::kOk;
}

}  // namespace haloplot
