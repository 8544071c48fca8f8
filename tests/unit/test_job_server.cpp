// The job protocol end to end on the host: the host client (host_sim/link) talks to the
// controller's JobServer (core/protocol) through an in-process loopback. Checked against
// independent references: the plot's trace equals the host simulator's for the same job;
// damaged and truncated frames are NAKed and the job still plots identically; a lost ACK
// does not store a chunk twice; a re-plot runs DRAW only and equals the simulator with the
// new width; each bad request gets its named error and leaves the stored job intact; an
// indexed scene projected on the controller lands within 1/2 + 2^-9 steps of long double; a
// scene with Bézier edges, drawn by the controller's curve job, plots the strokes of the host's
// curve drawing (pipeline/curve_pipeline.h, which runs the curve stages without the job).
#include <algorithm>
#include <cmath>
#include <deque>
#include <sstream>

#include "../check.h"
#include "../support/solid_scenes.h"
#include "../support/virtual_motion.h"
#include "demo/curve_scenes.h"
#include "haloplot/scene/cube_array.h"
#include "link/job_client.h"
#include "pipeline/curve_pipeline.h"
#include "pipeline/drawing_modes.h"
#include "pipeline/surface_pipeline.h"
#include "sim/simulator.h"
#include "support/must.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

struct Controller {
  std::vector<uint8_t> arena, rx = std::vector<uint8_t>(JobServer::kMaxPayload + kFrameOverhead);
  std::deque<uint8_t> replies;
  test::VirtualMotion motion;
  JobServer server;
  // `offset`: the arena starts that many bytes into the vector (an integrator's buffer off an
  // 8-byte boundary).
  explicit Controller(size_t arena_bytes, size_t offset = 0)
      : arena(arena_bytes + offset),
        server(arena.data() + offset, arena_bytes, rx.data(), rx.size(),
               ByteOutput{this,
                          [](void* c, const uint8_t* b, uint32_t n) {
                            static_cast<Controller*>(c)->replies.insert(
                                static_cast<Controller*>(c)->replies.end(), b, b + n);
                          }},
               motion.port()) {}
};

struct Loopback : Transport {
  Controller& c;
  explicit Loopback(Controller& ctl) : c(ctl) {}
  bool write(const uint8_t* b, size_t n) override {
    for (size_t i = 0; i < n; ++i) c.server.push(b[i]);
    return true;
  }
  size_t read(uint8_t* out, size_t cap, int) override {
    c.server.service();
    if (c.replies.empty()) c.server.idle();  // the line is quiet: the idle timeout fires
    size_t n = 0;
    while (n < cap && !c.replies.empty()) out[n++] = c.replies.front(), c.replies.pop_front();
    return n;
  }
};

JobSpec demo_spec(int32_t halo) {
  JobSpec spec;
  spec.drawing = DrawingEffect::kHaloed;
  spec.draw = DrawParams{halo, HaloMode::kPaper};
  spec.machine.kinematics = Kinematics::kCoreXY;
  return spec;
}

std::vector<Edge3> cubes(int n) {
  CubeArrayParams p;
  p.cubes = n;
  std::vector<Edge3> e(cube_array_edges(p));
  must(cube_array(p, e.data(), uint32_t(e.size())));
  return e;
}

std::string simulated(const JobSpec& spec, const std::vector<Edge3>& edges) {
  std::ostringstream out;
  SimReport r;
  JobSpec s = spec;
  if (!s.effects.backlash) s.machine.backlash[0] = s.machine.backlash[1] = 0;
  const Status st = simulate(s, edges, &out, &r);
  CHECK_MSG(ok(st), std::string("simulate: ") + status_name(st));
  return out.str();
}

// Upload, plot, wait: the status of each step.
Status plot_job(JobClient& client, const JobSpec& spec, const std::vector<Edge3>& edges) {
  Status s;
  if (!client.sync() || !client.upload(spec, edges, &s)) return Status::kBadParameter;
  if (!ok(s)) return s;
  if (!client.request(FrameType::kPlot, {}, &s)) return Status::kBadParameter;
  StatusReport r;
  if (ok(s) && !client.wait_idle(&r, 0)) return Status::kBadParameter;
  return s;
}

