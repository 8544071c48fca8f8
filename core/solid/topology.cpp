#include "haloplot/solid/topology.h"

#include "haloplot/sort/lower_bound.h"
#include "memory/carve.h"
#include "solid/cover.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

// A drawn edge keyed by (smaller vertex, larger vertex), and its index.
struct SideKey {
  uint64_t key;
  uint32_t ref;  // drawn edge index
};

uint64_t key_of(uint32_t a, uint32_t b) {
  return a < b ? (uint64_t{a} << 32) | b : (uint64_t{b} << 32) | a;
}

bool key_less(const SideKey& x, const SideKey& y) {
  return x.key < y.key || (x.key == y.key && x.ref < y.ref);
}

// Index of `key` among sorted drawn keys, or n if absent (binary search).
uint32_t find_key(const SideKey* keys, uint32_t n, uint64_t key) {
  const uint32_t lo = lower_bound_index(0, n, [&](uint32_t i) { return keys[i].key < key; });
  return lo < n && keys[lo].key == key ? lo : n;
}

// The drawn keys, sorted, and where each lesser vertex's keys begin when the buffer had room
// for that index (by_vertex[v], n_vertices + 1 of them): a lookup then searches the few keys
// of one vertex instead of all of them, for every side of every triangle, three times over.
// Without the room it searches them all: the same answers.
struct DrawnKeys {
  const SideKey* keys;
  uint32_t n;
  const uint32_t* by_vertex = nullptr;

  uint32_t find(uint64_t key) const {
    if (by_vertex == nullptr) return find_key(keys, n, key);
    const uint32_t v = static_cast<uint32_t>(key >> 32);
    const uint32_t lo = by_vertex[v], k = by_vertex[v + 1] - lo;
    const uint32_t i = find_key(keys + lo, k, key);
    return i < k ? lo + i : n;
  }
  const SideKey& operator[](uint32_t i) const { return keys[i]; }
};

// Puts the index at [at, end) if it fits there (8-byte aligned); else leaves the search whole.
void index_drawn(uint8_t* at, const uint8_t* end, uint32_t n_vertices, DrawnKeys* d) {
  d->by_vertex = nullptr;
  uint8_t* p = reinterpret_cast<uint8_t*>((reinterpret_cast<uintptr_t>(at) + 7) & ~uintptr_t{7});
  const size_t need = (size_t{n_vertices} + 1) * sizeof(uint32_t);
  if (p > end || size_t(end - p) < need) return;
  uint32_t* first = reinterpret_cast<uint32_t*>(p);
  uint32_t i = 0;
  for (uint32_t v = 0; v <= n_vertices; ++v) {
    while (i < d->n && static_cast<uint32_t>(d->keys[i].key >> 32) < v) ++i;
    first[v] = i;
  }
  d->by_vertex = first;
}

// The arrays the topology keeps, for n edges in all (drawn and diagonals).
template <typename C>
void count_kept(C& c, const SolidInput& in, size_t n) {
  const size_t sides = size_t{in.n_triangles} * 3;
  c.template take<SolidEdge>(n);                 // edges
  c.template take<uint32_t>(in.n_vertices + 1);  // vertex_edge_first
  c.template take<uint32_t>(2 * n);              // vertex_edges
  c.template take<uint32_t>(in.n_vertices + 1);  // vertex_face_first
  c.template take<uint32_t>(sides);              // vertex_faces
}

// The build's scratch, dead once it returns: carved from the top of the buffer so the kept
// arrays below it end where the caller's next stage may begin. The drawn edges' keys, then the
// keys of the undrawn sides that become diagonals (n_side of them, counted before they are
// stored: at most every side) and the faces of each edge. A triangle side's edge is looked up
// when it is needed, not stored: a band of a large model holds many sides for few edges.
template <typename C>
void count_scratch(C& c, size_t n_drawn, size_t n_side) {
  c.template take<SideKey>(n_drawn);           // drawn keys
  c.template take<uint64_t>(n_side);           // undrawn side keys
  c.template take<uint8_t>(n_drawn + n_side);  // faces per edge
}

