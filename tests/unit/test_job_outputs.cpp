// A failed job call leaves its outputs empty (job/job.h): a job_prepare, job_prepare_solid or
// job_prepare_curves call that fails (a bad parameter, a misaligned buffer, too few crossings,
// too small a buffer) leaves an empty PreparedJob, never the previous call's drawing, whose
// points may lie in memory the failed run overwrote; job_redraw keeps the CUTSET it reads and
// empties the rest, and a redraw after its failure still plots. Every case starts from a
// PreparedJob that holds a successful call's drawing, so a call that left it in place fails
// here (before the rule, each case did: run against the previous core, 7 checks failed).
#include <vector>

#include "check.h"
#include "haloplot/curve/bezier.h"
#include "selftest/misaligned_checks.h"

using namespace haloplot;
using namespace haloplot::misaligned;

namespace {

bool empty(const PreparedJob& j) {
  return j.points == nullptr && j.n_points == 0 && j.spans == nullptr && j.n_spans == 0 &&
         j.layer_points.n == 0 && j.cutset.edges == nullptr && j.feed.more == nullptr &&
         j.resume_after_events == 0;
}

std::vector<uint64_t> memory(1 << 15);  // 256 KB, 8-aligned
uint8_t* buffer() { return reinterpret_cast<uint8_t*>(memory.data()); }
const size_t kBytes = memory.size() * sizeof(uint64_t);

JobSpec haloed() {
  JobSpec spec;
  spec.draw = DrawParams{20, HaloMode::kPaper};
  return spec;
}

Status prepare(PreparedJob* job, uint32_t capacity, uint8_t* at, size_t bytes,
               const JobSpec& spec) {
  return job_prepare(spec, Edges{edges, kEdges}, capacity, at, bytes, job, nullptr);
}

void edge_jobs() {
  struct Case {
    const char* what;
    Status expected;
    uint32_t capacity;
    size_t offset, bytes;
    DrawingEffect drawing;
  };
  const Case cases[] = {
      {"too few crossings", Status::kCrossingCapacity, 1, 0, kBytes, DrawingEffect::kHaloed},
      {"too small a buffer", Status::kWorkspaceTooSmall, kCrossingCapacity, 0, 64,
       DrawingEffect::kHaloed},
      {"a misaligned buffer", Status::kMisalignedBuffer, kCrossingCapacity, 3, kBytes - 8,
       DrawingEffect::kHaloed},
      {"a drawing that needs faces", Status::kBadParameter, kCrossingCapacity, 0, kBytes,
       DrawingEffect::kHiddenRemoved},
  };
  for (const Case& c : cases) {
    PreparedJob job;
    CHECK(ok(prepare(&job, kCrossingCapacity, buffer(), kBytes, haloed())));
    CHECK_MSG(job.n_points > 0 && job.cutset.edges != nullptr, "job_prepare drew nothing");
    JobSpec spec = haloed();
    spec.drawing = c.drawing;
    const Status s = prepare(&job, c.capacity, buffer() + c.offset, c.bytes, spec);
    CHECK_MSG(s == c.expected, std::string("job_prepare, ") + c.what + ": " + status_name(s));
    CHECK_MSG(empty(job), std::string("job_prepare, ") + c.what + ": the previous drawing is left");
  }
}

void redraw() {
  PreparedJob job;
  CHECK(ok(prepare(&job, kCrossingCapacity, buffer(), kBytes, haloed())));
  const CutSet cutset = job.cutset;
  JobSpec wider = haloed();
  wider.draw.halo = 40;
  const size_t just_the_cutset = 256;  // DRAW's scratch and the path cannot fit
  Status s = job_redraw(wider, Edges{edges, kEdges}, kCrossingCapacity, buffer(), just_the_cutset,
                        &job, nullptr);
  CHECK_MSG(s == Status::kWorkspaceTooSmall, std::string("job_redraw: ") + status_name(s));
  CHECK_MSG(job.points == nullptr && job.n_points == 0 && job.spans == nullptr && job.n_spans == 0,
            "job_redraw failed: the previous drawing is left");
  CHECK_MSG(job.cutset.edges == cutset.edges && job.cutset.n_crossings == cutset.n_crossings,
            "job_redraw failed: the CUTSET it reads is gone");
  s = job_redraw(wider, Edges{edges, kEdges}, kCrossingCapacity, buffer(), kBytes, &job, nullptr);
  CHECK_MSG(ok(s) && job.n_points > 0, "job_redraw after a failed one");
}

void solid_job() {
  JobSpec spec = haloed();
  spec.drawing = DrawingEffect::kHiddenRemoved;
  PreparedJob job;
  HiddenReport report;
  CHECK(ok(job_prepare_solid(spec, solid.in, 64, 32, buffer(), kBytes, &job, nullptr, &report)));
  CHECK_MSG(job.n_points > 0, "job_prepare_solid drew nothing");
  const Status s =
      job_prepare_solid(spec, solid.in, 1, 32, buffer(), kBytes, &job, nullptr, &report);
  CHECK_MSG(s == Status::kCrossingCapacity, std::string("job_prepare_solid: ") + status_name(s));
  CHECK_MSG(empty(job), "job_prepare_solid failed: the previous drawing is left");
}

void curve_job() {
  const BezierEdge3 curves[2] = {{{Point3{1000, 1000, 10}, Point3{4000, 2000, 10},
                                   Point3{1000, 3000, 10}, Point3{5000, 4000, 10}}},
                                 {{Point3{1000, 4000, 90}, Point3{4000, 3000, 90},
                                   Point3{1000, 2000, 90}, Point3{5000, 1000, 90}}}};
  const CurveJobScene scene{curves, 2, nullptr, 0};
  JobSpec spec = haloed();
  spec.draw.halo = 60;
  PreparedJob job;
  CHECK(ok(job_prepare_curves(spec, scene, 64, buffer(), kBytes, &job, nullptr)));
  CHECK_MSG(job.n_points > 0, "job_prepare_curves drew nothing");
  const Status s = job_prepare_curves(spec, scene, 64, buffer(), 128, &job, nullptr);
  CHECK_MSG(s == Status::kWorkspaceTooSmall, std::string("job_prepare_curves: ") + status_name(s));
  CHECK_MSG(empty(job), "job_prepare_curves failed: the previous drawing is left");
}

}  // namespace

int main() {
  CHECK(ok(build_scenes()));
  edge_jobs();
  redraw();
  solid_job();
  curve_job();
  return check::finish("job_outputs");
}
