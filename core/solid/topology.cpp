#include "solid/topology.h"

#include "memory/carve.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

// An undirected side keyed by (smaller vertex, larger vertex), and where it came from.
struct SideKey {
  uint64_t key;
  uint32_t ref;  // drawn edge index, or 3 * triangle + corner
};

uint64_t key_of(uint32_t a, uint32_t b) {
  return a < b ? (uint64_t{a} << 32) | b : (uint64_t{b} << 32) | a;
}

bool key_less(const SideKey& x, const SideKey& y) {
  return x.key < y.key || (x.key == y.key && x.ref < y.ref);
}

// Index of `key` among sorted drawn keys, or n if absent (binary search).
uint32_t find_key(const SideKey* keys, uint32_t n, uint64_t key) {
  uint32_t lo = 0, hi = n;
  while (lo < hi) {
    const uint32_t mid = lo + (hi - lo) / 2;
    if (keys[mid].key < key)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo < n && keys[lo].key == key ? lo : n;
}

template <typename C>
void count_arrays(C& c, const SolidInput& in) {
  const size_t sides = size_t{in.n_triangles} * 3;
  c.template take<SolidEdge>(in.n_edges + sides);  // edges
  c.template take<uint32_t>(sides);                // side_edge
  c.template take<uint32_t>(in.n_vertices + 1);    // vertex_edge_first
  c.template take<uint32_t>(2 * (in.n_edges + sides));
  c.template take<uint32_t>(in.n_vertices + 1);  // vertex_face_first
  c.template take<uint32_t>(sides);
  c.template take<SideKey>(in.n_edges);          // drawn keys (dead after the build)
  c.template take<SideKey>(sides);               // side keys (dead after the build)
  c.template take<uint8_t>(in.n_edges + sides);  // faces per edge
}

}  // namespace

size_t topology_bytes(const SolidInput& in) {
  ByteCounter c;
  count_arrays(c, in);
  return c.total + 8;
}