void clean_plot_and_replot() {
  Controller c(1 << 20);
  Loopback link(c);
  JobClient client(link);
  const auto edges = cubes(4);
  const JobSpec spec = demo_spec(50);
  CHECK(ok(plot_job(client, spec, edges)));
  CHECK_EQ(c.motion.traces.size(), size_t{1});
  CHECK(!c.motion.traces.empty() && c.motion.traces[0] == simulated(spec, edges));
  StatusReport r;
  CHECK(client.query(&r));
  CHECK_EQ(r.cut_runs, 1u);
  CHECK_EQ(r.draw_runs, 1u);
  CHECK_EQ(r.edges, uint32_t(edges.size()));
  CHECK(r.crossings > 0);
  // Re-plot with a new halo width: DRAW again, CUT not; the trace equals a fresh simulation.
  std::vector<uint8_t> halo(kHaloBytes);
  encode_halo(DrawParams{120, HaloMode::kPaper}, halo.data());
  Status s;
  CHECK(client.request(FrameType::kReplot, halo, &s) && ok(s));
  CHECK(client.wait_idle(&r, 0));
  CHECK_EQ(r.cut_runs, 1u);
  CHECK_EQ(r.draw_runs, 2u);
  CHECK(c.motion.traces.size() == 2 && c.motion.traces[1] == simulated(demo_spec(120), edges));
  CHECK(c.motion.traces.size() == 2 && c.motion.traces[1] != c.motion.traces[0]);
}

// The arena at offsets 1 to 7 from an 8-byte boundary: the server uses it from the next
// boundary on (the stages it calls refuse misaligned buffers), so the plot and re-plot are the
// simulator's, as with an aligned arena.
void misaligned_arena() {
  const auto edges = cubes(2);
  const std::string want = simulated(demo_spec(50), edges);
  const std::string want_replot = simulated(demo_spec(120), edges);
  for (size_t offset = 1; offset <= 7; ++offset) {
    Controller c(1 << 16, offset);
    Loopback link(c);
    JobClient client(link);
    const Status s = plot_job(client, demo_spec(50), edges);
    CHECK_MSG(ok(s), "offset " + std::to_string(offset) + ": " + status_name(s));
    CHECK(c.motion.traces.size() == 1 && c.motion.traces[0] == want);
    std::vector<uint8_t> halo(kHaloBytes);
    encode_halo(DrawParams{120, HaloMode::kPaper}, halo.data());
    Status r;
    StatusReport report;
    CHECK(client.request(FrameType::kReplot, halo, &r) && ok(r) && client.wait_idle(&report, 0));
    CHECK(c.motion.traces.size() == 2 && c.motion.traces[1] == want_replot);
  }
}

void damaged_frames() {
  const auto edges = cubes(4);
  const JobSpec spec = demo_spec(50);
  const std::string want = simulated(spec, edges);
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    Controller c(1 << 20);
    Loopback link(c);
    FaultPlan faults;
    faults.corrupt_every = 2;
    faults.truncate_every = 3;
    faults.seed = seed;
    JobClient client(link, faults);
    CHECK(ok(plot_job(client, spec, edges)));
    const LinkStats& st = client.stats();
    CHECK(st.corrupted > 0 && st.truncated > 0);
    // Every damaged transmission was answered with a NAK (or, when the damage hit the start
    // byte's length so the frame waits for bytes, by the idle timeout's NAK): one resend each.
    CHECK_EQ(st.resends, st.corrupted + st.truncated);
    CHECK_EQ(st.naks, st.corrupted + st.truncated);
    CHECK(c.motion.traces.size() == 1 && c.motion.traces[0] == want);
    StatusReport r;
    CHECK(client.query(&r));
    CHECK_EQ(r.bad_frames, st.naks);
  }
}

