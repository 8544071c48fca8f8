#include "pipeline/surface_pipeline.h"

#include <algorithm>
#include <chrono>

namespace haloplot::host {
namespace {

Status collect(void* context, const FranklinPiece& p) {
  static_cast<std::vector<FranklinPiece>*>(context)->push_back(p);
  return Status::kOk;
}

}  // namespace

Status run_franklin(const SolidScene& scene, const FranklinParams& params, FranklinRun* out) {
  const SolidInput in = solid_input(scene);
  uint32_t crossings = 4 * in.n_edges + 1024, incidences = in.n_vertices + 64;
  Status s = Status::kOk;
  for (int attempt = 0; attempt < 4; ++attempt) {
    out->bytes = franklin_bytes(in, params, crossings, incidences);
    std::vector<uint64_t> buffer(out->bytes / 8 + 1);
    out->pieces.clear();
    const auto t0 = std::chrono::steady_clock::now();
    s = franklin_hidden_lines(in, params, crossings, incidences, buffer.data(), buffer.size() * 8,
                              FranklinSink{&collect, &out->pieces}, &out->stats);
    out->ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (s == Status::kCrossingCapacity)
      crossings = uint32_t(out->stats.crossings);
    else if (s == Status::kIncidenceCapacity)
      incidences = out->stats.incidences;
    else
      break;
  }
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
        RegionSegment{p.edge, p.t0, p.t1, p.from, p.to});
  return Status::kOk;
}

}  // namespace

Status run_regions(const SolidScene& scene, const FranklinParams& params, RegionsRun* out) {
  const SolidInput in = solid_input(scene);
  FranklinParams every = params;
  every.every_piece = true;
  uint32_t crossings = 4 * in.n_edges + 1024, incidences = in.n_vertices + 64;
  Status s = Status::kOk;
  FranklinStats fs;
  for (int attempt = 0; attempt < 4; ++attempt) {
    std::vector<uint64_t> buffer(franklin_bytes(in, every, crossings, incidences) / 8 + 1);
    out->segments.clear();
    s = franklin_hidden_lines(in, every, crossings, incidences, buffer.data(), buffer.size() * 8,
                              FranklinSink{&collect_visible, &out->segments}, &fs);
    if (s == Status::kCrossingCapacity)
      crossings = uint32_t(fs.crossings);
    else if (s == Status::kIncidenceCapacity)
      incidences = fs.incidences;
    else
      break;
  }
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
  HiddenSurfaceCapacity cap{4 * in.n_edges + 1024, in.n_vertices + 64, 4 * in.n_edges + 1024};
  size_t bytes = hidden_surface_bytes(in, fp, cap.crossings, cap.incidences, cap.segments);
  Status s = Status::kOk;
  for (int attempt = 0; attempt < 8; ++attempt) {
    std::vector<uint64_t> buffer(bytes / 8 + 1);
    out->strokes.clear();
    const auto t0 = std::chrono::steady_clock::now();
    s = hidden_surface(in, fp, params, cap.crossings, cap.incidences, cap.segments, buffer.data(),
                       buffer.size() * 8, FranklinSink{nullptr, nullptr},
                       HatchSink{&collect_stroke, &out->strokes}, &out->surface);
    out->ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const HiddenSurfaceStats& st = out->surface;
    if (s == Status::kWorkspaceTooSmall)
      bytes = std::max(st.bytes_needed, bytes * 2);
    else if (cap.grow(s, st))
      bytes = std::max(bytes,
                       hidden_surface_bytes(in, fp, cap.crossings, cap.incidences, cap.segments));
    else
      break;
  }
  return s;
}

}  // namespace

Status run_hatch(const SolidScene& scene, const HatchParams& params, HatchRun* out,
                 HatchMethod method, FranklinParams franklin) {
  const SolidInput in = solid_input(scene);
  if (method == HatchMethod::kRegions) return run_regions_hatch(in, params, franklin, out);
  uint32_t crossings = 8 * in.n_triangles + 1024;
  size_t bytes = hatch_bytes(in, params, crossings);
  Status s = Status::kOk;
  for (int attempt = 0; attempt < 6; ++attempt) {
    std::vector<uint64_t> buffer(bytes / 8 + 1);
    out->strokes.clear();
    s = hatch_faces(in, params, crossings, buffer.data(), buffer.size() * 8,
                    HatchSink{&collect_stroke, &out->strokes}, &out->stats);
    if (s == Status::kCrossingCapacity) {
      crossings = uint32_t(out->stats.crossings);
      bytes = hatch_bytes(in, params, crossings);
    } else if (s == Status::kWorkspaceTooSmall) {
      bytes = out->stats.bytes_needed + bytes / 2;
    } else {
      break;
    }
  }
  return s;
}

}  // namespace haloplot::host
