// Streamed bands: a controller that never holds the scene. The host runs the band conductor
// over the whole scene with the controller's arena and sends each band's edges; the controller
// (here the same core on the host, fed by a stream that is often not ready yet) must draw the
// same plot: its step trace equals `haloplot sim` of the same job with the same arena, byte for
// byte, however often the plot waits for a band. A band with an edge missing must show. The
// same for a solid's hidden lines in bands (10 x 10 cubes, hidden-dashed, outlined, and
// hatched; a hatched torus): its bands carry vertices, edges and triangles, and a band missing
// faces must show, as must the torus's bands without the triangles that complete a polygon. A
// smooth torus (no drawn edge: every side left out, as a crease angle above its facets' leaves
// them) draws its contour diagonals only, which each band finds among the triangles it is sent.
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "check.h"
#include "demo/cube_array.h"
#include "haloplot/band/band_rule.h"
#include "pipeline/band_stream.h"
#include "sim/simulator.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {
constexpr size_t kArena = 64 * 1024;
// A solid's bands streamed: the trace equals the banded `sim` of the same job. Hatched too: then
// each band carries every triangle of each polygon it holds (the lines' direction reads the
// whole polygon), and bands planned without that rule must change the plot.
void check_solid(bool hatch, bool torus = false, bool smooth = false) {
  solid_scenes::Mesh m;
  if (torus)  // quads whose diagonals do not span them in y: a band can meet half of one
    solid_scenes::torus(&m, 0, 0, 0, 6000, 2000, 48, 24, true);
  else
    for (int i = 0; i < 10; ++i)
      for (int j = 0; j < 10; ++j)
        solid_scenes::box(&m, i * 3000, j * 3000, 0, i * 3000 + 2000, j * 3000 + 2000, 2000);
  SolidScene scene;
  CHECK(solid_scenes::project(m, solid_scenes::view(30000, 25000), &scene));
  if (smooth) scene.edge_pairs.clear();
  const SolidInput in = solid_input(scene);
  const bool closed = model_closed(scene);
  CHECK(closed);
  JobSpec job;
  job.drawing = DrawingEffect::kHiddenDashed;
  job.hidden.dash = 160;
  job.hidden.gap = 80;
  job.hidden.outline = true;
  job.hidden.hatch = hatch;
  job.hidden.hatch_spacing = 240;
  job.machine.kinematics = Kinematics::kCoreXY;
  std::ostringstream reference;
  SimReport report;
  CHECK(simulate_solid(job, in, closed, &reference, &report, kArena) == Status::kOk);
  CHECK_MSG(!report.spans.empty(), "the banded plot draws strokes");
  BandPlan plan;
  CHECK(plan_streamed_solid(in, closed, band_spec(job), kArena, &plan) == Status::kOk);
  CHECK_EQ(plan.bands.size(), size_t(report.bands.bands));
  CHECK(plan.bands.size() > 1);
  size_t v = 0, e = 0, t = 0;
  for (const PlannedBand& b : plan.bands) {
    v += b.vertices.size();
    e += b.ids.size();
    t += b.triangles.size();
  }
  std::printf(
      "%s%s streamed: %zu bands; %zu vertices, %zu edges, %zu triangles "
      "sent for %u, %u, %u; %zu strokes\n",
      smooth ? "a smooth torus" : (torus ? "a torus" : "10 x 10 solid cubes"),
      hatch ? " hatched" : "", plan.bands.size(), v, e, t, in.n_vertices, in.n_edges,
      in.n_triangles, report.spans.size());
  for (int busy : {0, 2}) {
    PlanStream stream;
    stream.plan = &plan;
    stream.busy_every = stream.busy_left = busy;
    std::ostringstream out;
    SimReport streamed;
    const Status s = simulate_streamed(job, stream.stream(), 0, kArena, &out, &streamed, &plan);
    CHECK_MSG(ok(s), std::string("streamed solid: ") + status_name(s));
    CHECK_MSG(out.str() == reference.str(), "streamed solid trace (" +
                                                std::to_string(out.str().size()) +
                                                " bytes) equals haloplot sim's (" +
                                                std::to_string(reference.str().size()) + " bytes)");
  }
  BandPlan broken = plan;
  PlannedBand& b = broken.bands[broken.bands.size() / 2];
  b.triangles.resize(b.triangles.size() / 2);  // half its faces (a back face hides nothing)
  PlanStream stream;
  stream.plan = &broken;
  std::ostringstream out;
  SimReport streamed;
  const Status s = simulate_streamed(job, stream.stream(), 0, kArena, &out, &streamed, &broken);
  CHECK_MSG(!ok(s) || out.str() != reference.str(), "a band missing faces must change the plot");
  // (A cube's quads: both halves span the quad's rows, so no band cuts one; and only a hatched
  // plot's bands hold whole polygons.)
  if (!torus || !hatch) return;
  // The same bands, each without the triangles that only complete a polygon.
  BandPlan cut = plan;
  size_t fewer = 0;
  for (PlannedBand& band : cut.bands) {
    std::vector<Triangle> kept;
    for (const Triangle& tri : band.triangles)
      if (triangle_meets_rows(in.vertices[tri.v[0]], in.vertices[tri.v[1]], in.vertices[tri.v[2]],
                              band.y0, band.y1))
        kept.push_back(tri);
    fewer += band.triangles.size() - kept.size();
    band.triangles = kept;
  }
  PlanStream cut_stream;
  cut_stream.plan = &cut;
  std::ostringstream cut_out;
  SimReport cut_report;
  const Status cs =
      simulate_streamed(job, cut_stream.stream(), 0, kArena, &cut_out, &cut_report, &cut);
  CHECK_MSG(fewer > 0 && (!ok(cs) || cut_out.str() != reference.str()),
            "bands without whole polygons (" + std::to_string(fewer) +
                " triangles fewer) must change the hatched plot");
}

}  // namespace

