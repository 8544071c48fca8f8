#include "pipeline/solid_pipeline.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <ctime>
#include <system_error>
#include <thread>
#include <unordered_map>
#include <utility>

#include "pipeline/host_memory.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace haloplot::host {
namespace {

// The pieces' first pages faulted in on another thread while the stage's first steps run
// (the topology's build, on one thread): the kernel's zeroing of them cost most of the
// pieces' emission (some 50 ms of 80 on the 1M-triangle torus), which the sink, called from
// one thread, could not share. Only pages a piece will be written to: one a drawn edge (each
// edge seen at all gives a piece or more), never past the capacity reserved. Nothing where
// the system has no such advice (before Linux 5.14 the call fails and changes nothing).
struct Prefault {
  std::thread thread;
  void start(void* begin, size_t bytes) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    const uintptr_t page = 4096, b = reinterpret_cast<uintptr_t>(begin);
    const uintptr_t lo = (b + page - 1) & ~(page - 1), hi = (b + bytes) & ~(page - 1);
    if (hi <= lo) return;
    try {
      thread = std::thread(
          [lo, hi] { madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_POPULATE_WRITE); });
    } catch (const std::system_error&) {  // no thread: the sink faults them in as before
    }
#else
    (void)begin;
    (void)bytes;
#endif
  }
  void join() {
    if (thread.joinable()) thread.join();
  }
  ~Prefault() { join(); }
};

// The pieces as they come. The geometry of an edge beyond the drawn ones (a diagonal, a line
// on the faces) is kept aside with its index; SolidRun::edges is filled once the stage's
// buffer is given back (a drawn edge's geometry is the scene's), so the two never take
// memory at the same time.
struct Collect {
  SolidRun* run;
  std::vector<std::pair<uint32_t, Edge3>> others;
  Prefault* prefault = nullptr;
  void keep(const HiddenPiece& p) {
    if (p.edge >= run->n_drawn) others.push_back({p.edge, *p.geometry});
  }
};

SolidPiece solid_piece(const HiddenPiece& p) {
  SolidPiece s{p.edge, p.q, p.t0, 0, p.hidden};
  s.t1 = p.t1 & 0x3fffffffffffffff;  // t1 <= 2^32: the mask (the field's width) drops nothing
  return s;
}

Status collect_piece(void* context, const HiddenPiece& p) {
  Collect* c = static_cast<Collect*>(context);
  c->keep(p);
  if (p.hatch) {
    c->run->hatch.push_back(solid_piece(p));
    c->run->hatch_faces.push_back(p.face[0]);
    return Status::kOk;
  }
  if (p.face[0] != kNoFace) {
    c->run->intersections.push_back(solid_piece(p));
    c->run->intersection_faces.push_back({p.face[0], p.face[1]});
    return Status::kOk;
  }
  (p.edge < c->run->n_drawn ? c->run->pieces : c->run->contour_diagonals).push_back(solid_piece(p));
  return Status::kOk;
}

void collect_begin(void* context, uint8_t*, size_t, const Edge3*) {
  Collect* c = static_cast<Collect*>(context);
  if (c->prefault != nullptr) c->prefault->join();  // its pages in before the first piece
}

Status collect_outline(void* context, const OutlinePiece& p) {
  Collect* c = static_cast<Collect*>(context);
  c->keep(p);
  c->run->outline.push_back(OutlineSegment{p.edge, p.t0, p.t1});
  return Status::kOk;
}

// The intersection lines in the order of their two faces, and numbered so. The core finds them
// cell by cell of its face grid, whose cells change with the faces' sizes (solid/face_grid.h)
// though the lines do not; two faces cross in one segment at most, so the pair names a line
// whatever grid found it. The lines keep the numbers they had among them, and each its
// pieces in their order.
void order_lines_by_faces(SolidRun* out, std::vector<std::pair<uint32_t, Edge3>>* others) {
  const size_t n = out->intersections.size();
  std::vector<size_t> order(n);
  for (size_t k = 0; k < n; ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [out](size_t a, size_t b) {
    return out->intersection_faces[a] < out->intersection_faces[b];
  });
  std::vector<uint32_t> numbers;
  for (const SolidPiece& p : out->intersections) numbers.push_back(p.edge);
  std::sort(numbers.begin(), numbers.end());
  numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
  std::unordered_map<uint32_t, uint32_t> renumbered;
  std::vector<SolidPiece> pieces;
  std::vector<std::array<uint32_t, 2>> faces;
  pieces.reserve(n);
  faces.reserve(n);
  for (size_t k : order) {
    const uint32_t found = out->intersections[k].edge;
    auto it = renumbered.find(found);
    if (it == renumbered.end()) it = renumbered.emplace(found, numbers[renumbered.size()]).first;
    pieces.push_back(out->intersections[k]);
    pieces.back().edge = it->second;
    faces.push_back(out->intersection_faces[k]);
  }
  out->intersections.swap(pieces);
  out->intersection_faces.swap(faces);
  for (std::pair<uint32_t, Edge3>& o : *others) {
    const auto it = renumbered.find(o.first);
    if (it != renumbered.end()) o.first = it->second;
  }
}