// A lost ACK: the client resends a chunk the controller already stored; it must not be
// stored twice (the upload would then overflow its declared count).
void lost_ack() {
  Controller c(1 << 20);
  Loopback link(c);
  JobClient client(link);
  const auto edges = cubes(2);
  Status s;
  CHECK(client.sync() && client.upload(demo_spec(50), edges, &s) && ok(s));
  // Replay the last chunk's frame as the client would after losing the reply.
  std::vector<uint8_t> rec(kEdgeRecordBytes);
  encode_edge(edges.back(), rec.data());
  std::vector<uint8_t> frame(rec.size() + kFrameOverhead);
  // The client's last seq was used by the final chunk: resend a frame with that seq.
  StatusReport before;
  CHECK(client.query(&before));
  const uint8_t last_seq = uint8_t(before.seq - 1);
  frame.resize(encode_frame(uint8_t(FrameType::kUploadEdges), last_seq, rec.data(),
                            uint16_t(rec.size()), frame.data(), frame.size()));
  c.replies.clear();
  link.write(frame.data(), frame.size());
  CHECK(!c.replies.empty());  // answered again (the query's reply, repeated)
  CHECK(c.server.state() == ServerState::kReady);
  CHECK_EQ(c.server.edges(), uint32_t(edges.size()));
}

void errors_leave_job_intact() {
  const auto edges = cubes(3);
  const JobSpec spec = demo_spec(50);
  const std::string want = simulated(spec, edges);
  Controller c(48 * 1024);
  Loopback link(c);
  JobClient client(link);
  Status s;
  CHECK(client.sync());
  // Plot and re-plot before any scene.
  CHECK(client.request(FrameType::kPlot, {}, &s) && s == Status::kNoScene);
  std::vector<uint8_t> halo(kHaloBytes);
  encode_halo(DrawParams{80, HaloMode::kPaper}, halo.data());
  CHECK(client.request(FrameType::kReplot, halo, &s) && s == Status::kNoCutset);
  CHECK(ok(plot_job(client, spec, edges)));
  // A scene far too large for the arena: refused before a byte is stored.
  std::vector<uint8_t> begin(kUploadBeginBytes);
  encode_upload_begin(UploadBegin{SceneFormat::kEdges, 0, 100000, 0}, begin.data());
  CHECK(client.request(FrameType::kUploadBegin, begin, &s) && s == Status::kSceneTooLarge);
  // Malformed payloads and out-of-range parameters.
  CHECK(client.request(FrameType::kSetHalo, {1, 2, 3}, &s) && s == Status::kMalformedRequest);
  std::vector<uint8_t> fx = {uint8_t(DrawingEffect::kHatch) + 1, 0};
  CHECK(client.request(FrameType::kSetEffects, fx, &s) && s == Status::kMalformedRequest);
  JobSpec fast = spec;
  fast.machine.draw_speed = 1000000;
  std::vector<uint8_t> m(kMachineBytes);
  encode_machine(fast, m.data());
  CHECK(client.request(FrameType::kSetMachine, m, &s) && !ok(s));
  // Faces come only with the indexed format, and only inside an upload.
  encode_upload_begin(UploadBegin{SceneFormat::kEdges, 0, 12, 6}, begin.data());
  CHECK(client.request(FrameType::kUploadBegin, begin, &s) && s == Status::kMalformedRequest);
  CHECK(client.request(FrameType::kUploadFaces, std::vector<uint8_t>(16), &s) &&
        s == Status::kUploadMismatch);
  {
    // A method beyond fallback, and a hatch spacing of 0, are refused.
    std::vector<uint8_t> hidden(kHiddenBytes);
    encode_hidden(HiddenJob{}, hidden.data());
    hidden[0] = 3;
    CHECK(client.request(FrameType::kSetHidden, hidden, &s) && s == Status::kMalformedRequest);
    HiddenJob zero;
    zero.hatch = true;
    zero.hatch_spacing = 0;
    encode_hidden(zero, hidden.data());
    CHECK(client.request(FrameType::kSetHidden, hidden, &s) && s == Status::kMalformedRequest);
  }
  CHECK(client.request(FrameType::kUploadEdges, std::vector<uint8_t>(24), &s) &&
        s == Status::kUploadMismatch);
  StatusReport r;
  CHECK(client.query(&r));
  CHECK(r.last_error == Status::kUploadMismatch);
  // None of that touched the stored job: it plots as before.
  CHECK(client.request(FrameType::kPlot, {}, &s) && ok(s));
  CHECK(client.wait_idle(&r, 0));
  CHECK(c.motion.traces.size() == 2 && c.motion.traces[1] == want);
  // A scene that fits the arena but whose CUT does not: a named error, not a crash.
  Controller small(12 * 1024);
  Loopback small_link(small);
  JobClient small_client(small_link);
  const Status too_big = plot_job(small_client, spec, cubes(4));
  CHECK(too_big == Status::kWorkspaceTooSmall || too_big == Status::kSceneTooLarge);
}

