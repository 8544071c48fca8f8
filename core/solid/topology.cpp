#include "haloplot/solid/topology.h"

#include "haloplot/sort/lower_bound.h"
#include "memory/carve.h"
#include "solid/build_parts.h"
#include "solid/cover.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

// A drawn edge keyed by (smaller vertex, larger vertex), and its index.
struct SideKey {
  uint64_t key;
  uint32_t ref;  // drawn edge index
};

// Side j of a triangle runs from its corner j to the next. The loops over sides take each
// triangle's three in turn (side s = 3 t + j, in the same order as s counting up) rather than
// dividing s by 3 twice over for each.
uint32_t next_corner(uint32_t j) { return j == 2 ? 0 : j + 1; }

uint64_t key_of(uint32_t a, uint32_t b) {
  return a < b ? (uint64_t{a} << 32) | b : (uint64_t{b} << 32) | a;
}

// A lambda, not a function: the sorts call it inline.
constexpr auto key_less = [](const SideKey& x, const SideKey& y) {
  return x.key < y.key || (x.key == y.key && x.ref < y.ref);
};

constexpr auto u64_less = [](uint64_t x, uint64_t y) { return x < y; };

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

uint8_t* align8(uint8_t* at) {
  return reinterpret_cast<uint8_t*>((reinterpret_cast<uintptr_t>(at) + 7) & ~uintptr_t{7});
}

// n items of T at [at, end) (8-byte aligned) if they fit there, else null.
template <typename T>
T* room_for(uint8_t* at, const uint8_t* end, size_t n) {
  uint8_t* p = align8(at);
  if (p > end || size_t(end - p) < n * sizeof(T)) return nullptr;
  return reinterpret_cast<T*>(p);
}

// first[v] for v <= n_vertices: the first of n sorted items whose lesser vertex (lesser(i)) is
// at least v. Over [at, end) if it fits there (null if not); returns it.
template <typename Lesser>
uint32_t* index_by_vertex(uint8_t* at, const uint8_t* end, uint32_t n_vertices, uint32_t n,
                          Lesser lesser) {
  uint32_t* first = room_for<uint32_t>(at, end, size_t{n_vertices} + 1);
  if (first == nullptr) return nullptr;
  uint32_t i = 0;
  for (uint32_t v = 0; v <= n_vertices; ++v) {
    while (i < n && lesser(i) < v) ++i;
    first[v] = i;
  }
  return first;
}