std::string reason_text(const HiddenReport& r) {
  switch (r.reason) {
    case FallbackReason::kNone:
      return "";
    case FallbackReason::kAsked:
      return "asked for";
    case FallbackReason::kBand:
      return "a band of a banded plot (the topology-free method is local to the band)";
    case FallbackReason::kConflicts:
      return "parts meet where faces touch or overlap exactly, and there the quick method "
             "(walking visibility from vertex to vertex) got two answers at " +
             std::to_string(r.qi.conflicts) +
             " vertices; the drawing is as exact, made the slower way";
  }
  return "";
}

}  // namespace

bool model_closed(const SolidScene& scene) {
  const SolidInput in = solid_input(scene);
  std::vector<uint64_t> buffer(topology_bytes(in) / 8 + 1);
  Topology topo;
  if (!ok(build_topology(in, buffer.data(), buffer.size() * 8, &topo))) return false;
  return topo.check.manifold();
}

SolidInput solid_input(const SolidScene& scene) {
  SolidInput in;
  in.vertices = scene.vertices.data();
  in.n_vertices = uint32_t(scene.vertices.size());
  in.edge_pairs = scene.edge_pairs.data();
  in.n_edges = uint32_t(scene.edge_pairs.size() / 2);
  in.triangles = scene.triangles.data();
  in.n_triangles = uint32_t(scene.triangles.size());
  if (scene.facing.size() == scene.triangles.size() && !scene.facing.empty())
    in.facing = scene.facing.data();
  return in;
}

Status run_hidden_lines(const SolidScene& scene, HiddenMethod method, FallbackParams kira,
                        SolidRun* out, bool outlines, bool intersections, const HatchParams* hatch,
                        const Parts* parts, uint32_t qi_part_vertices) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  *out = SolidRun{};
  const SolidInput in = solid_input(scene);
  HiddenParams params;
  params.method = method;
  params.outline = outlines;
  params.intersections = intersections;
  params.hatch = hatch != nullptr;
  if (hatch != nullptr) params.hatch_params = *hatch;
  params.kira = kira.use_classes || kira.use_vc;
  params.cut.parts = parts;
  params.qi_part_vertices = qi_part_vertices;
  // The sink keeps nothing in the stage's tail. 4 MB: a round of the QI emission's parts keeps
  // some 170,000 pieces; the lines' parts keep far fewer.
  params.end_parts_bytes = size_t{4} << 20;
  // First guesses; the core says what a short run needs (never a wrong or partial answer).
  StageNeeds needs;
  needs.crossings = 4 * (in.n_edges + 3 * in.n_triangles) + 1024;
  needs.incidences = in.n_vertices + 64;
  HiddenReport r;
  Prefault prefault;
  Collect c{out, {}, &prefault};
  HiddenLinesStage stage{&in, params,
                         HiddenSink{&collect_begin, &collect_piece, &collect_outline, &c}, &r,
                         hidden_lines_first_bytes(in)};
  auto restart = restarting(&stage, [out, &in] {
    out->pieces.clear();
    out->contour_diagonals.clear();
    out->outline.clear();
    out->intersections.clear();
    out->intersection_faces.clear();
    out->hatch.clear();
    out->hatch_faces.clear();
    out->n_drawn = in.n_edges;
  });
  out->pieces.reserve(2 * size_t{in.n_edges});  // a piece or two a drawn edge
  if (parts != nullptr && parts->split() > 1)
    prefault.start(out->pieces.data(), size_t{in.n_edges} * sizeof(SolidPiece));
  HostMemory memory;
  const Status s = run_sized(restart, memory.memory(), &needs);
  prefault.join();
  memory.words = ZeroedWords();  // the stage's buffer back before the edges take theirs
  order_lines_by_faces(out, &c.others);
  out->check = r.check;
  out->classes = r.classes;
  out->cut = r.cut;
  out->qi = r.qi;
  out->fallback = r.fallback;
  out->outline_stats = r.outline;
  out->intersection_stats = r.intersections;
  out->hatch_stats = r.hatch;
  for (uint32_t f : out->hatch_faces) out->hatch_polygons.push_back(scene.triangles[f].polygon);
  out->incidences = r.incidences;
  out->coincident_vertices = r.coincident_vertices;
  out->used_qi = r.used_qi;
  out->fallback_reason = reason_text(r);
  out->bytes_topology = r.bytes_topology;
  out->bytes_incidence = r.bytes_incidence;
  out->bytes_cut = r.bytes_cut;
  out->bytes_qi = r.bytes_qi;
  out->bytes_fallback = r.bytes_fallback;
  out->bytes_outline = r.bytes_outline;
  out->bytes_intersections = r.bytes_intersections;
  // Every drawn edge's geometry, also for edges that gave no piece (seen end-on), and those of
  // the other edges that gave pieces (the rest stay zero).
  uint32_t n_geometry = in.n_edges;
  for (const auto& o : c.others) n_geometry = std::max(n_geometry, o.first + 1);
  out->edges.assign(n_geometry, Edge3{});
  for (const auto& o : c.others) out->edges[o.first] = o.second;
  for (uint32_t e = 0; e < in.n_edges; ++e)
    out->edges[e] =
        Edge3{scene.vertices[scene.edge_pairs[2 * e]], scene.vertices[scene.edge_pairs[2 * e + 1]]};
  out->ms_total =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  out->cpu_ms_total = double(std::clock() - c0) * 1000 / CLOCKS_PER_SEC;
  return s;
}

}  // namespace haloplot::host
