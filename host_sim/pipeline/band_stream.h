// The host's half of a streamed plot: run the controller's band conductor over the whole scene
// with the controller's arena (a dry run: no motion), note the bands it commits and its margin,
// and cut the scene into what each band gathers, in the order a controller asks for them. A
// controller that receives these bands (band/conductor.h begin_streamed) draws exactly what the
// dry run drew, without ever holding the scene.
#pragma once
#include <cstdint>
#include <vector>

#include "haloplot/band/conductor.h"

namespace haloplot::host {

struct PlannedBand {
  int32_t y0 = 0, y1 = 0;
  std::vector<Edge3> edges;   // the edges the band gathers, in scene order (an edge plot)
  std::vector<uint32_t> ids;  // their indices in the scene (a solid's: of its drawn edges)
  // A solid's band (band/solid_source.h StagedSolidBand): the vertices it uses by ascending
  // scene index, its drawn edges as scene vertex pairs, its triangles.
  std::vector<uint32_t> vertex_ids;
  std::vector<Point3> vertices;
  std::vector<uint32_t> pairs;
  std::vector<Triangle> triangles;
};

struct BandPlan {
  bool solid = false, closed = false;  // a solid's bands, and its model's check
  bool turned = false;  // a solid's page turned a quarter: its rows are the turned frame's
  int32_t margin = 0;
  std::vector<PlannedBand> bands;
  BandStats stats;  // the dry run's
};

Status plan_streamed_bands(const std::vector<Edge3>& edges, const BandSpec& spec,
                           size_t arena_bytes, BandPlan* out);
// The same for a solid's hidden lines (band/conductor.h begin_solid).
Status plan_streamed_solid(const SolidInput& in, bool closed, const BandSpec& spec,
                           size_t arena_bytes, BandPlan* out);

// A BandStream over a plan, for the host's own runs and tests: serves the bands in order.
// `busy_every` > 0 answers kBusy that many times before each band, as a link still receiving.
struct PlanStream {
  const BandPlan* plan = nullptr;
  size_t next = 0;
  int busy_every = 0, busy_left = 0;
  uint64_t busy_answers = 0;
  StagedSolidBand staged;  // the solid band being served
  BandStream stream();
};

}  // namespace haloplot::host