// Puts the drawn keys' index at [at, end) if it fits there; else leaves the search whole.
// Returns where the index ends (at when there is none).
uint8_t* index_drawn(uint8_t* at, const uint8_t* end, uint32_t n_vertices, DrawnKeys* d) {
  const SideKey* keys = d->keys;
  d->by_vertex = index_by_vertex(at, end, n_vertices, d->n, [&](uint32_t i) {
    return static_cast<uint32_t>(keys[i].key >> 32);
  });
  return d->by_vertex == nullptr ? at : align8(at) + (size_t{n_vertices} + 1) * sizeof(uint32_t);
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

// The triangle sides that are not drawn edges (the diagonals to be), of triangles [t0, t1), as
// keys; a band keeps only those meeting its rows. With `side` null they are only counted;
// otherwise stored in side order, from side[0].
uint32_t undrawn_sides(const SolidInput& in, const TopologyOptions& options, const DrawnKeys& drawn,
                       uint32_t t0, uint32_t t1, uint64_t* side) {
  uint32_t n_side = 0;
  for (uint32_t t = t0; t < t1; ++t) {
    const Triangle& tri = in.triangles[t];
    for (uint32_t j = 0; j < 3; ++j) {
      const uint32_t a = tri.v[j], b = tri.v[next_corner(j)];
      const uint64_t k = key_of(a, b);
      if (drawn.find(k) != in.n_edges || !side_in_rows(in, options, a, b)) continue;
      if (side != nullptr) side[n_side] = k;
      ++n_side;
    }
  }
  return n_side;
}

// The build's parts and what they share: part i stores the undrawn sides of its range of
// triangles or (with room for a count per vertex) of its range of lesser vertices, numbers the
// diagonals of its range of sorted sides, attaches the faces of the edges whose lesser vertex
// lies in its range of vertices (it alone writes them, in side order as one part would) and
// checks its range of edges.
struct Build {
  const SolidInput& in;
  const TopologyOptions& options;
  const Parts* parts;
  uint32_t k;  // parts
  DrawnKeys drawn;
  const uint32_t* diagonal_by_vertex = nullptr;  // first diagonal (from n_drawn) by lesser vertex
  Topology& t;
  uint64_t* side = nullptr;
  uint32_t n_side = 0;
  uint8_t* nfaces = nullptr;
  uint32_t sides_before[kMaxBuildParts + 1] = {};      // undrawn sides of the parts before i
  uint32_t diagonals_before[kMaxBuildParts + 1] = {};  // distinct sides of the sorted ranges
  MeshCheck checks[kMaxBuildParts];

  Build(const SolidInput& input, const TopologyOptions& o, const DrawnKeys& d, Topology& topo)
      : in(input),
        options(o),
        parts(o.parts),
        k(build_part_count(o.parts, uint64_t{input.n_triangles} * 3 + input.n_edges)),
        drawn(d),
        t(topo) {}
  // The steps that store by vertex (the drawn keys, the undrawn sides, the diagonals' index),
  // in one part as in many, where they fit: they replace the sorts of everything, about half the
  // build's work (the 1M-triangle torus's build on one thread: some 350 -> 165 ms CPU). Never
  // on a chip: its flash and stack keep no room for them (the sorts give the same arrays).
  bool by_vertex() const { return kMaxBuildParts > 1; }
  template <typename F>
  void run(F f) {
    each_part(parts, k, f);
  }
  uint32_t triangle_begin(uint32_t i) const { return part_begin(in.n_triangles, k, i); }
  uint32_t side_begin(uint32_t i) const { return part_begin(n_side, k, i); }
  // The diagonal with key `key`, which every undrawn side in the rows has.
  uint32_t find_diagonal(uint64_t key) const {
    uint32_t lo = t.n_drawn, hi = t.n_edges;
    if (diagonal_by_vertex != nullptr) {
      const uint32_t v = static_cast<uint32_t>(key >> 32);
      hi = lo + diagonal_by_vertex[v + 1];
      lo += diagonal_by_vertex[v];
    }
    return lower_bound_index(
        lo, hi, [&](uint32_t i) { return key_of(t.edges[i].v0, t.edges[i].v1) < key; });
  }
};

// Counts the undrawn sides of every part's triangles; returns them all.
uint32_t count_sides(Build& b) {
  uint32_t count[kMaxBuildParts] = {};
  b.run([&](uint32_t i) {
    count[i] = undrawn_sides(b.in, b.options, b.drawn, b.triangle_begin(i), b.triangle_begin(i + 1),
                             nullptr);
  });
  for (uint32_t i = 0; i < b.k; ++i) b.sides_before[i + 1] = b.sides_before[i] + count[i];
  return b.sides_before[b.k];
}

// Stores the undrawn sides, part i those of its triangles, and sorts them whole, so the
// diagonals are numbered independently of the triangle order.
void sort_sides(Build& b) {
  b.run([&](uint32_t i) {
    undrawn_sides(b.in, b.options, b.drawn, b.triangle_begin(i), b.triangle_begin(i + 1),
                  b.side + b.sides_before[i]);
  });
  sort_total(b.side, b.n_side, u64_less);
}

// Calls f(key) for each undrawn side in the rows whose lesser vertex is in [v_lo, v_hi), in
// side order.
template <typename F>
void undrawn_by_vertex(const Build& b, uint32_t v_lo, uint32_t v_hi, F f) {
  for (uint32_t t = 0; t < b.in.n_triangles; ++t) {
    const Triangle& tri = b.in.triangles[t];
    for (uint32_t j = 0; j < 3; ++j) {
      const uint32_t a = tri.v[j], c = tri.v[next_corner(j)];
      const uint32_t lesser = a < c ? a : c;
      if (lesser < v_lo || lesser >= v_hi) continue;
      const uint64_t key = key_of(a, c);
      if (b.drawn.find(key) == b.in.n_edges && side_in_rows(b.in, b.options, a, c)) f(key);
    }
  }
}

// Items in order of their keys without a sort of them all, where there is room for a count per
// vertex (`start`, n_vertices + 1) and the key begins with the item's lesser vertex (a drawn
// edge's, an undrawn side's): part i counts the items whose lesser vertex is in its range of
// vertices (each(v_lo, v_hi, f) calls f(lesser vertex, item) for those, in order), then stores
// them from where the vertices before end and sorts each vertex's few. First count_by_vertex:
// the counts into start[v + 1], then each vertex's next slot; where part i's items begin into
// before[i]; returns the items. Then store_by_vertex: start[v] becomes v's first item.
template <typename Each>
uint32_t count_by_vertex(Build& b, uint32_t* start, uint32_t* before, Each each) {
  const uint32_t nv = b.in.n_vertices;
  b.run([&](uint32_t i) {
    const uint32_t lo = part_begin(nv, b.k, i), hi = part_begin(nv, b.k, i + 1);
    uint32_t* count = start + 1;
    for (uint32_t v = lo; v < hi; ++v) count[v] = 0;
    each(lo, hi, [&](uint32_t v, const auto&) { ++count[v]; });
  });
  start[0] = 0;
  uint32_t n = 0;
  for (uint32_t i = 0; i < b.k; ++i) {
    before[i] = n;
    for (uint32_t v = part_begin(nv, b.k, i); v < part_begin(nv, b.k, i + 1); ++v) {
      const uint32_t c = start[v + 1];
      start[v + 1] = n;  // vertex v's next slot while storing; its end after
      n += c;
    }
  }
  return n;
}

template <typename T, typename Each, typename Less>
void store_by_vertex(Build& b, uint32_t* start, const uint32_t* before, T* out, Each each,
                     Less less) {
  const uint32_t nv = b.in.n_vertices;
  b.run([&](uint32_t i) {
    const uint32_t lo = part_begin(nv, b.k, i), hi = part_begin(nv, b.k, i + 1);
    each(lo, hi, [&](uint32_t v, const T& item) { out[start[v + 1]++] = item; });
    uint32_t from = before[i];  // start[lo] may be the part before's, still storing
    for (uint32_t v = lo; v < hi; ++v) {
      sort_total(out + from, start[v + 1] - from, less);
      from = start[v + 1];
    }
  });
}

// The undrawn sides by their lesser vertex, for count_by_vertex and store_by_vertex.
auto sides_by_vertex(const Build& b) {
  return [&b](uint32_t v_lo, uint32_t v_hi, auto f) {
    undrawn_by_vertex(b, v_lo, v_hi, [&](uint64_t key) { f(uint32_t(key >> 32), key); });
  };
}

// The drawn keys sorted and indexed by lesser vertex (the index at [at, end), as index_drawn
// makes it), in parts; false, and nothing done, where the index does not fit.
bool sort_drawn_by_vertex(Build& b, uint8_t* at, const uint8_t* end, SideKey* drawn) {
  uint32_t* start = room_for<uint32_t>(at, end, size_t{b.in.n_vertices} + 1);
  if (start == nullptr) return false;
  const uint32_t* pairs = b.in.edge_pairs;
  const uint32_t n = b.in.n_edges;
  auto each = [pairs, n](uint32_t v_lo, uint32_t v_hi, auto f) {
    for (uint32_t e = 0; e < n; ++e) {
      const uint32_t x = pairs[2 * e], y = pairs[2 * e + 1], lesser = x < y ? x : y;
      if (lesser >= v_lo && lesser < v_hi) f(lesser, SideKey{key_of(x, y), e});
    }
  };
  uint32_t before[kMaxBuildParts] = {};
  count_by_vertex(b, start, before, each);
  store_by_vertex(b, start, before, drawn, each, key_less);
  b.drawn.by_vertex = start;
  return true;
}

// The diagonals: one per distinct sorted side. Returns how many.
uint32_t count_diagonals(Build& b) {
  uint32_t count[kMaxBuildParts] = {};
  b.run([&](uint32_t i) {
    count[i] = 0;
    for (uint32_t s = b.side_begin(i); s < b.side_begin(i + 1); ++s)
      if (s == 0 || b.side[s] != b.side[s - 1]) ++count[i];
  });
  for (uint32_t i = 0; i < b.k; ++i) b.diagonals_before[i + 1] = b.diagonals_before[i] + count[i];
  return b.diagonals_before[b.k];
}

// The edges: the drawn ones in input order, then one diagonal per distinct undrawn side, in
// the order of their keys (each diagonal runs from its lesser vertex). No edge has a face yet.
void number_edges(Build& b) {
  const SolidInput& in = b.in;
  Topology& t = b.t;
  t.n_edges = in.n_edges + b.diagonals_before[b.k];
  t.n_drawn = in.n_edges;
  b.run([&](uint32_t i) {
    for (uint32_t e = part_begin(in.n_edges, b.k, i); e < part_begin(in.n_edges, b.k, i + 1); ++e)
      t.edges[e] = SolidEdge{in.edge_pairs[2 * e],
                             in.edge_pairs[2 * e + 1],
                             {kNoFace, kNoFace},
                             EdgeClass::kLoose,
                             true,
                             false};
    uint32_t n = in.n_edges + b.diagonals_before[i];
    for (uint32_t s = b.side_begin(i); s < b.side_begin(i + 1); ++s) {
      if (s > 0 && b.side[s] == b.side[s - 1]) continue;
      const uint32_t v0 = static_cast<uint32_t>(b.side[s] >> 32);
      const uint32_t v1 = static_cast<uint32_t>(b.side[s] & 0xffffffffu);
      t.edges[n++] = SolidEdge{v0, v1, {kNoFace, kNoFace}, EdgeClass::kLoose, false, false};
    }
    for (uint32_t e = part_begin(t.n_edges, b.k, i); e < part_begin(t.n_edges, b.k, i + 1); ++e)
      b.nfaces[e] = 0;
  });
}

// Attaches the faces of the sides whose lesser vertex is in [v_lo, v_hi), in side order: a
// side running v0 -> v1 takes slot 0, v1 -> v0 slot 1 (the other when taken).
void attach_range(Build& b, uint32_t v_lo, uint32_t v_hi) {
  const SolidInput& in = b.in;
  for (uint32_t t = 0; t < in.n_triangles; ++t) {
    const Triangle& tri = in.triangles[t];
    for (uint32_t j = 0; j < 3; ++j) {
      const uint32_t a = tri.v[j], b_ = tri.v[next_corner(j)];
      const uint32_t lesser = a < b_ ? a : b_;
      if (lesser < v_lo || lesser >= v_hi) continue;
      const uint64_t key = key_of(a, b_);
      const uint32_t d = b.drawn.find(key);
      uint32_t edge;
      if (d < in.n_edges)
        edge = b.drawn[d].ref;
      else if (side_in_rows(in, b.options, a, b_))
        edge = b.find_diagonal(key);
      else
        continue;  // a band's side beyond its rows
      SolidEdge& e = b.t.edges[edge];
      const int slot = a == e.v0 ? 0 : 1;
      if (b.nfaces[edge] < 255) ++b.nfaces[edge];
      if (e.face[slot] == kNoFace)
        e.face[slot] = t;
      else if (e.face[1 - slot] == kNoFace)
        e.face[1 - slot] = t;  // kept so the edge still has two faces; counted below
    }
  }
}

// Each edge of [e_lo, e_hi) checked: loose, a boundary, non-manifold, or two faces that agree
// (regular) or not.
void check_range(Build& b, uint32_t e_lo, uint32_t e_hi, MeshCheck* check) {
  for (uint32_t e = e_lo; e < e_hi; ++e) {
    const SolidEdge se = b.t.edges[e];
    if (b.nfaces[e] == 0) {
      ++check->loose_edges;
    } else if (b.nfaces[e] == 1) {
      ++check->boundary_edges;
    } else if (b.nfaces[e] > 2) {
      ++check->nonmanifold_edges;
    } else {
      // Two faces: consistent iff they run the edge in opposite directions.
      const Triangle& f0 = b.in.triangles[se.face[0]];
      const Triangle& f1 = b.in.triangles[se.face[1]];
      bool f0_forward = false, f1_forward = false;
      for (int k = 0; k < 3; ++k) {
        if (f0.v[k] == se.v0 && f0.v[(k + 1) % 3] == se.v1) f0_forward = true;
        if (f1.v[k] == se.v0 && f1.v[(k + 1) % 3] == se.v1) f1_forward = true;
      }
      if (f0_forward == f1_forward)
        ++check->misoriented_edges;
      else
        b.t.edges[e].regular = true;
    }
  }
}

void attach_faces(Build& b) {
  const uint32_t nv = b.in.n_vertices, ne = b.t.n_edges, k = b.k;
  b.run([&](uint32_t i) { attach_range(b, part_begin(nv, k, i), part_begin(nv, k, i + 1)); });
  b.run([&](uint32_t i) {
    b.checks[i] = MeshCheck{};
    check_range(b, part_begin(ne, k, i), part_begin(ne, k, i + 1), &b.checks[i]);
  });
  MeshCheck& c = b.t.check;
  for (uint32_t i = 0; i < k; ++i) {
    c.loose_edges += b.checks[i].loose_edges;
    c.boundary_edges += b.checks[i].boundary_edges;
    c.nonmanifold_edges += b.checks[i].nonmanifold_edges;
    c.misoriented_edges += b.checks[i].misoriented_edges;
  }
}

// Stars (each vertex's edges and faces), by counting then filling. Part i counts and fills the
// stars of its range of vertices, reading every edge and face in order as one part would.
void build_stars(const SolidInput& in, Topology& t, const Parts* parts) {
  const uint32_t sides = in.n_triangles * 3, n = t.n_edges, nv = in.n_vertices;
  const uint32_t k = build_part_count(parts, uint64_t{sides} + 2 * uint64_t{n});
  uint32_t* edge_next = t.vertex_edge_first + 1;  // counts, then each vertex's next slot
  uint32_t* face_next = t.vertex_face_first + 1;
  auto count = [&](uint32_t i) {
    const uint32_t lo = part_begin(nv, k, i), hi = part_begin(nv, k, i + 1);
    for (uint32_t v = lo; v < hi; ++v) edge_next[v] = face_next[v] = 0;
    for (uint32_t e = 0; e < n; ++e) {
      const uint32_t v0 = t.edges[e].v0, v1 = t.edges[e].v1;
      if (v0 >= lo && v0 < hi) ++edge_next[v0];
      if (v1 >= lo && v1 < hi) ++edge_next[v1];
    }
    for (uint32_t f = 0; f < in.n_triangles; ++f)
      for (const uint32_t v : in.triangles[f].v)
        if (v >= lo && v < hi) ++face_next[v];
  };
  each_part(parts, k, count);
  // The starts, each vertex's at first[v]; the next slot of v is first[v + 1] while filling.
  t.vertex_edge_first[0] = t.vertex_face_first[0] = 0;
  uint32_t edges_before = 0, faces_before = 0;
  for (uint32_t v = 0; v < nv; ++v) {
    const uint32_t ec = edge_next[v], fc = face_next[v];
    edge_next[v] = edges_before;
    face_next[v] = faces_before;
    edges_before += ec;
    faces_before += fc;
  }
  auto fill = [&](uint32_t i) {
    const uint32_t lo = part_begin(nv, k, i), hi = part_begin(nv, k, i + 1);
    for (uint32_t e = 0; e < n; ++e) {
      const uint32_t v0 = t.edges[e].v0, v1 = t.edges[e].v1;
      if (v0 >= lo && v0 < hi) t.vertex_edges[edge_next[v0]++] = e;
      if (v1 >= lo && v1 < hi) t.vertex_edges[edge_next[v1]++] = e;
    }
    for (uint32_t f = 0; f < in.n_triangles; ++f)
      for (const uint32_t v : in.triangles[f].v)
        if (v >= lo && v < hi) t.vertex_faces[face_next[v]++] = f;
  };
  each_part(parts, k, fill);
  // Each next slot ends where the vertex's star ends: first[v + 1], as it should be.
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

Status build_topology_stars(Topology* topo, void* buffer, size_t bytes, const Parts* parts) {
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
  build_stars(in, t, parts);
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

// By vertex (Build::by_vertex: a 64-bit host, in one part or many), the build takes more room
// than by sorting, never more than topology_bytes(): a copy of the drawn keys (sorted by vertex
// from the copy), a count of undrawn sides per vertex (the sides then stored by vertex, needing
// no sort) and an index of the diagonals by vertex, each where the kept arrays will be or in
// the gap above them, and only when it fits (otherwise the build sorts, as a chip does: the
// same result).
Status build_topology(const SolidInput& in, void* buffer, size_t bytes, Topology* out,
                      const TopologyOptions& options) {
  const Status checked = check_input(in);
  if (checked != Status::kOk) return checked;
  const uint32_t sides = in.n_triangles * 3;
  // Scratch from the top of the buffer (8-byte aligned): the drawn keys first, then, once the
  // undrawn sides are counted, their keys and the face counts below them; the kept arrays from
  // the bottom once the number of edges is known.
  uint8_t* lo = align8(static_cast<uint8_t*>(buffer));
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
  Build b(in, options, DrawnKeys{drawn, in.n_edges}, t);

  // Drawn edges keep their input order and index; a repeat is an input error. By vertex, sorted
  // by vertex where their index will be (it is made on the way).
  const bool drawn_sorted =
      b.by_vertex() && sort_drawn_by_vertex(b, lo, reinterpret_cast<uint8_t*>(drawn), drawn);
  if (!drawn_sorted) {
    for (uint32_t e = 0; e < in.n_edges; ++e)
      drawn[e] = SideKey{key_of(in.edge_pairs[2 * e], in.edge_pairs[2 * e + 1]), e};
    sort_total(drawn, in.n_edges, key_less);
  }
  for (uint32_t i = 1; i < in.n_edges; ++i)
    if (drawn[i].key == drawn[i - 1].key) return Status::kBadParameter;

  // The diagonals' keys come first, so the kept arrays are carved for the exact number of edges.
  // The index of the drawn keys goes where the kept arrays will be, then above them (each time
  // only where nothing written before the next lookup can reach it).
  uint8_t* index_end =
      drawn_sorted ? align8(lo) + (size_t{in.n_vertices} + 1) * sizeof(uint32_t)
                   : index_drawn(lo, reinterpret_cast<uint8_t*>(drawn), in.n_vertices, &b.drawn);
  // By vertex, the sides where a count per vertex fits below the most scratch.
  const size_t most_scratch = topology_scratch_bytes(in);
  uint32_t* side_start =
      b.by_vertex() && b.drawn.by_vertex != nullptr && size_t(hi - index_end) > most_scratch
          ? room_for<uint32_t>(index_end, hi - most_scratch, size_t{in.n_vertices} + 1)
          : nullptr;
  b.n_side = side_start != nullptr
                 ? count_by_vertex(b, side_start, b.sides_before, sides_by_vertex(b))
                 : count_sides(b);
  ByteCounter scratch_size;
  count_scratch(scratch_size, in.n_edges, b.n_side);
  if (size_t(hi - lo) < scratch_size.total) return Status::kWorkspaceTooSmall;
  Carver scratch(hi - scratch_size.total, scratch_size.total - drawn_bytes);
  b.side = scratch.take<uint64_t>(b.n_side);
  b.nfaces = scratch.take<uint8_t>(size_t{in.n_edges} + b.n_side);
  if (side_start != nullptr) {  // the drawn keys' index stays where it is, below the counts
    store_by_vertex(b, side_start, b.sides_before, b.side, sides_by_vertex(b), u64_less);
  } else {
    index_drawn(lo, hi - scratch_size.total, in.n_vertices, &b.drawn);
    sort_sides(b);
  }
  const uint32_t n_diagonals = count_diagonals(b);
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
  number_edges(b);
  index_end = index_drawn(carve.next, hi - scratch_size.total, in.n_vertices, &b.drawn);
  if (b.by_vertex()) {  // the diagonals' own index, so the parts' lookups stay near one vertex's
                        // keys
    const SolidEdge* diagonals = t.edges + t.n_drawn;
    b.diagonal_by_vertex =
        index_by_vertex(index_end, hi - scratch_size.total, in.n_vertices, n_diagonals,
                        [&](uint32_t i) { return diagonals[i].v0; });
  }
  attach_faces(b);
  if (options.stars) build_stars(in, t, b.parts);
  *out = t;
  return Status::kOk;
}

}  // namespace haloplot
