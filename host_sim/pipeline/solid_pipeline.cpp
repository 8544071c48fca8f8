#include "pipeline/solid_pipeline.h"

#include <chrono>

#include "solid/incidence.h"
#include "solid/topology.h"

namespace haloplot::host {
namespace {

Status collect_qi(void* context, const QiPiece& p) {
  SolidRun* r = static_cast<SolidRun*>(context);
  (p.edge < r->n_drawn ? r->pieces : r->contour_diagonals)
      .push_back(SolidPiece{p.edge, p.t0, p.t1, p.q, p.q != 0});
  return Status::kOk;
}

Status collect_outline(void* context, const OutlineSegment& s) {
  static_cast<std::vector<OutlineSegment>*>(context)->push_back(s);
  return Status::kOk;
}

Status collect_fallback(void* context, const FallbackPiece& p) {
  static_cast<std::vector<SolidPiece>*>(context)->push_back(
      SolidPiece{p.edge, p.t0, p.t1, p.q, p.hidden});
  return Status::kOk;
}

std::string check_text(const MeshCheck& c) {
  std::string s;
  auto add = [&](uint32_t n, const char* what) {
    if (n == 0) return;
    if (!s.empty()) s += ", ";
    s += std::to_string(n) + " " + what;
  };
  add(c.boundary_edges, "boundary edges (open surface)");
  add(c.nonmanifold_edges, "edges on three or more faces");
  add(c.misoriented_edges, "edges whose faces disagree on orientation");
  return s;
}

}  // namespace

Status run_hidden_lines(const SolidScene& scene, HiddenMethod method, FallbackParams kira,
                        SolidRun* out, bool outlines) {
  const auto t0 = std::chrono::steady_clock::now();
  *out = SolidRun{};
  SolidInput in;
  in.vertices = scene.vertices.data();
  in.n_vertices = uint32_t(scene.vertices.size());
  in.edge_pairs = scene.edge_pairs.data();
  in.n_edges = uint32_t(scene.edge_pairs.size() / 2);
  in.triangles = scene.triangles.data();
  in.n_triangles = uint32_t(scene.triangles.size());

  out->bytes_topology = topology_bytes(in);
  std::vector<uint64_t> topo_buf(out->bytes_topology / 8 + 1);
  Topology topo;
  Status s = build_topology(in, topo_buf.data(), topo_buf.size() * 8, &topo);
  if (!ok(s)) return s;
  out->check = topo.check;
  std::vector<uint8_t> front(topo.n_triangles);
  out->classes = classify(&topo, front.data());

  std::vector<Edge3> all(topo.n_edges);
  for (uint32_t e = 0; e < topo.n_edges; ++e) all[e] = topo.edge3(e);
  out->edges = all;
  out->n_drawn = topo.n_drawn;
  HostCut cut;
  s = host_cut(all, CutParams{}, &cut);
  if (!ok(s)) return s;
  out->cut = cut.stats;
  out->bytes_cut = cut.scratch_bytes + cutset_bytes(cut.set.n_edges, cut.set.n_crossings);

  uint32_t capacity = topo.n_vertices + 64, needed = 0;
  std::vector<uint64_t> inc_buf;
  Incidences inc;
  for (int attempt = 0; attempt < 2; ++attempt) {
    out->bytes_incidence = incidence_bytes(topo, capacity);
    inc_buf.assign(out->bytes_incidence / 8 + 1, 0);
    s = find_incidences(topo, capacity, inc_buf.data(), inc_buf.size() * 8, &inc, &needed);
    if (s != Status::kIncidenceCapacity) break;
    capacity = needed;
  }
  if (!ok(s)) return s;
  out->incidences = inc.n;
  out->coincident_vertices = inc.coincident_vertices;

  const bool manifold = topo.check.manifold() && topo.check.loose_edges == 0;
  bool use_qi = method == HiddenMethod::kQi || (method == HiddenMethod::kAuto && manifold);
  if (method == HiddenMethod::kQi && !topo.check.manifold()) return Status::kNotManifold;
  if (use_qi) {
    out->bytes_qi = qi_bytes(topo);
    std::vector<uint64_t> qi_buf(out->bytes_qi / 8 + 1);
    QiState state;
    s = propagate_qi(topo, front.data(), cut.set, inc, qi_buf.data(), qi_buf.size() * 8, &state,
                     &out->qi);
    if (!ok(s)) return s;
    s = emit_qi_pieces(topo, front.data(), cut.set, inc, state, QiSink{&collect_qi, out});
    if (!ok(s)) return s;
    if (outlines) {
      out->bytes_outline = outline_bytes(topo, cut.set, inc);
      std::vector<uint64_t> ol_buf(out->bytes_outline / 8 + 1);
      s = find_outlines(topo, front.data(), cut.set, inc, state, ol_buf.data(), ol_buf.size() * 8,
                        OutlineSink{&collect_outline, &out->outline}, &out->outline_stats);
      if (!ok(s)) return s;
    }
    out->used_qi = true;
    if (method == HiddenMethod::kAuto && out->qi.conflicts > 0) {
      // Exact propagation only disagrees with itself on a mesh that pierces itself (or
      // another): the fallback asks the faces directly instead.
      out->fallback_reason = std::to_string(out->qi.conflicts) +
                             " vertices reached with two different QIs (does the mesh pierce "
                             "itself?)";
      out->used_qi = false;
      out->pieces.clear();
      out->contour_diagonals.clear();
      out->outline.clear();
      use_qi = false;
    }
  }
  if (!use_qi) {
    if (out->fallback_reason.empty())  // else the QI conflicts above say why
      out->fallback_reason = method != HiddenMethod::kAuto
                                 ? "asked for"
                                 : (topo.check.manifold() ? std::to_string(topo.check.loose_edges) +
                                                                " loose edges (lines on no face)"
                                                          : check_text(topo.check));
    FallbackParams p = kira;
    if (!topo.check.manifold()) {
      // Open or broken surfaces: both sides of a face show, and no class or V.C. holds.
      p.any_facing = true;
      p.use_classes = p.use_vc = false;
    }
    out->bytes_fallback = fallback_bytes(topo);
    std::vector<uint64_t> fb_buf(out->bytes_fallback / 8 + 1);
    s = run_fallback(topo, front.data(), cut.set, inc, p, fb_buf.data(), fb_buf.size() * 8,
                     FallbackSink{&collect_fallback, &out->pieces}, &out->fallback);
    if (!ok(s)) return s;
  }
  out->ms_total =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return Status::kOk;
}

}  // namespace haloplot::host
