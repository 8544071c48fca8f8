#include "haloplot/solid/classify.h"

#include "haloplot/geometry/wide.h"
#include "solid/cover.h"

namespace haloplot {
namespace {

uint32_t far_corner(const Triangle& t, uint32_t a, uint32_t b) {
  for (int k = 0; k < 3; ++k)
    if (t.v[k] != a && t.v[k] != b) return t.v[k];
  return t.v[0];
}

}  // namespace

bool convex_edge(const Topology& topo, uint32_t edge) {
  const SolidEdge& e = topo.edges[edge];
  const Triangle& f0 = topo.triangles[e.face[0]];
  const Point3& a = topo.vertices[f0.v[0]];
  const Point3& b = topo.vertices[f0.v[1]];
  const Point3& c = topo.vertices[f0.v[2]];
  const Point3& q = topo.vertices[far_corner(topo.triangles[e.face[1]], e.v0, e.v1)];
  // Outward normal n = (b - a) x (c - a): components below 2^42; n . (q - a) below 2^65.
  const int64_t ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const int64_t vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const int64_t nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  const Wide s = mul_i64(nx, q.x - a.x) + mul_i64(ny, q.y - a.y) + mul_i64(nz, q.z - a.z);
  return s.negative();
}

int front_face_side(const Topology& topo, const uint8_t* front, uint32_t edge) {
  const SolidEdge& e = topo.edges[edge];
  const uint32_t f = front[e.face[0]] ? e.face[0] : e.face[1];
  const Point3 a = topo.vertices[e.v0], b = topo.vertices[e.v1];
  const Point3 p = topo.vertices[far_corner(topo.triangles[f], e.v0, e.v1)];
  const int64_t s = int64_t{b.x - a.x} * (p.y - a.y) - int64_t{b.y - a.y} * (p.x - a.x);
  return s > 0 ? 1 : -1;
}

namespace {

// +1: face f's far corner from edge (a, b) lies left of a -> b on paper, -1 right, 0 on it.
int corner_side(const Topology& topo, uint32_t f, uint32_t a, uint32_t b) {
  const Point3 pa = topo.vertices[a], pb = topo.vertices[b];
  const Point3 p = topo.vertices[far_corner(topo.triangles[f], a, b)];
  const int64_t s = int64_t{pb.x - pa.x} * (p.y - pa.y) - int64_t{pb.y - pa.y} * (p.x - pa.x);
  return s > 0 ? 1 : (s < 0 ? -1 : 0);
}

bool has_corner(const Triangle& t, uint32_t v) { return t.v[0] == v || t.v[1] == v || t.v[2] == v; }

}  // namespace

int paper_jump(const Topology& topo, uint32_t edge) {
  const SolidEdge& e = topo.edges[edge];
  int sum = 0;
  const bool more = !e.regular && e.face[0] != kNoFace && e.face[1] != kNoFace &&
                    topo.vertex_face_first != nullptr;
  if (!more) {  // the faces the edge keeps are all its faces
    for (int k = 0; k < 2; ++k)
      if (e.face[k] != kNoFace) sum += corner_side(topo, e.face[k], e.v0, e.v1);
    return sum;
  }
  for (uint32_t k = topo.vertex_face_first[e.v0]; k < topo.vertex_face_first[e.v0 + 1]; ++k) {
    const uint32_t f = topo.vertex_faces[k];
    if (has_corner(topo.triangles[f], e.v1)) sum += corner_side(topo, f, e.v0, e.v1);
  }
  return sum;
}

bool paper_h3(const Topology& topo, uint32_t edge, int* side) {
  const SolidEdge& e = topo.edges[edge];
  if (!e.regular) return false;
  const uint32_t* f0 = topo.triangles[e.face[0]].v;
  const uint32_t* f1 = topo.triangles[e.face[1]].v;
  const bool ccw0 =
      projected_area2(topo.vertices[f0[0]], topo.vertices[f0[1]], topo.vertices[f0[2]]) > 0;
  const bool ccw1 =
      projected_area2(topo.vertices[f1[0]], topo.vertices[f1[1]], topo.vertices[f1[2]]) > 0;
  if (ccw0 == ccw1 || !convex_edge(topo, edge)) return false;
  if (side != nullptr)
    *side = corner_side(topo, ccw0 ? e.face[0] : e.face[1], e.v0, e.v1) >= 0 ? 1 : -1;
  return true;
}

bool edge_on_contour(const Topology& topo, uint32_t edge) {
  const SolidEdge& e = topo.edges[edge];
  if (!e.regular || !paper_h3(topo, edge)) return false;
  for (int k = 0; k < 2; ++k) {
    const uint32_t* v = topo.triangles[e.face[k]].v;
    if (projected_area2(topo.vertices[v[0]], topo.vertices[v[1]], topo.vertices[v[2]]) == 0)
      return true;
  }
  return false;
}

ClassCounts classify(Topology* topo, uint8_t* front, const uint8_t* facing) {
  ClassCounts k;
  for (uint32_t t = 0; t < topo->n_triangles; ++t) {
    const uint32_t* v = topo->triangles[t].v;
    const bool f = facing != nullptr ? facing[t] != 0
                                     : projected_area2(topo->vertices[v[0]], topo->vertices[v[1]],
                                                       topo->vertices[v[2]]) > 0;
    front[t] = f ? 1 : 0;
    ++(f ? k.front_faces : k.back_faces);
  }
  for (uint32_t i = 0; i < topo->n_edges; ++i) {
    SolidEdge& e = topo->edges[i];
    EdgeClass c = EdgeClass::kLoose;
    if (e.regular) {
      const int fronts = front[e.face[0]] + front[e.face[1]];
      if (fronts == 0)
        c = EdgeClass::kH1;
      else if (fronts == 2)
        c = EdgeClass::kH4;
      else
        c = convex_edge(*topo, i) ? EdgeClass::kH3 : EdgeClass::kH2;
    }
    e.cls = c;
    ++k.h[static_cast<int>(c)];
  }
  return k;
}

}  // namespace haloplot