// Every vertex in range and every index in its array; no edge or triangle repeats a vertex.
Status check_input(const SolidInput& in) {
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
  return Status::kOk;
}

// Does side a-b meet the rows the topology keeps (all of them unless options.rows)?
bool side_in_rows(const SolidInput& in, const TopologyOptions& options, uint32_t a, uint32_t b) {
  const int32_t ya = in.vertices[a].y, yb = in.vertices[b].y;
  return !options.rows ||
         ((ya < yb ? yb : ya) >= options.row_lo && (ya < yb ? ya : yb) <= options.row_hi);
}

// The triangle sides that are not drawn edges (the diagonals to be), as keys; a band keeps only
// those meeting its rows. With `side` null they are only counted; otherwise stored and sorted,
// so the diagonals are numbered independently of the triangle order.
uint32_t undrawn_sides(const SolidInput& in, const TopologyOptions& options, const DrawnKeys& drawn,
                       uint64_t* side) {
  const uint32_t sides = in.n_triangles * 3;
  uint32_t n_side = 0;
  for (uint32_t s = 0; s < sides; ++s) {
    const Triangle& tri = in.triangles[s / 3];
    const uint32_t a = tri.v[s % 3], b = tri.v[(s % 3 + 1) % 3];
    const uint64_t k = key_of(a, b);
    if (drawn.find(k) != in.n_edges || !side_in_rows(in, options, a, b)) continue;
    if (side != nullptr) side[n_side] = k;
    ++n_side;
  }
  if (side != nullptr) sort_total(side, n_side, [](uint64_t x, uint64_t y) { return x < y; });
  return n_side;
}

// The edges: the drawn ones in input order, then one diagonal per distinct undrawn side, in
// the order of their keys (each diagonal runs from its lesser vertex).
void number_edges(const SolidInput& in, const uint64_t* side, uint32_t n_side, Topology& t) {
  for (uint32_t e = 0; e < in.n_edges; ++e)
    t.edges[e] = SolidEdge{in.edge_pairs[2 * e],
                           in.edge_pairs[2 * e + 1],
                           {kNoFace, kNoFace},
                           EdgeClass::kLoose,
                           true,
                           false};
  uint32_t n = in.n_edges;
  for (uint32_t i = 0; i < n_side; ++i) {
    if (i > 0 && side[i] == side[i - 1]) continue;
    const uint32_t a = static_cast<uint32_t>(side[i] >> 32);
    const uint32_t b = static_cast<uint32_t>(side[i] & 0xffffffffu);
    t.edges[n++] = SolidEdge{a, b, {kNoFace, kNoFace}, EdgeClass::kLoose, false, false};
  }
  t.n_edges = n;
  t.n_drawn = in.n_edges;
}

// The edge triangle side s lies on: a drawn edge, a diagonal (found among t's diagonals, which
// are in key order), or kNoFace for a band's side beyond its rows.
uint32_t side_edge(const SolidInput& in, const TopologyOptions& options, const DrawnKeys& drawn,
                   const Topology& t, uint32_t s) {
  const Triangle& tri = in.triangles[s / 3];
  const uint32_t a = tri.v[s % 3], b = tri.v[(s % 3 + 1) % 3];
  const uint64_t k = key_of(a, b);
  const uint32_t d = drawn.find(k);
  if (d < in.n_edges) return drawn[d].ref;
  if (!side_in_rows(in, options, a, b)) return kNoFace;
  // Every such side's key is a diagonal's.
  return lower_bound_index(t.n_drawn, t.n_edges,
                           [&](uint32_t i) { return key_of(t.edges[i].v0, t.edges[i].v1) < k; });
}