void busy_and_abort() {
  Controller c(1 << 20);
  c.motion.busy_polls = 1000;
  Loopback link(c);
  JobClient client(link);
  const auto edges = cubes(2);
  Status s;
  CHECK(client.sync() && client.upload(demo_spec(50), edges, &s) && ok(s));
  CHECK(client.request(FrameType::kPlot, {}, &s) && ok(s));
  CHECK(c.server.state() == ServerState::kPlotting);
  std::vector<uint8_t> begin(kUploadBeginBytes);
  encode_upload_begin(UploadBegin{SceneFormat::kEdges, 0, 1, 0}, begin.data());
  CHECK(client.request(FrameType::kUploadBegin, begin, &s) && s == Status::kBusy);
  CHECK(client.request(FrameType::kAbort, {}, &s) && ok(s));
  CHECK(c.motion.aborted);
  StatusReport r;
  CHECK(client.wait_idle(&r, 0));
  CHECK(r.state == ServerState::kReady);
  CHECK(r.last_error == Status::kAborted);
}

// World cubes as vertices and index pairs, projected on the controller; all-edges drawing so
// the plotted spans are the projected edges themselves.
void indexed_scene() {
  std::vector<Point3> world;
  std::vector<uint32_t> pairs;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 8; ++k)
      world.push_back(Point3{i * 1500 + (k & 1) * 1000, ((k >> 1) & 1) * 1000, (k >> 2) * 1000});
  for (uint32_t i = 0; i < 3; ++i)
    for (uint32_t a = 0; a < 8; ++a)
      for (uint32_t bit = 1; bit < 8; bit <<= 1)
        if (!(a & bit)) pairs.insert(pairs.end(), {8 * i + a, 8 * i + (a | bit)});
  Controller c(1 << 20);
  Loopback link(c);
  JobClient client(link);
  JobSpec spec = demo_spec(0);
  spec.drawing = DrawingEffect::kAllEdges;
  View view;
  view.azimuth_mdeg = 25500;
  view.elevation_mdeg = 35250;
  Status s;
  CHECK(client.sync() && client.upload_indexed(spec, view, world, pairs, &s) && ok(s));
  CHECK(client.request(FrameType::kPlot, {}, &s) && ok(s));
  CHECK_EQ(c.motion.spans.size(), size_t{1});
  if (c.motion.spans.size() != 1) return;
  // Reference projection in long double, fitted the README's way.
  const long double pi = 3.141592653589793238462643383279502884L;
  const long double az = 25.5L * pi / 180, el = 35.25L * pi / 180;
  std::vector<long double> xs, ys;
  for (const Point3& p : world) {
    const long double y1 = p.x * std::sin(az) + p.y * std::cos(az);
    xs.push_back(p.x * std::cos(az) - p.y * std::sin(az));
    ys.push_back(p.z * std::cos(el) + y1 * std::sin(el));
  }
  const long double xl = *std::min_element(xs.begin(), xs.end()),
                    xh = *std::max_element(xs.begin(), xs.end());
  const long double yl = *std::min_element(ys.begin(), ys.end()),
                    yh = *std::max_element(ys.begin(), ys.end());
  const long double scale = std::min(view.width / (xh - xl), view.height / (yh - yl));
  long double worst = 0;
  size_t matched = 0;
  for (size_t e = 0; e < pairs.size() / 2; ++e) {
    const uint32_t a = pairs[2 * e], b = pairs[2 * e + 1];
    const long double ax = view.margin + (xs[a] - xl) * scale,
                      ay = view.margin + (ys[a] - yl) * scale;
    const long double bx = view.margin + (xs[b] - xl) * scale,
                      by = view.margin + (ys[b] - yl) * scale;
    for (const Segment2& g : c.motion.spans[0]) {
      const long double d1 = std::max(
          {std::fabs(g.x0 - ax), std::fabs(g.y0 - ay), std::fabs(g.x1 - bx), std::fabs(g.y1 - by)});
      const long double d2 = std::max(
          {std::fabs(g.x0 - bx), std::fabs(g.y0 - by), std::fabs(g.x1 - ax), std::fabs(g.y1 - ay)});
      const long double d = std::min(d1, d2);
      if (d <= 0.5L + 1.0L / 512) {
        ++matched;
        worst = std::max(worst, d);
        break;
      }
    }
  }
  CHECK_EQ(matched, pairs.size() / 2);
  // A new view forgets the CUT of the old one (re-plot must refuse until the next plot).
  std::vector<uint8_t> v(kViewBytes);
  encode_view(view, v.data());
  CHECK(client.request(FrameType::kSetView, v, &s) && ok(s));
  std::vector<uint8_t> halo(kHaloBytes);
  encode_halo(DrawParams{50, HaloMode::kPaper}, halo.data());
  CHECK(client.request(FrameType::kReplot, halo, &s) && s == Status::kNoCutset);
  // A vertex index beyond the vertices is refused at plot time by name.
  pairs[5] = 999;
  CHECK(client.upload_indexed(spec, view, world, pairs, &s) && ok(s));
  CHECK(client.request(FrameType::kPlot, {}, &s) && s == Status::kBadParameter);
}

