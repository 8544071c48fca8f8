#include "pipeline/surface_pipeline.h"

#include <algorithm>
#include <chrono>

#include "pipeline/host_memory.h"

namespace haloplot::host {
namespace {

Status collect(void* context, const FranklinPiece& p) {
  static_cast<std::vector<FranklinPiece>*>(context)->push_back(p);
  return Status::kOk;
}

// The first guesses every host run starts from; the core's report sizes the next run.
StageNeeds first_guess(const SolidInput& in) {
  StageNeeds needs;
  needs.crossings = 4 * in.n_edges + 1024;
  needs.incidences = in.n_vertices + 64;
  needs.segments = 4 * in.n_edges + 1024;
  return needs;
}

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

Status run_franklin(const SolidScene& scene, const FranklinParams& params, FranklinRun* out) {
  const SolidInput in = solid_input(scene);
  StageNeeds needs = first_guess(in);
  FranklinStage stage{&in, params, FranklinSink{&collect, &out->pieces}, &out->stats};
  auto t0 = std::chrono::steady_clock::now();  // the last run's start: ms times it alone
  auto restart = restarting(&stage, [out, &t0] {
    out->pieces.clear();
    t0 = std::chrono::steady_clock::now();
  });
  HostMemory memory;
  const Status s = run_sized(restart, memory.memory(), &needs);
  out->ms = ms_since(t0);
  out->bytes = stage.bytes(needs);
  return s;
}

namespace {

Status collect_stroke(void* context, const HatchStroke& s) {
  static_cast<std::vector<HatchStroke>*>(context)->push_back(s);
  return Status::kOk;
}

Status collect_visible(void* context, const FranklinPiece& p) {
  if (!p.hidden)
    static_cast<std::vector<RegionSegment>*>(context)->push_back(
        RegionSegment{{p.edge, p.t0, p.t1}, p.from, p.to});
  return Status::kOk;
}

}  // namespace

Status run_regions(const SolidScene& scene, const FranklinParams& params, RegionsRun* out) {
  const SolidInput in = solid_input(scene);
  FranklinParams every = params;
  every.every_piece = true;
  StageNeeds needs = first_guess(in);
  FranklinStats fs;
  FranklinStage franklin{&in, every, FranklinSink{&collect_visible, &out->segments}, &fs};
  auto restart = restarting(&franklin, [out] { out->segments.clear(); });
  HostMemory memory;
  Status s = run_sized(restart, memory.memory(), &needs);
  if (s != Status::kOk) return s;
  const uint32_t n = uint32_t(out->segments.size());
  std::vector<uint64_t> buffer(regions_bytes(in, n) / 8 + 1);
  Regions r;
  s = build_regions(in, out->segments.data(), n, buffer.data(), buffer.size() * 8, &r, &out->stats);
  if (s != Status::kOk) return s;
  out->n_nodes = r.n_nodes;
  out->node.assign(r.node, r.node + 2 * n);
  out->kept.assign(r.kept, r.kept + n);
  out->cycle.assign(r.cycle, r.cycle + 2 * n);
  out->cycle_face.assign(r.cycle_face, r.cycle_face + r.n_cycles);
  out->cycle_bounded.assign(r.cycle_bounded, r.cycle_bounded + r.n_cycles);
  return Status::kOk;
}

namespace {

Status run_regions_hatch(const SolidInput& in, const HatchParams& params, const FranklinParams& fp,
                         HatchRun* out) {
  StageNeeds needs = first_guess(in);
  HiddenSurfaceStage stage{&in,
                           fp,
                           params,
                           FranklinSink{nullptr, nullptr},
                           HatchSink{&collect_stroke, &out->strokes},
                           &out->surface};
  auto t0 = std::chrono::steady_clock::now();  // the last run's start: ms times it alone
  auto restart = restarting(&stage, [out, &t0] {
    out->strokes.clear();
    t0 = std::chrono::steady_clock::now();
  });
  HostMemory memory;
  const Status s = run_sized(restart, memory.memory(), &needs);
  out->ms = ms_since(t0);
  return s;
}

}  // namespace

Status run_hatch(const SolidScene& scene, const HatchParams& params, HatchRun* out,
                 HatchMethod method, FranklinParams franklin) {
  const SolidInput in = solid_input(scene);
  if (method == HatchMethod::kRegions) return run_regions_hatch(in, params, franklin, out);
  SolidRun run;
  FallbackParams kira;
  kira.use_classes = kira.use_vc = true;
  const auto t0 = std::chrono::steady_clock::now();
  const Status s = run_hidden_lines(scene, HiddenMethod::kAuto, kira, &run, false, false, &params);
  out->ms = ms_since(t0);
  out->lines = run.hatch_stats;
  for (size_t k = 0; k < run.hatch.size(); ++k) {
    const SolidPiece& p = run.hatch[k];
    if (p.hidden) continue;
    HatchStroke h{run.hatch_faces[k], run.hatch_polygons[k], Edge3{}};
    const Span sp = make_stroke(run.edges[p.edge], p.edge, p.t0, p.t1);
    h.line = Edge3{{sp.x0, sp.y0, 0}, {sp.x1, sp.y1, 0}};
    out->strokes.push_back(h);
  }
  return s;
}

}  // namespace haloplot::host