// Attach faces: a side running v0 -> v1 takes slot 0, v1 -> v0 slot 1. Then each edge is
// checked: loose, a boundary, non-manifold, or two faces that agree (regular) or not.
void attach_faces(const SolidInput& in, const TopologyOptions& options, const DrawnKeys& drawn,
                  uint8_t* nfaces, Topology& t) {
  const uint32_t sides = in.n_triangles * 3, n = t.n_edges;
  for (uint32_t e = 0; e < n; ++e) nfaces[e] = 0;
  for (uint32_t s = 0; s < sides; ++s) {
    const uint32_t edge = side_edge(in, options, drawn, t, s);
    if (edge == kNoFace) continue;  // a band's side beyond its rows
    const Triangle& tri = in.triangles[s / 3];
    const uint32_t a = tri.v[s % 3];
    SolidEdge& e = t.edges[edge];
    const int slot = a == e.v0 ? 0 : 1;
    if (nfaces[edge] < 255) ++nfaces[edge];
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
}

// Stars (each vertex's edges and faces), by counting then filling.
void build_stars(const SolidInput& in, Topology& t) {
  const uint32_t sides = in.n_triangles * 3, n = t.n_edges;
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
}

// A side's face on paper: +1 counter-clockwise, -1 clockwise, 0 on a line.
int paper_side(const Topology& t, uint32_t f) {
  const uint32_t* v = t.triangles[f].v;
  const int64_t a = projected_area2(t.vertices[v[0]], t.vertices[v[1]], t.vertices[v[2]]);
  return a > 0 ? 1 : (a < 0 ? -1 : 0);
}

}  // namespace

void drop_flat_diagonals(Topology* topo, const uint8_t* facing) {
  Topology& t = *topo;
  if (t.vertex_edges != nullptr) return;
  uint32_t n = t.n_drawn;
  for (uint32_t e = t.n_drawn; e < t.n_edges; ++e) {
    const SolidEdge d = t.edges[e];
    const bool flat = d.regular && paper_side(t, d.face[0]) != 0 &&
                      paper_side(t, d.face[0]) == paper_side(t, d.face[1]) &&
                      (facing == nullptr || facing[d.face[0]] == facing[d.face[1]]);
    if (!flat) t.edges[n++] = d;
  }
  t.kept_bytes = t.kept_bytes - carve_round(size_t{t.n_edges} * sizeof(SolidEdge)) +
                 carve_round(size_t{n} * sizeof(SolidEdge));
  t.n_edges = n;
}

size_t topology_star_bytes(const Topology& topo) {
  ByteCounter c;
  c.take<uint32_t>(size_t{topo.n_vertices} + 1);
  c.take<uint32_t>(2 * size_t{topo.n_edges});
  c.take<uint32_t>(size_t{topo.n_vertices} + 1);
  c.take<uint32_t>(size_t{topo.n_triangles} * 3);
  return c.total + 8;
}

Status build_topology_stars(Topology* topo, void* buffer, size_t bytes) {
  Topology& t = *topo;
  Carver carve(buffer, bytes);
  t.vertex_edge_first = carve.take<uint32_t>(size_t{t.n_vertices} + 1);
  t.vertex_edges = carve.take<uint32_t>(2 * size_t{t.n_edges});
  t.vertex_face_first = carve.take<uint32_t>(size_t{t.n_vertices} + 1);
  t.vertex_faces = carve.take<uint32_t>(size_t{t.n_triangles} * 3);
  if (carve.short_) {
    t.vertex_edge_first = t.vertex_edges = t.vertex_face_first = t.vertex_faces = nullptr;
    return Status::kWorkspaceTooSmall;
  }
  SolidInput in;
  in.vertices = t.vertices;
  in.n_vertices = t.n_vertices;
  in.triangles = t.triangles;
  in.n_triangles = t.n_triangles;
  build_stars(in, t);
  return Status::kOk;
}

size_t topology_bytes(const SolidInput& in) {
  ByteCounter kept;
  count_kept(kept, in, size_t{in.n_edges} + size_t{in.n_triangles} * 3);  // at most this many
  return kept.total + topology_scratch_bytes(in) + 8;
}

size_t topology_scratch_bytes(const SolidInput& in) {
  ByteCounter scratch;
  count_scratch(scratch, in.n_edges, size_t{in.n_triangles} * 3);  // at most every side
  return scratch.total;
}

