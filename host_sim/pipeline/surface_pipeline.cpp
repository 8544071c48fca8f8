#include "pipeline/surface_pipeline.h"

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

}  // namespace

Status run_hatch(const SolidScene& scene, const HatchParams& params, HatchRun* out) {
  const SolidInput in = solid_input(scene);
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