int main() {
  // The README's demo job: Figure 4, halo 50, the demo machine (scenes/demo.job).
  const std::vector<Edge3> edges = cube_array(CubeArrayParams{});
  JobSpec job;
  job.draw = DrawParams{50, HaloMode::kPaper};
  job.machine.kinematics = Kinematics::kCoreXY;
  std::ostringstream reference;
  SimReport report;
  CHECK(simulate(job, edges, &reference, &report, kArena) == Status::kOk);
  BandSpec spec;
  spec.draw = job.draw;
  spec.cut = job.cut;
  BandPlan plan;
  CHECK(plan_streamed_bands(edges, spec, kArena, &plan) == Status::kOk);
  CHECK_EQ(plan.bands.size(), size_t(report.bands.bands));
  CHECK(plan.bands.size() > 1);
  size_t sent = 0;
  for (const PlannedBand& b : plan.bands) sent += b.edges.size();
  std::printf("figure 4 streamed: %zu bands, %zu edges sent for %zu (%.2fx), margin %d\n",
              plan.bands.size(), sent, edges.size(), double(sent) / double(edges.size()),
              plan.margin);

  for (int busy : {0, 3}) {
    PlanStream stream;
    stream.plan = &plan;
    stream.busy_every = stream.busy_left = busy;
    std::ostringstream out;
    SimReport streamed;
    const Status s = simulate_streamed(job, stream.stream(), plan.margin, kArena, &out, &streamed);
    const std::string trace = out.str();
    CHECK_MSG(ok(s), std::string("streamed run: ") + status_name(s));
    CHECK_EQ(streamed.band_ticks.size(), plan.bands.size());
    CHECK_MSG(trace == reference.str(),
              "streamed trace (" + std::to_string(trace.size()) + " bytes, waited " +
                  std::to_string(stream.busy_answers) + " times) equals haloplot sim's (" +
                  std::to_string(reference.str().size()) + " bytes)");
    if (busy > 0) CHECK(stream.busy_answers >= plan.bands.size());
  }
  // A band sent without one of the edges that lie wholly in its rows: the plot must not come out
  // the same.
  {
    BandPlan broken = plan;
    PlannedBand& b = broken.bands[broken.bands.size() / 2];
    size_t k = 0;
    while (k < b.edges.size() && !(std::min(b.edges[k].a.y, b.edges[k].b.y) >= b.y0 &&
                                   std::max(b.edges[k].a.y, b.edges[k].b.y) < b.y1))
      ++k;
    CHECK(k < b.edges.size());
    b.edges.erase(b.edges.begin() + long(k));
    b.ids.erase(b.ids.begin() + long(k));
    PlanStream stream;
    stream.plan = &broken;
    std::ostringstream out;
    SimReport streamed;
    const Status s =
        simulate_streamed(job, stream.stream(), broken.margin, kArena, &out, &streamed);
    CHECK_MSG(!ok(s) || out.str() != reference.str(),
              "a band missing an edge must change the plot");
  }
  check_solid(false);
  check_solid(true);
  check_solid(true, true);
  check_solid(false, true, true);
  return check::finish("band_stream");
}