// A solid over the link: world vertices, edge pairs and triangles, hidden lines worked out on
// the controller. It must draw exactly the strokes the host tool draws for the same model and
// view (the same core, reached through the protocol), dashes and outline pass included.
void solid_scene() {
  solid_scenes::Mesh m;
  solid_scenes::box(&m, 0, 0, 0, 2000, 2000, 2000);
  solid_scenes::box(&m, 1000, -3000, 1000, 3000, -1000, 3000);
  const std::vector<uint32_t> pairs = solid_scenes::polygon_edges(m);
  const std::vector<Triangle> tris = host::triangulate(m.v, m.faces, nullptr);
  View view;
  view.azimuth_mdeg = 30000;
  view.elevation_mdeg = 25000;
  for (DrawingEffect drawing : {DrawingEffect::kHiddenRemoved, DrawingEffect::kHiddenDashed}) {
    Controller c(1 << 20);
    Loopback link(c);
    JobClient client(link);
    JobSpec spec = demo_spec(0);
    spec.drawing = drawing;
    spec.hidden.outline = true;
    spec.hidden.dash = 120;
    spec.hidden.gap = 60;
    // The dashed drawing also hatched (the hidden-line run's hatch lines on the controller).
    const bool hatch = drawing == DrawingEffect::kHiddenDashed;
    spec.hidden.hatch = hatch;
    spec.hidden.hatch_spacing = 150;
    spec.hidden.hatch_angle_mdeg = 30000;
    spec.hidden.hatch_mdeg_per_depth = 90000;
    Status s;
    // Without faces the controller says what is missing.
    CHECK(client.sync() && client.upload_indexed(spec, view, m.v, pairs, &s) && ok(s));
    CHECK(client.request(FrameType::kPlot, {}, &s) && s == Status::kNoFaces);
    CHECK(client.upload_indexed(spec, view, m.v, pairs, &s, &tris) && ok(s));
    CHECK(client.request(FrameType::kPlot, {}, &s) && ok(s));
    StatusReport r;
    CHECK(client.wait_idle(&r, 0) && r.last_error == Status::kOk);
    CHECK_EQ(c.motion.spans.size(), size_t{1});
    if (c.motion.spans.size() != 1) return;
    // The host tool's strokes for the same model and view.
    host::SolidScene scene;
    scene.vertices.resize(m.v.size());
    CHECK(project_points(view, m.v.data(), uint32_t(m.v.size()), scene.vertices.data()) ==
          Status::kOk);
    scene.edge_pairs = pairs;
    scene.triangles = tris;
    host::SolidRun run;
    FallbackParams kira;
    kira.use_classes = kira.use_vc = true;
    HatchParams hp;
    hp.spacing = 150;
    hp.angle_mdeg = 30000;
    hp.mdeg_per_depth = 90000;
    CHECK(host::run_hidden_lines(scene, HiddenMethod::kAuto, kira, &run, true, false,
                                 hatch ? &hp : nullptr) == Status::kOk);
    host::ModeSpec ms;
    ms.mode = drawing == DrawingEffect::kHiddenDashed ? SolidMode::kHiddenDashed
                                                      : SolidMode::kHiddenRemoved;
    ms.dash_steps = 120;
    ms.gap_steps = 60;
    ms.outline = true;
    const host::ModeDrawing d = host::make_mode_drawing(run, ms);
    // Layer by layer (visible, hidden dashes, intersections, hatching, outlines), each in the
    // host's order: the controller groups its strokes by the hidden-line run's piece flags,
    // the host by its drawing's kinds.
    std::vector<Segment2> want;
    int kinds = 0;
    for (const std::vector<Span>& layer : host::layer_spans(d)) {
      kinds += !layer.empty();
      for (const Span& x : layer) want.push_back(Segment2{x.x0, x.y0, x.x1, x.y1});
    }
    CHECK(kinds >= (hatch ? 4 : 2));  // not vacuous: more than one layer to order
    const size_t hatched = d.hatch.size();
    if (hatch) CHECK(hatched > 20);  // not vacuous: the cubes' visible faces are hatched
    const std::vector<Segment2>& got = c.motion.spans[0];
    CHECK_EQ(got.size(), want.size());
    bool same = got.size() == want.size();
    for (size_t i = 0; same && i < got.size(); ++i)
      same = got[i].x0 == want[i].x0 && got[i].y0 == want[i].y0 && got[i].x1 == want[i].x1 &&
             got[i].y1 == want[i].y1;
    CHECK_MSG(same, "the controller's strokes equal the host tool's");
    CHECK(want.size() > 18);  // not vacuous: edges, dashes and the outline pass
    // The controller's plot is `sim`'s of the host's strokes drawn whole, layer by layer.
    JobSpec whole = spec;
    whole.drawing = DrawingEffect::kAllEdges;
    const std::vector<Edge3> strokes = host::mode_strokes(d, &whole.layers);
    CHECK_MSG(c.motion.traces.size() == 1 && c.motion.traces[0] == simulated(whole, strokes),
              "the controller's trace is sim's of the same strokes, layer by layer");
  }
}