Status build_topology(const SolidInput& in, void* buffer, size_t bytes, Topology* out,
                      const TopologyOptions& options) {
  const Status checked = check_input(in);
  if (checked != Status::kOk) return checked;
  const uint32_t sides = in.n_triangles * 3;
  // Scratch from the top of the buffer (8-byte aligned): the drawn keys first, then, once the
  // undrawn sides are counted, their keys and the face counts below them; the kept arrays from
  // the bottom once the number of edges is known.
  uint8_t* lo =
      reinterpret_cast<uint8_t*>((reinterpret_cast<uintptr_t>(buffer) + 7) & ~uintptr_t{7});
  uint8_t* hi = reinterpret_cast<uint8_t*>(
      (reinterpret_cast<uintptr_t>(static_cast<uint8_t*>(buffer) + bytes)) & ~uintptr_t{7});
  const size_t drawn_bytes = carve_round(size_t{in.n_edges} * sizeof(SideKey));
  if (buffer == nullptr || hi < lo || size_t(hi - lo) < drawn_bytes)
    return Status::kWorkspaceTooSmall;
  SideKey* drawn = reinterpret_cast<SideKey*>(hi - drawn_bytes);
  Topology t;
  t.vertices = in.vertices;
  t.n_vertices = in.n_vertices;
  t.triangles = in.triangles;
  t.n_triangles = in.n_triangles;

  // Drawn edges keep their input order and index; a repeat is an input error.
  for (uint32_t e = 0; e < in.n_edges; ++e)
    drawn[e] = SideKey{key_of(in.edge_pairs[2 * e], in.edge_pairs[2 * e + 1]), e};
  sort_total(drawn, in.n_edges, key_less);
  for (uint32_t i = 1; i < in.n_edges; ++i)
    if (drawn[i].key == drawn[i - 1].key) return Status::kBadParameter;

  // The diagonals' keys come first, so the kept arrays are carved for the exact number of edges.
  // The index of the drawn keys goes where the kept arrays will be, then above them (each time
  // only where nothing written before the next lookup can reach it).
  DrawnKeys keys{drawn, in.n_edges};
  index_drawn(lo, reinterpret_cast<uint8_t*>(drawn), in.n_vertices, &keys);
  const uint32_t n_side = undrawn_sides(in, options, keys, nullptr);
  ByteCounter scratch_size;
  count_scratch(scratch_size, in.n_edges, n_side);
  if (size_t(hi - lo) < scratch_size.total) return Status::kWorkspaceTooSmall;
  Carver scratch(hi - scratch_size.total, scratch_size.total - drawn_bytes);
  uint64_t* side = scratch.take<uint64_t>(n_side);
  uint8_t* nfaces = scratch.take<uint8_t>(size_t{in.n_edges} + n_side);
  index_drawn(lo, hi - scratch_size.total, in.n_vertices, &keys);  // below the side keys now
  undrawn_sides(in, options, keys, side);
  uint32_t n_diagonals = 0;
  for (uint32_t i = 0; i < n_side; ++i)
    if (i == 0 || side[i] != side[i - 1]) ++n_diagonals;
  Carver carve(lo, size_t(hi - lo) - scratch_size.total);
  t.edges = carve.take<SolidEdge>(size_t{in.n_edges} + n_diagonals);
  if (options.stars) {
    t.vertex_edge_first = carve.take<uint32_t>(in.n_vertices + 1);
    t.vertex_edges = carve.take<uint32_t>(2 * (size_t{in.n_edges} + n_diagonals));
    t.vertex_face_first = carve.take<uint32_t>(in.n_vertices + 1);
    t.vertex_faces = carve.take<uint32_t>(sides);
  }
  if (carve.short_) return Status::kWorkspaceTooSmall;
  t.kept_bytes = size_t(carve.next - static_cast<uint8_t*>(buffer));
  t.scratch_bytes = scratch_size.total;
  number_edges(in, side, n_side, t);
  index_drawn(carve.next, hi - scratch_size.total, in.n_vertices, &keys);
  attach_faces(in, options, keys, nfaces, t);
  if (options.stars) build_stars(in, t);
  *out = t;
  return Status::kOk;
}

}  // namespace haloplot
