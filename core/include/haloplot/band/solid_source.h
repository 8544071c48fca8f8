// Where a banded solid plot reads its model from: random access to the projected vertices, the
// drawn edges (vertex pairs, in output order) and the faces (triangles). The band conductor
// reads the faces and edges once per band and keeps only those meeting the band's rows, and the
// vertices they use, so the model never sits in the arena whole (solid/mesh.h says what a
// solid input is).
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/solid/mesh.h"
#include "haloplot/sort/lower_bound.h"
#include "haloplot/status/status.h"

namespace haloplot {

struct SolidSource {
  void* ctx = nullptr;
  uint32_t n_vertices = 0, n_edges = 0, n_triangles = 0;
  // The whole model is a closed, consistently oriented 2-manifold (solid/topology.h MeshCheck
  // of all of it): back faces then hide nothing and Kira's classes hold. A band cannot tell,
  // since its part of a closed solid is open at its borders.
  bool closed = false;
  Status (*vertex)(void* ctx, uint32_t index, Point3* out) = nullptr;
  Status (*edge)(void* ctx, uint32_t index, uint32_t* v0, uint32_t* v1) = nullptr;
  Status (*triangle)(void* ctx, uint32_t index, Triangle* out) = nullptr;
};

// A source over a solid input the caller keeps alive.
inline SolidSource array_solid_source(const SolidInput* in, bool closed) {
  SolidSource s;
  s.ctx = const_cast<SolidInput*>(in);
  s.n_vertices = in->n_vertices;
  s.n_edges = in->n_edges;
  s.n_triangles = in->n_triangles;
  s.closed = closed;
  s.vertex = [](void* ctx, uint32_t i, Point3* out) {
    const SolidInput* model = static_cast<const SolidInput*>(ctx);
    if (i >= model->n_vertices) return Status::kBadParameter;
    *out = model->vertices[i];
    return Status::kOk;
  };
  s.edge = [](void* ctx, uint32_t i, uint32_t* v0, uint32_t* v1) {
    const uint32_t* p = static_cast<const SolidInput*>(ctx)->edge_pairs + 2 * size_t{i};
    *v0 = p[0];
    *v1 = p[1];
    return Status::kOk;
  };
  s.triangle = [](void* ctx, uint32_t i, Triangle* out) {
    *out = static_cast<const SolidInput*>(ctx)->triangles[i];
    return Status::kOk;
  };
  return s;
}

// One band of a solid as a host sends it (a streamed plot): the vertices the band uses, by
// ascending scene index, and its drawn edges (scene vertex indices; their scene edge indices
// travel beside them in StreamedBand::ids) and triangles, in scene order. Its source answers
// for the scene's vertex indices, so the band gathers from it what it gathered on the host.
struct StagedSolidBand {
  const uint32_t* vertex_ids = nullptr;  // ascending
  const Point3* vertices = nullptr;
  uint32_t n_vertices = 0;
  const uint32_t* pairs = nullptr;  // 2 per edge
  uint32_t n_edges = 0;
  const Triangle* triangles = nullptr;
  uint32_t n_triangles = 0;

  SolidSource source(bool closed) const {
    SolidSource s;
    s.ctx = const_cast<StagedSolidBand*>(this);
    s.n_vertices = n_vertices;
    s.n_edges = n_edges;
    s.n_triangles = n_triangles;
    s.closed = closed;
    s.vertex = [](void* ctx, uint32_t v, Point3* out) {
      const StagedSolidBand* b = static_cast<const StagedSolidBand*>(ctx);
      const uint32_t lo =
          lower_bound_index(0, b->n_vertices, [&](uint32_t i) { return b->vertex_ids[i] < v; });
      if (lo == b->n_vertices || b->vertex_ids[lo] != v) return Status::kUploadMismatch;
      *out = b->vertices[lo];
      return Status::kOk;
    };
    s.edge = [](void* ctx, uint32_t i, uint32_t* v0, uint32_t* v1) {
      const StagedSolidBand* b = static_cast<const StagedSolidBand*>(ctx);
      *v0 = b->pairs[2 * size_t{i}];
      *v1 = b->pairs[2 * size_t{i} + 1];
      return Status::kOk;
    };
    s.triangle = [](void* ctx, uint32_t i, Triangle* out) {
      *out = static_cast<const StagedSolidBand*>(ctx)->triangles[i];
      return Status::kOk;
    };
    return s;
  }
};

}  // namespace haloplot
