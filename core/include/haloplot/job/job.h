// A plot job: which drawing effect, which halo, which machine and which plotter effects.
// job_prepare() runs only the stages the drawing effect needs (CUT and DRAW only for haloed
// lines), then path planning, all in one caller buffer carved per stage. A stage that does
// not run gets zero bytes and a zero counter: an unrequested effect costs nothing.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/band/conductor.h"
#include "haloplot/band/curve_bands.h"
#include "haloplot/curve/curve_draw.h"
#include "haloplot/cut/cut.h"
#include "haloplot/draw/draw.h"
#include "haloplot/motion/machine.h"
#include "haloplot/motion/path_plan.h"
#include "haloplot/motion/planner.h"
#include "haloplot/solid/hidden_lines.h"
#include "haloplot/status/status.h"

namespace haloplot {

enum class DrawingEffect : uint8_t {
  kAllEdges,       // every edge whole: no CUT, no DRAW
  kHaloed,         // HALO: CUT, then DRAW with the halo width
  kHiddenRemoved,  // needs faces: a solid job (job_prepare_solid), or its chosen strokes
  kHiddenDashed,   // needs faces: likewise, the hidden lines dashed (HiddenJob's dash)
  // Kept for the protocol's numbering: outlines and hatching are options of the two above
  // (HiddenJob::outline, hatch_spacing); an edge job given either needs faces and is refused.
  kOutline,
  kHatch,
};

// The hidden-line drawings' settings (kHiddenRemoved, kHiddenDashed).
struct HiddenJob {
  HiddenMethod method = HiddenMethod::kAuto;
  bool outline = false;          // redraw Kira's outlines last
  int32_t dash = 160, gap = 80;  // hidden-dashed: steps drawn and skipped
  // Hatch the visible faces (Franklin 1980's regions, surface/hidden_surface.h) after the
  // edges and before the outlines.
  bool hatch = false;
  int32_t hatch_spacing = 120, hatch_angle_mdeg = 45000, hatch_mdeg_per_depth = 90000;
  // Draw the visible parts of the lines where faces cross (solid/intersection_lines.h): on by
  // default, since solids that pass through each other are common in assemblies.
  bool intersections = true;
};

struct JobSpec {
  DrawingEffect drawing = DrawingEffect::kHaloed;
  HiddenJob hidden;
  DrawParams draw;  // halo width and mode
  CutParams cut;    // grid choices (and reach for the exact halo)
  Machine machine;
  PlotterEffects effects;
  int32_t start_x = 0, start_y = 0;  // where the pen is before the job
  bool finish_home = true;           // end pen up at the origin (job key `finish home|stay`)
  // The scene's units are 2^-substep_bits steps (the View that projected it). The lengths
  // above stay in steps (the halo, dashes, hatch spacing, CUT's reach, the pen's start); the
  // job turns them into units and rounds what it emits to steps (geometry/units.h).
  int32_t substep_bits = 0;
  // A drawing-all job of strokes decided elsewhere (the host's hidden-line drawings): the
  // edges come grouped by line kind, this many of each, and each kind is planned in turn
  // (motion/path_plan.h plan_path_layers). n = 0: one layer. A hidden-line job groups its
  // strokes itself; a haloed one has one layer.
  LayerCounts layers;
  // The path planner's clean-up (motion/path_plan.h): no dots, overlaps drawn once, and strokes
  // shorter than clean.min_stroke (plot steps, like start_x: not scaled to units) dropped.
  PathClean clean;
};

// Bytes each stage takes from the job buffer (0: the stage does not run), and the peak the
// buffer must hold. Stages share the buffer where one is dead when the next begins:
//   [CUTSET | CUT scratch                      ]   while CUT runs
//   [CUTSET | spans | DRAW scratch             ]   while DRAW runs (CUT's scratch is dead)
//   [CUTSET | spans | points | path workspace  ]   while the path is planned
// job_bytes() bounds every stage with K = crossing_capacity; job_prepare() checks each stage
// against the real K, so a smaller buffer works whenever the scene's crossings allow. Every
// buffer and workspace below starts on a kBufferAlignment (8) boundary, or the call returns
// kMisalignedBuffer before it touches it (status/status.h).
struct JobBytes {
  size_t cut_scratch = 0, cutset = 0, draw_scratch = 0, spans = 0, path = 0, points = 0;
  size_t peak = 0;
  size_t total() const { return peak; }
};

struct JobCounters {
  uint32_t cut_runs = 0, draw_runs = 0, path_runs = 0;  // a curve job's crossings count as CUT
  CutStats cut;
  DrawStats draw;
  PathStats path;
  CurveCrossStats curve_cross;  // a scene with curves (job_prepare_curves)
  CurveDrawStats curve_draw;
};

struct PreparedJob {
  const PathPoint* points = nullptr;
  uint32_t n_points = 0;
  uint32_t n_spans = 0;
  const Segment2* spans = nullptr;
  LayerCounts layer_points;  // how many of the points each layer took (n = 0: one layer)
  CutSet cutset;             // valid when CUT ran: DRAW can rerun from it with another halo width
  PointFeed feed;            // set: the points come band by band from this feed (a streamed plot)
  // > 0: go on with a plot that stopped after this many step events (an abort, a reset):
  // motion/virtual_run.h skip_events() before the motion starts.
  uint32_t resume_after_events = 0;
};

// The band conductor's settings for this job: an edge drawing (kHaloed, or kAllEdges), or the
// strokes of a hidden-line drawing in bands (kHiddenRemoved, kHiddenDashed: begin_solid).
BandSpec band_spec(const JobSpec& spec);

// Bytes the job needs for these edges when CUT may store up to `crossing_capacity` records.
// CUT's plan is computed here (O(N)); kCrossingCapacity from job_prepare() says how many
// records a retry needs.
Status job_bytes(const JobSpec& spec, Edges edges, uint32_t crossing_capacity, JobBytes* bytes);

// The crossing capacity job_prepare() needs for these edges, exactly: a counting pass of CUT
// (it stores no record) in `buffer`, which takes what job_bytes() says for a capacity of 0.
// An edge job without CUT (kAllEdges) needs none: 0, and the buffer is not touched (a
// misaligned one is still kMisalignedBuffer, as for every entry).
Status job_crossings(const JobSpec& spec, Edges edges, void* buffer, size_t buffer_bytes,
                     uint32_t* capacity);

// Every job_prepare* call empties *out first: a call that fails leaves an empty PreparedJob
// (no points, no spans, no CUTSET), never the previous call's. job_redraw keeps the CUTSET it
// reads and empties the rest.
Status job_prepare(const JobSpec& spec, Edges edges, uint32_t crossing_capacity, void* buffer,
                   size_t buffer_bytes, PreparedJob* out, JobCounters* counters);

// A hidden-line drawing of a solid (spec.drawing kHiddenRemoved or kHiddenDashed): the
// hidden-line run (solid/hidden_lines.h) in the buffer, its strokes (solid/modes.h) gathered
// in the run's free tail, then moved to the front for the path. kCrossingCapacity and
// kIncidenceCapacity: *report says the counts a retry needs; kSinkFull: the strokes did not
// fit beside the run (a larger buffer, or a simpler scene).
Status job_prepare_solid(const JobSpec& spec, const SolidInput& in, uint32_t crossing_capacity,
                         uint32_t incidence_capacity, void* buffer, size_t buffer_bytes,
                         PreparedJob* out, JobCounters* counters, HiddenReport* report);

// The capacities and the buffer job_prepare_solid() needs for this solid, exactly: counting
// passes of the hidden-line run in `buffer` (from no capacity up to what the run reports; its
// strokes counted, none stored), which need at most what the job does. *needs: .crossings,
// .incidences and .bytes (to ask job_prepare_solid() with). Fails as the job would; on
// kWorkspaceTooSmall report->bytes_needed says what the run needs, as far as it got.
Status job_solid_bytes(const JobSpec& spec, const SolidInput& in, void* buffer, size_t buffer_bytes,
                       StageNeeds* needs, HiddenReport* report);

// Re-plot with another halo width (spec.draw): DRAW and the path run again from the CUTSET
// that job_prepare() left at the start of the same buffer; CUT does not run (the paper's
// point: a new halo width costs only DRAW). `job` is updated in place. `edges` are the ones
// job_prepare() was given (their count places the CUTSET's end): another count is
// kBadParameter.
Status job_redraw(const JobSpec& spec, Edges edges, uint32_t crossing_capacity, void* buffer,
                  size_t buffer_bytes, PreparedJob* job, JobCounters* counters);

// The planner for a prepared job: its points, then the band feed of a streamed plot, then the
// travel home (spec.finish_home). The simulator, the controller and the self-tests all start
// their motion through this one call, so their traces can only differ by arithmetic.
Status init_planner(MotionPlanner* planner, const JobSpec& spec, const PreparedJob& job,
                    void* workspace, size_t workspace_bytes);

// A scene with cubic Bézier edges (curve/curve_draw.h): the curves, and the straight edges
// among them; edges are numbered curves first, then the segments.
struct CurveJobScene {
  const BezierEdge3* curves = nullptr;
  uint32_t n_curves = 0;
  const Edge3* segments = nullptr;
  uint32_t n_segments = 0;
};

// The first pieces of a curve job's crossing search are flat within this many steps. They only
// pair the curves up (a crossing's precision comes from the refinement, curve/curve_cross.h):
// coarse pieces keep the scratch small enough for a controller's arena (the demo trefoil: 96
// pieces in 22,720 bytes, not 768 in 122,176 at the stage's default of 1/4 unit).
inline constexpr int32_t kCurveJobPieceSteps = 16;

// The curve stages' settings for a job, in the scene's units: pieces flat within
// kCurveJobPieceSteps, the segments crossed with each other too (no CUT runs on a scene with
// curves), the paper's gap of spec.draw.halo, chords within the stage's default 1/4 unit.
// `plot` of a curve scene uses the same, so it draws what the job plots.
void curve_job_params(const JobSpec& spec, CurveCrossParams* cross, CurveDrawParams* draw);

// The same curve job in bands (band/curve_bands.h), for an arena smaller than the whole
// drawing's needs: the stages' settings of curve_job_params(), the pen's start, the job's
// clean-up (without its minimum stroke: a border cuts strokes). kBadParameter for a job
// job_prepare_curves() refuses too.
Status curve_band_spec(const JobSpec& spec, CurveBandSpec* out);

// A haloed drawing of a scene with curves (spec.drawing kHaloed, the paper's gap; anything else
// is kBadParameter): the crossings (run_curve_cross), the curve DRAW's chords (run_curve_draw),
// then the path of the chords as of any drawing's spans, all in one caller buffer:
//   [hits | crossing scratch          ]   while the crossings are found
//   [hits | DRAW scratch | chords     ]   while DRAW runs (once counting, once storing)
//   [chords | points | path workspace ]   while the path is planned
// hit_capacity bounds the hits: kCrossingCapacity leaves counters->curve_cross.needed, the
// capacity a retry needs. kWorkspaceTooSmall leaves *need_bytes (when not null) the buffer a
// retry needs, as far as the run got. Nothing is partial: a full buffer is an error.
Status job_prepare_curves(const JobSpec& spec, const CurveJobScene& scene, uint32_t hit_capacity,
                          void* buffer, size_t buffer_bytes, PreparedJob* out,
                          JobCounters* counters, size_t* need_bytes = nullptr);

// The hit capacity and the buffer job_prepare_curves() needs for this scene, exactly: counting
// passes in `buffer` (the crossings from no capacity up to what their hits take, then DRAW
// counting its chords; no chord is stored), which need at most what the job does.
// kWorkspaceTooSmall leaves *bytes the buffer the passes need, as far as they got.
Status job_curves_bytes(const JobSpec& spec, const CurveJobScene& scene, void* buffer,
                        size_t buffer_bytes, uint32_t* hit_capacity, size_t* bytes);

// A re-plot of a curve job with another halo (steps.draw): job_prepare_curves() left its n_hits
// hits at the buffer's front, so only DRAW and the path run again (crossings do not depend on
// the halo). counters (may be null): its curve_cross is kept, the rest are this run's.
Status job_redraw_curves(const JobSpec& steps, const CurveJobScene& scene, uint32_t n_hits,
                         void* buffer, size_t buffer_bytes, PreparedJob* out,
                         JobCounters* counters);

// job_prepare_curves() as a sized stage: needs.crossings is the hit capacity; bytes() is what
// the crossing search takes (DRAW's and the path's needs come from a run).
struct CurveJobStage {
  const JobSpec* spec;
  CurveJobScene scene;
  PreparedJob* out;
  JobCounters* counters;
  uint32_t cut_runs = 0, draw_runs = 0;
  size_t bytes(const StageNeeds& needs) const;
  Status run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want);
};

// job_prepare() as a sized stage (memory/sized_stage.h): needs.crossings is CUT's record
// capacity. cut_runs and draw_runs add up over every run.
struct EdgeJobStage {
  const JobSpec* spec;
  Edges edges;
  PreparedJob* out;
  JobCounters* counters;
  JobBytes* sized;  // may be null: the last query's bytes per stage
  uint32_t cut_runs = 0, draw_runs = 0;
  size_t bytes(const StageNeeds& needs);
  Status run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want);
};

// job_prepare_solid() as a sized stage: needs.crossings and .incidences are the capacities;
// bytes() is the first guess of a growing buffer (job_solid_bytes() is the bound).
struct SolidJobStage {
  const JobSpec* spec;
  const SolidInput* in;
  PreparedJob* out;
  JobCounters* counters;
  HiddenReport* report;
  uint32_t cut_runs = 0;
  size_t bytes(const StageNeeds&) const { return hidden_lines_first_bytes(*in); }
  Status run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want);
};

}  // namespace haloplot