Status build_topology(const SolidInput& in, void* buffer, size_t bytes, Topology* out) {
  if (in.n_edges > 0x3fffffffu || in.n_triangles > 0x3fffffffu / 3) return Status::kTooManyEdges;
  for (uint32_t i = 0; i < in.n_vertices; ++i)
    if (!in_range(in.vertices[i])) return Status::kCoordinateOutOfRange;
  for (uint32_t e = 0; e < in.n_edges; ++e) {
    const uint32_t a = in.edge_pairs[2 * e], b = in.edge_pairs[2 * e + 1];
    if (a >= in.n_vertices || b >= in.n_vertices || a == b) return Status::kBadParameter;
  }
  for (uint32_t t = 0; t < in.n_triangles; ++t) {
    const uint32_t* v = in.triangles[t].v;
    if (v[0] >= in.n_vertices || v[1] >= in.n_vertices || v[2] >= in.n_vertices)
      return Status::kBadParameter;
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) return Status::kBadParameter;
  }
  const uint32_t sides = in.n_triangles * 3;
  Carver carve(buffer, bytes);
  Topology t;
  t.vertices = in.vertices;
  t.n_vertices = in.n_vertices;
  t.triangles = in.triangles;
  t.n_triangles = in.n_triangles;
  t.edges = carve.take<SolidEdge>(in.n_edges + sides);
  t.side_edge = carve.take<uint32_t>(sides);
  t.vertex_edge_first = carve.take<uint32_t>(in.n_vertices + 1);
  t.vertex_edges = carve.take<uint32_t>(2 * (size_t{in.n_edges} + sides));
  t.vertex_face_first = carve.take<uint32_t>(in.n_vertices + 1);
  t.vertex_faces = carve.take<uint32_t>(sides);
  SideKey* drawn = carve.take<SideKey>(in.n_edges);
  SideKey* side = carve.take<SideKey>(sides);
  uint8_t* nfaces = carve.take<uint8_t>(in.n_edges + sides);
  if (carve.short_) return Status::kWorkspaceTooSmall;

  // Drawn edges keep their input order and index; a repeat is an input error.
  for (uint32_t e = 0; e < in.n_edges; ++e) {
    const uint32_t a = in.edge_pairs[2 * e], b = in.edge_pairs[2 * e + 1];
    t.edges[e] = SolidEdge{a, b, {kNoFace, kNoFace}, EdgeClass::kLoose, true, false};
    drawn[e] = SideKey{key_of(a, b), e};
  }
  heap_sort(drawn, in.n_edges, key_less);
  for (uint32_t i = 1; i < in.n_edges; ++i)
    if (drawn[i].key == drawn[i - 1].key) return Status::kBadParameter;

  // Triangle sides that are not drawn edges become diagonals, numbered in key order so the
  // result does not depend on the triangle order.
  uint32_t n_side = 0;
  for (uint32_t s = 0; s < sides; ++s) {
    const Triangle& tri = in.triangles[s / 3];
    const uint32_t a = tri.v[s % 3], b = tri.v[(s % 3 + 1) % 3];
    const uint64_t k = key_of(a, b);
    const uint32_t d = find_key(drawn, in.n_edges, k);
    if (d < in.n_edges)
      t.side_edge[s] = drawn[d].ref;
    else
      side[n_side++] = SideKey{k, s};
  }
  heap_sort(side, n_side, key_less);
  uint32_t n = in.n_edges;
  for (uint32_t i = 0; i < n_side; ++i) {
    if (i == 0 || side[i].key != side[i - 1].key) {
      const uint32_t a = static_cast<uint32_t>(side[i].key >> 32);
      const uint32_t b = static_cast<uint32_t>(side[i].key & 0xffffffffu);
      t.edges[n++] = SolidEdge{a, b, {kNoFace, kNoFace}, EdgeClass::kLoose, false, false};
    }
    t.side_edge[side[i].ref] = n - 1;
  }
  t.n_edges = n;
  t.n_drawn = in.n_edges;

  // Attach faces: a side running v0 -> v1 takes slot 0, v1 -> v0 slot 1.
  for (uint32_t e = 0; e < n; ++e) nfaces[e] = 0;
  for (uint32_t s = 0; s < sides; ++s) {
    const Triangle& tri = in.triangles[s / 3];
    const uint32_t a = tri.v[s % 3];
    SolidEdge& e = t.edges[t.side_edge[s]];
    const int slot = a == e.v0 ? 0 : 1;
    if (nfaces[t.side_edge[s]] < 255) ++nfaces[t.side_edge[s]];
    if (e.face[slot] == kNoFace)
      e.face[slot] = s / 3;
    else if (e.face[1 - slot] == kNoFace)
      e.face[1 - slot] = s / 3;  // kept so the edge still has two faces; counted below
  }
  for (uint32_t e = 0; e < n; ++e) {
    const SolidEdge se = t.edges[e];
    if (nfaces[e] == 0) {
      ++t.check.loose_edges;
    } else if (nfaces[e] == 1) {
      ++t.check.boundary_edges;
    } else if (nfaces[e] > 2) {
      ++t.check.nonmanifold_edges;
    } else {
      // Two faces: consistent iff they run the edge in opposite directions.
      const Triangle& f0 = in.triangles[se.face[0]];
      const Triangle& f1 = in.triangles[se.face[1]];
      bool f0_forward = false, f1_forward = false;
      for (int k = 0; k < 3; ++k) {
        if (f0.v[k] == se.v0 && f0.v[(k + 1) % 3] == se.v1) f0_forward = true;
        if (f1.v[k] == se.v0 && f1.v[(k + 1) % 3] == se.v1) f1_forward = true;
      }
      if (f0_forward == f1_forward)
        ++t.check.misoriented_edges;
      else
        t.edges[e].regular = true;
    }
  }

  // Stars, by counting then filling.
  for (uint32_t v = 0; v <= in.n_vertices; ++v) t.vertex_edge_first[v] = t.vertex_face_first[v] = 0;
  for (uint32_t e = 0; e < n; ++e) {
    ++t.vertex_edge_first[t.edges[e].v0 + 1];
    ++t.vertex_edge_first[t.edges[e].v1 + 1];
  }
  for (uint32_t s = 0; s < sides; ++s) ++t.vertex_face_first[in.triangles[s / 3].v[s % 3] + 1];
  for (uint32_t v = 0; v < in.n_vertices; ++v) {
    t.vertex_edge_first[v + 1] += t.vertex_edge_first[v];
    t.vertex_face_first[v + 1] += t.vertex_face_first[v];
  }
  // Fill using the next slot of each vertex (the first array shifted by one, restored after).
  for (uint32_t e = 0; e < n; ++e) {
    t.vertex_edges[t.vertex_edge_first[t.edges[e].v0]++] = e;
    t.vertex_edges[t.vertex_edge_first[t.edges[e].v1]++] = e;
  }
  for (uint32_t s = 0; s < sides; ++s)
    t.vertex_faces[t.vertex_face_first[in.triangles[s / 3].v[s % 3]]++] = s / 3;
  for (uint32_t v = in.n_vertices; v > 0; --v) {
    t.vertex_edge_first[v] = t.vertex_edge_first[v - 1];
    t.vertex_face_first[v] = t.vertex_face_first[v - 1];
  }
  t.vertex_edge_first[0] = t.vertex_face_first[0] = 0;
  *out = t;
  return Status::kOk;
}

}  // namespace haloplot