// The demo trefoil (24 Bézier edges, 3 crossings) and a straight edge across it, uploaded as
// curves and edges into a controller's 96 KB arena: the controller finds the crossings, draws
// the halos and plots; its trace must be the plot of the chords the host's curve drawing
// makes with the same settings (host_curve_draw, no job code), drawn whole. Then the refusals:
// a curve record of the wrong length, curves in the indexed format, the exact halo, an arena
// too small for the crossing search.
void curve_scene() {
  CurveView view;
  view.size = 15200;
  view.margin = 400;
  host::CurveScene knot = trefoil_knot(24, view);
  const std::vector<Edge3> segments = {Edge3{{1000, 7000, 20000}, {14000, 8000, 20000}}};
  JobSpec spec = demo_spec(80);
  CurveCrossParams cp;
  CurveDrawParams dp;
  curve_job_params(spec, &cp, &dp);
  HostCurveDraw d;
  CHECK(ok(host_curve_draw(knot.curves, segments, cp, dp, &d)));
  std::vector<Edge3> chords;
  for (const Span& c : d.chords) chords.push_back(Edge3{{c.x0, c.y0, 0}, {c.x1, c.y1, 0}});
  JobSpec whole = spec;
  whole.drawing = DrawingEffect::kAllEdges;
  const std::string want = simulated(whole, chords);
  // The knot's 3 crossings and the segment's over it, as the host drawing counts them: the
  // controller must report as many.
  const uint32_t crossings = d.cross_stats.crossings;
  CHECK(crossings > 3);
  Controller c(96 * 1024);
  Loopback link(c);
  JobClient client(link);
  Status s;
  CHECK(client.sync() && client.upload(spec, segments, &s, &knot.curves) && ok(s));
  CHECK(client.request(FrameType::kPlot, {}, &s));
  CHECK_MSG(ok(s), std::string("curve plot: ") + status_name(s));
  StatusReport r;
  CHECK(client.wait_idle(&r, 0));
  CHECK_EQ(r.edges, 25u);
  CHECK_EQ(r.crossings, crossings);
  CHECK_MSG(c.motion.traces.size() == 1 && c.motion.traces[0] == want,
            "the controller's curve plot is the host curve drawing's chords, plotted whole");
  // sim of the same job (the curve job on the host) is that trace too.
  std::ostringstream sim_trace;
  SimReport sr;
  CHECK(ok(simulate(spec, segments, &sim_trace, &sr, 0, TraceForm::kText, {}, 0, &knot.curves)));
  CHECK(sim_trace.str() == want);
  // A curve record cut short; the indexed format with curves; the exact halo.
  std::vector<uint8_t> begin(kUploadBeginCurvesBytes);
  UploadBegin b{SceneFormat::kEdges, 0, 0, 0};
  b.curves = 2;
  encode_upload_begin_curves(b, begin.data());
  CHECK(client.request(FrameType::kUploadBegin, begin, &s) && ok(s));
  CHECK(client.request(FrameType::kUploadCurves, std::vector<uint8_t>(kCurveRecordBytes + 1), &s));
  CHECK_MSG(s == Status::kUploadMismatch,
            std::string("expected kUploadMismatch, got ") + status_name(s));
  b.format = SceneFormat::kIndexed;
  b.vertices = 3;
  encode_upload_begin_curves(b, begin.data());
  CHECK(client.request(FrameType::kUploadBegin, begin, &s));
  CHECK_MSG(s == Status::kMalformedRequest,
            std::string("expected kMalformedRequest, got ") + status_name(s));
  JobSpec exact = spec;
  exact.draw.mode = HaloMode::kExact;
  CHECK(client.upload(exact, segments, &s, &knot.curves) && ok(s));
  CHECK(client.request(FrameType::kPlot, {}, &s));
  CHECK_MSG(s == Status::kUnsupported, std::string("expected kUnsupported, got ") + status_name(s));
  // In bands (kUploadBegin's 21-byte form): the trace of sim of the job with that arena, which
  // is not the unbanded plot's; the form without curves, or with too small an arena, refused.
  const uint32_t band_arena = 24576;
  std::ostringstream banded_trace;
  SimReport br;
  CHECK(ok(simulate(spec, segments, &banded_trace, &br, band_arena, TraceForm::kText, {}, 0,
                    &knot.curves)));
  CHECK(br.bands.bands >= 2);
  CHECK(banded_trace.str() != want);
  CHECK(client.upload(spec, segments, &s, &knot.curves, band_arena) && ok(s));
  CHECK(client.request(FrameType::kPlot, {}, &s) && ok(s));
  CHECK(client.wait_idle(&r, 0));
  CHECK_MSG(c.motion.traces.size() == 2 && c.motion.traces[1] == banded_trace.str(),
            "the controller's curve plot in bands is sim's of the job with that arena");
  std::vector<uint8_t> bands_begin(kUploadBeginBandsBytes);
  UploadBegin bb{SceneFormat::kEdges, 0, 1, 0};
  bb.band_arena = band_arena;  // no curves
  encode_upload_begin_bands(bb, bands_begin.data());
  CHECK(client.request(FrameType::kUploadBegin, bands_begin, &s) && s == Status::kMalformedRequest);
  bb.curves = 2;
  bb.band_arena = kMinBandArena - 1;
  encode_upload_begin_bands(bb, bands_begin.data());
  CHECK(client.request(FrameType::kUploadBegin, bands_begin, &s) && s == Status::kMalformedRequest);
  // 8 KB: the scene fits (1,176 bytes), the crossing search does not; named, no plot.
  Controller small(8 * 1024);
  Loopback small_link(small);
  JobClient small_client(small_link);
  CHECK(small_client.sync() && small_client.upload(spec, segments, &s, &knot.curves) && ok(s));
  CHECK(small_client.request(FrameType::kPlot, {}, &s));
  CHECK_MSG(s == Status::kWorkspaceTooSmall,
            std::string("expected kWorkspaceTooSmall, got ") + status_name(s));
  CHECK(small.motion.traces.empty());
}

}  // namespace

int main() {
  clean_plot_and_replot();
  misaligned_arena();
  damaged_frames();
  lost_ack();
  errors_leave_job_intact();
  busy_and_abort();
  indexed_scene();
  solid_scene();
  curve_scene();
  return check::finish("job_server");
}
