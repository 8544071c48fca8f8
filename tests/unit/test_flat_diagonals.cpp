// drop_flat_diagonals (solid/topology.h), on hand-worked meshes: a square split along a
// diagonal, seen from the front and from behind, loses the diagonal (its faces lie on both sides
// of it on paper); a fold (the second face turned over onto the first), a diagonal whose faces
// the model's facing tells apart, a face of no area and a topology with stars keep every edge.
#include <cstdint>

#include "check.h"
#include "haloplot/solid/topology.h"

using namespace haloplot;

namespace {

struct Built {
  Topology t;
  size_t kept_before = 0;
  alignas(8) uint8_t buffer[4096];
};

// Vertices 0..4, the given triangles (one polygon each: their shared side is undrawn), the
// square's four sides drawn.
void build(const Point3* v, const Triangle* tris, bool stars, Built* b) {
  static const uint32_t pairs[] = {0, 1, 1, 2, 2, 3, 3, 0};
  SolidInput in;
  in.vertices = v;
  in.n_vertices = 5;
  in.edge_pairs = pairs;
  in.n_edges = 4;
  in.triangles = tris;
  in.n_triangles = 2;
  TopologyOptions o;
  o.stars = stars;
  CHECK(build_topology(in, b->buffer, sizeof b->buffer, &b->t, o) == Status::kOk);
  b->kept_before = b->t.kept_bytes;
}

// Is side a-b among the topology's edges?
bool has_edge(const Topology& t, uint32_t a, uint32_t b) {
  for (uint32_t e = 0; e < t.n_edges; ++e)
    if ((t.edges[e].v0 == a && t.edges[e].v1 == b) || (t.edges[e].v0 == b && t.edges[e].v1 == a))
      return true;
  return false;
}

}  // namespace

int main() {
  // The square (0,0) (10,0) (10,10) (0,10); vertex 4 lies right of the diagonal 0-2 on paper.
  const Point3 v[5] = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {10, 2, 0}};
  const Triangle front[2] = {{{0, 1, 2}, 0}, {{0, 2, 3}, 1}};  // counter-clockwise: both front
  const Triangle back[2] = {{{0, 2, 1}, 0}, {{0, 3, 2}, 1}};   // clockwise: both back
  const Triangle fold[2] = {{{0, 1, 2}, 0}, {{0, 2, 4}, 1}};   // the second turned over
  {
    Built b;
    build(v, front, false, &b);
    CHECK(b.t.n_edges == 5 && b.t.n_drawn == 4);
    drop_flat_diagonals(&b.t, nullptr);
    CHECK(b.t.n_edges == 4);  // the diagonal is gone, the sides stay in order
    for (uint32_t e = 0; e < 4; ++e) CHECK(b.t.edges[e].drawn);
    CHECK(b.t.kept_bytes == b.kept_before - 24);  // 5 edges of 20 bytes in 104, 4 in 80
  }
  {
    Built b;
    build(v, back, false, &b);
    drop_flat_diagonals(&b.t, nullptr);
    CHECK(b.t.n_edges == 4 && !has_edge(b.t, 0, 2));
  }
  {
    Built b;
    build(v, fold, false, &b);
    const uint32_t n = b.t.n_edges;  // the sides 2-4 and 4-0 are diagonals too, on one face
    CHECK(has_edge(b.t, 0, 2));
    drop_flat_diagonals(&b.t, nullptr);
    CHECK(b.t.n_edges == n);  // a fold hides what passes behind it on one side only
    CHECK(has_edge(b.t, 0, 2));
    CHECK(b.t.kept_bytes == b.kept_before);
  }
  {
    Built b;
    build(v, front, false, &b);
    const uint8_t facing[2] = {1, 0};  // the model says one face is turned away
    drop_flat_diagonals(&b.t, facing);
    CHECK(b.t.n_edges == 5);
  }
  {
    // A face of no area on paper (its corners on one line): neither side, kept.
    const Point3 w[5] = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {5, 5, 7}};
    const Triangle thin[2] = {{{0, 1, 2}, 0}, {{0, 2, 4}, 1}};
    Built b;
    build(w, thin, false, &b);
    drop_flat_diagonals(&b.t, nullptr);
    CHECK(has_edge(b.t, 0, 2));
  }
  {
    Built b;
    build(v, front, true, &b);
    drop_flat_diagonals(&b.t, nullptr);
    CHECK(b.t.n_edges == 5);  // the stars name the diagonal: left as it is
  }
  return check::finish("flat_diagonals");
}
