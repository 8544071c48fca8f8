#include "haloplot/protocol/job_server.h"

#include "haloplot/geometry/units.h"
#include "haloplot/view/facing.h"
#include "memory/carve.h"

namespace haloplot {
namespace {

// Scene bytes at the front of the arena, by format (see the layout in job_server.h).
size_t world_bytes(const UploadBegin& s) {
  return carve_round(size_t{s.vertices} * sizeof(Point3));
}
size_t pair_bytes(const UploadBegin& s) {
  return carve_round(size_t{s.edges} * 2 * sizeof(uint32_t));
}
size_t edge_bytes(const UploadBegin& s) { return carve_round(size_t{s.edges} * sizeof(Edge3)); }
size_t curve_bytes(const UploadBegin& s) {
  return carve_round(size_t{s.curves} * sizeof(BezierEdge3));
}
size_t face_bytes(const UploadBegin& s) { return carve_round(size_t{s.faces} * sizeof(Triangle)); }

bool hidden_line_drawing(DrawingEffect d) {
  return d == DrawingEffect::kHiddenRemoved || d == DrawingEffect::kHiddenDashed;
}

}  // namespace

JobServer::JobServer(uint8_t* arena, size_t arena_bytes, uint8_t* rx_buffer, size_t rx_bytes,
                     ByteOutput out, MotionPort motion)
    : decoder_(rx_buffer, rx_bytes, kMaxPayload), out_(out), motion_(motion) {
  // A constructor has no status to return: the server uses its arena from the first
  // kBufferAlignment boundary on (the scene and job layouts need it), losing up to 7 bytes.
  const uintptr_t p = reinterpret_cast<uintptr_t>(arena);
  const size_t lost =
      size_t((kBufferAlignment - (p & (kBufferAlignment - 1))) & (kBufferAlignment - 1));
  arena_ = arena == nullptr || arena_bytes < lost ? nullptr : arena + lost;
  arena_bytes_ = arena_ == nullptr ? 0 : arena_bytes - lost;
}

size_t JobServer::job_offset() const {
  // The indexed format keeps the world vertices and the pairs (a new view re-projects them)
  // in front of the projected edges; the edges format its curves.
  const size_t front = scene_.format == SceneFormat::kIndexed
                           ? world_bytes(scene_) + pair_bytes(scene_) + face_bytes(scene_)
                           : curve_bytes(scene_);
  return front + edge_bytes(scene_);
}

void JobServer::push(uint8_t byte) {
  on_event(decoder_.push(byte));
  for (FrameDecoder::Event ev = decoder_.poll(); ev != FrameDecoder::Event::kNone;
       ev = decoder_.poll())
    on_event(ev);
}

void JobServer::idle() {
  for (FrameDecoder::Event ev = decoder_.idle(); ev != FrameDecoder::Event::kNone;
       ev = decoder_.poll())
    on_event(ev);
}

void JobServer::on_event(FrameDecoder::Event ev) {
  if (ev == FrameDecoder::Event::kFrame) {
    on_frame(decoder_.frame());
  } else if (ev == FrameDecoder::Event::kBadFrame) {
    const uint8_t expected = expected_seq_;
    reply(FrameType::kNak, &expected, 1);
  }
}

void JobServer::on_frame(const Frame& f) {
  if (f.type == uint8_t(FrameType::kSync)) {
    expected_seq_ = f.seq;  // accepted below as the expected frame
  } else if (f.seq == uint8_t(expected_seq_ - 1) && last_reply_bytes_ > 0) {
    // The sender did not hear our reply and sent the frame again: answer again, act once.
    out_.write(out_.ctx, last_reply_, last_reply_bytes_);
    return;
  } else if (f.seq != expected_seq_) {
    const uint8_t expected = expected_seq_;
    reply(FrameType::kNak, &expected, 1);
    return;
  }
  ++expected_seq_;
  if (f.type == uint8_t(FrameType::kQueryStatus)) {
    send_status(f.seq);
  } else {
    const Status s = act(f);
    // A band offered while the last one is still staged is flow control, not a failure.
    const bool flow = s == Status::kBusy && f.type == uint8_t(FrameType::kBandBegin);
    if (!ok(s) && !flow) last_error_ = s;
    const uint8_t ack[2] = {f.seq, uint8_t(s)};
    reply(FrameType::kAck, ack, 2);
  }
  // Only replies to in-sequence frames are repeated for a duplicate; a NAK never is.
}

Status JobServer::act(const Frame& f) {
  const FrameType type = FrameType(f.type);
  if (type == FrameType::kSync) return Status::kOk;
  if (type == FrameType::kAbort) {
    if (state_ == ServerState::kPlotting) motion_.abort(motion_.ctx);
    return Status::kOk;
  }
  if (type == FrameType::kPause || type == FrameType::kResume) {
    if (f.length != 0) return Status::kMalformedRequest;
    if (motion_.pause == nullptr) return Status::kUnsupported;
    if (state_ != ServerState::kPlotting) return Status::kNotPlotting;
    (type == FrameType::kPause ? motion_.pause : motion_.resume)(motion_.ctx);
    return Status::kOk;
  }
  // Platform requests decide for themselves what a running plot allows.
  if (f.type >= kPlatformTypeFirst && extension_.handle)
    return extension_.handle(extension_.ctx, f);
  // The bands of a streamed plot arrive while it plots.
  if (type == FrameType::kBandBegin) return band_begin(f.payload, f.length);
  if (type == FrameType::kBandEdges) return band_edges(f.payload, f.length);
  if (type == FrameType::kBandVertices || type == FrameType::kBandSolidEdges ||
      type == FrameType::kBandTriangles)
    return band_solid(type, f.payload, f.length);
  if (type == FrameType::kStreamEnd) {
    if (!streamed_ || f.length != 0 || staging_ == Staging::kReceiving)
      return Status::kUploadMismatch;
    stream_end_ = true;
    return Status::kOk;
  }
  if (state_ == ServerState::kPlotting) return Status::kBusy;
  switch (type) {
    case FrameType::kUploadBegin:
      return upload_begin(f.payload, f.length);
    case FrameType::kUploadEdges:
    case FrameType::kUploadCurves:
    case FrameType::kUploadVertices:
    case FrameType::kUploadEdgeIndices:
      return upload_records(type, f.payload, f.length);
    case FrameType::kUploadFaces:
      return upload_records(type, f.payload, f.length);
    case FrameType::kSetHidden:
      return decode_hidden(f.payload, f.length, &spec_.hidden);
    case FrameType::kSetView: {
      View v;
      Status s = decode_view(f.payload, f.length, &v);
      if (ok(s)) s = validate(v);
      if (!ok(s)) return s;
      view_ = v;
      if (scene_.format == SceneFormat::kIndexed) forget_cut();  // the projection changes
      return Status::kOk;
    }
    case FrameType::kSetHalo: {
      DrawParams d;
      const Status s = decode_halo(f.payload, f.length, &d);
      if (!ok(s)) return s;
      // The exact halo needs CUT's near misses out to the width: a wider one needs a new CUT.
      if (d.mode == HaloMode::kExact && d.halo > spec_.cut.reach) forget_cut();
      spec_.draw = d;
      if (d.mode == HaloMode::kExact)
        spec_.cut.reach = d.halo > spec_.cut.reach ? d.halo : spec_.cut.reach;
      return Status::kOk;
    }
    case FrameType::kSetEffects:
      return decode_effects(f.payload, f.length, &spec_);
    case FrameType::kSetMachine: {
      JobSpec next = spec_;
      Status s = decode_machine(f.payload, f.length, &next);
      if (ok(s)) s = validate(next.machine);
      if (ok(s)) spec_ = next;
      return s;
    }
    case FrameType::kStreamBegin:
      return stream_begin(f.payload, f.length);
    case FrameType::kPlot:
      // Empty, or u32: go on with an earlier plot of this job that stopped after that many
      // step events (an abort, a reset: motion/virtual_run.h skip_events).
      if (f.length != 0 && f.length != 4) return Status::kMalformedRequest;
      resume_events_ = f.length == 4 ? get_u32(f.payload) : 0;
      if (resume_events_ > 0 && streamed_) return Status::kUnsupported;
      return streamed_ ? plot_streamed() : plot();
    case FrameType::kReplot:
      return replot(f.payload, f.length);
    default:
      return Status::kMalformedRequest;
  }
}

Status JobServer::upload_begin(const uint8_t* p, uint16_t n) {
  UploadBegin b;
  const Status s = decode_upload_begin(p, n, &b);
  if (!ok(s)) return s;
  if (b.faces > 0 && b.format != SceneFormat::kIndexed) return Status::kMalformedRequest;
  // 64-bit sums: a hostile count cannot wrap the check.
  const uint64_t need = (b.format == SceneFormat::kIndexed
                             ? uint64_t{b.vertices} * sizeof(Point3) + uint64_t{b.edges} * 8 +
                                   uint64_t{b.faces} * sizeof(Triangle) + 24
                             : 0) +
                        uint64_t{b.edges} * sizeof(Edge3) + 8 +
                        uint64_t{b.curves} * sizeof(BezierEdge3) + 8;
  if (need > arena_bytes_) return Status::kSceneTooLarge;
  scene_ = b;
  streamed_ = false;
  received_vertices_ = received_edges_ = received_faces_ = received_curves_ = 0;
  n_edges_ = n_curves_ = 0;
  forget_cut();
  state_ = b.edges == 0 && b.curves == 0 ? ServerState::kIdle : ServerState::kUploading;
  return Status::kOk;
}

Status JobServer::upload_records(FrameType type, const uint8_t* p, uint16_t n) {
  if (state_ != ServerState::kUploading) return Status::kUploadMismatch;
  const bool indexed = scene_.format == SceneFormat::kIndexed;
  if (type == FrameType::kUploadCurves) {
    if (indexed || n % kCurveRecordBytes) return Status::kUploadMismatch;
    const uint32_t k = uint32_t(n / kCurveRecordBytes);
    if (k > scene_.curves - received_curves_) return Status::kUploadMismatch;
    BezierEdge3* curves = reinterpret_cast<BezierEdge3*>(arena_);
    for (uint32_t i = 0; i < k; ++i)
      curves[received_curves_ + i] = decode_curve(p + i * kCurveRecordBytes);
    received_curves_ += k;
  } else if (type == FrameType::kUploadVertices) {
    if (!indexed || n % kVertexRecordBytes) return Status::kUploadMismatch;
    const uint32_t k = uint32_t(n / kVertexRecordBytes);
    if (k > scene_.vertices - received_vertices_) return Status::kUploadMismatch;
    Point3* world = reinterpret_cast<Point3*>(arena_);
    for (uint32_t i = 0; i < k; ++i)
      world[received_vertices_ + i] = decode_vertex(p + i * kVertexRecordBytes);
    received_vertices_ += k;
  } else if (type == FrameType::kUploadFaces) {
    if (!indexed || n % kFaceRecordBytes) return Status::kUploadMismatch;
    const uint32_t k = uint32_t(n / kFaceRecordBytes);
    if (k > scene_.faces - received_faces_) return Status::kUploadMismatch;
    Triangle* faces =
        reinterpret_cast<Triangle*>(arena_ + world_bytes(scene_) + pair_bytes(scene_));
    for (uint32_t i = 0; i < k; ++i)
      faces[received_faces_ + i] = decode_face(p + i * kFaceRecordBytes);
    received_faces_ += k;
  } else {
    const size_t size = type == FrameType::kUploadEdges ? kEdgeRecordBytes : kIndexRecordBytes;
    if (indexed != (type == FrameType::kUploadEdgeIndices) || n % size)
      return Status::kUploadMismatch;
    const uint32_t k = uint32_t(n / size);
    if (k > scene_.edges - received_edges_) return Status::kUploadMismatch;
    if (indexed) {
      uint32_t* pairs = reinterpret_cast<uint32_t*>(arena_ + world_bytes(scene_));
      for (uint32_t i = 0; i < 2 * k; ++i) pairs[2 * received_edges_ + i] = get_u32(p + 4 * i);
    } else {
      Edge3* edges = reinterpret_cast<Edge3*>(arena_ + curve_bytes(scene_));
      for (uint32_t i = 0; i < k; ++i) edges[received_edges_ + i] = decode_edge(p + i * size);
    }
    received_edges_ += k;
  }
  if (received_edges_ == scene_.edges && received_vertices_ == scene_.vertices &&
      received_faces_ == scene_.faces && received_curves_ == scene_.curves) {
    n_edges_ = scene_.edges;
    n_curves_ = scene_.curves;
    state_ = ServerState::kReady;
  }
  return Status::kOk;
}

Status JobServer::plot() {
  if (state_ != ServerState::kReady) return Status::kNoScene;
  uint8_t* job_mem = arena_ + job_offset();
  const size_t job_bytes = arena_bytes_ - job_offset();
  Edge3* edges = reinterpret_cast<Edge3*>(arena_ + job_offset() - edge_bytes(scene_));
  if (scene_.format == SceneFormat::kIndexed) {
    // Project into the (still free) job buffer, then expand the pairs into edges.
    if (size_t{scene_.vertices} * sizeof(Point3) > job_bytes) return Status::kWorkspaceTooSmall;
    Point3* screen = reinterpret_cast<Point3*>(job_mem);
    View view = view_;
    view.substep_bits = spec_.substep_bits;  // the job's units (kSetEffects)
    Status s =
        project_points(view, reinterpret_cast<const Point3*>(arena_), scene_.vertices, screen);
    if (ok(s))
      s = edges_from_indices(screen, scene_.vertices,
                             reinterpret_cast<const uint32_t*>(arena_ + world_bytes(scene_)),
                             n_edges_, edges);
    if (!ok(s)) return s;
  }
  forget_cut();
  if (hidden_line_drawing(spec_.drawing)) return plot_hidden(job_mem, job_bytes);
  if (n_curves_ > 0) return plot_curves(edges, job_mem, job_bytes);
  // The crossing count is unknown before CUT: start from a guess and run again with the
  // exact count CUT reports (it never stores a partial CUTSET).
  StageNeeds needs;
  needs.crossings = n_edges_ + 64;
  const uint64_t t0 = clock_ ? clock_() : 0;
  EdgeJobStage stage{&spec_, Edges{edges, n_edges_}, &job_, &counters_, nullptr};
  FixedMemory memory{job_mem, job_bytes};
  const Status s = run_sized(stage, memory.memory(), &needs);
  crossing_capacity_ = needs.crossings;
  cut_runs_ += stage.cut_runs;
  draw_runs_ += stage.draw_runs;
  if (clock_) prepare_ticks_ = clock_() - t0;
  if (!ok(s)) return s;
  has_cut_ = spec_.drawing == DrawingEffect::kHaloed;
  return start_motion();
}

// A scene with curves: the curve stages in the job buffer (job_prepare_curves), haloed with the
// paper's gap only.
Status JobServer::plot_curves(const Edge3* edges, uint8_t* job_mem, size_t job_bytes) {
  if (spec_.drawing != DrawingEffect::kHaloed || spec_.draw.mode != HaloMode::kPaper)
    return Status::kUnsupported;
  if (scene_.band_arena > 0) return plot_curve_bands(edges, job_mem, job_bytes);
  // The hit count is unknown before the search: guess, then run again with the count it
  // reports (it never stores a partial answer).
  StageNeeds needs;
  needs.crossings = 64;
  const uint64_t t0 = clock_ ? clock_() : 0;
  CurveJobStage stage{
      &spec_,
      CurveJobScene{reinterpret_cast<const BezierEdge3*>(arena_), n_curves_, edges, n_edges_},
      &job_, &counters_};
  FixedMemory memory{job_mem, job_bytes};
  const Status s = run_sized(stage, memory.memory(), &needs);
  cut_runs_ += stage.cut_runs;
  draw_runs_ += stage.draw_runs;
  if (clock_) prepare_ticks_ = clock_() - t0;
  if (!ok(s)) return s;
  has_cut_ = true;  // the hits stay at the job buffer's front for a re-plot
  return start_motion();
}

// The curve job in bands of the arena the host asked for (kUploadBegin's 21-byte form), as
// `sim` of the job with that arena plots it: band by band while the pen moves. No hits are
// kept for a re-plot (each band's are gone with it).
Status JobServer::plot_curve_bands(const Edge3* edges, uint8_t* job_mem, size_t job_bytes) {
  if (scene_.band_arena > job_bytes) return Status::kWorkspaceTooSmall;
  CurveBandSpec spec;
  Status s = curve_band_spec(spec_, &spec);
  if (ok(s))
    s = curve_bands_.begin(spec, reinterpret_cast<const BezierEdge3*>(arena_), n_curves_, edges,
                           n_edges_, job_mem, scene_.band_arena & ~uint32_t{7});
  if (!ok(s)) return s;
  job_ = PreparedJob{};
  job_.feed = PointFeed{&CurveBands::feed, &curve_bands_};
  return start_motion();
}

Status JobServer::plot_hidden(uint8_t* job_mem, size_t job_bytes) {
  if (scene_.format != SceneFormat::kIndexed || scene_.faces == 0) return Status::kNoFaces;
  // The projected vertices stay at the front of the job buffer (plot() put them there), then
  // in sub-step units each face's facing from the model (view/facing.h, as the host does); the
  // hidden-line run and its strokes take the rest.
  const size_t screen_bytes = carve_round(size_t{scene_.vertices} * sizeof(Point3));
  const size_t facing_bytes = spec_.substep_bits > 0 ? carve_round(scene_.faces) : 0;
  if (screen_bytes + facing_bytes > job_bytes) return Status::kWorkspaceTooSmall;
  SolidInput in;
  in.vertices = reinterpret_cast<const Point3*>(job_mem);
  in.n_vertices = scene_.vertices;
  in.edge_pairs = reinterpret_cast<const uint32_t*>(arena_ + world_bytes(scene_));
  in.n_edges = n_edges_;
  in.triangles =
      reinterpret_cast<const Triangle*>(arena_ + world_bytes(scene_) + pair_bytes(scene_));
  in.n_triangles = scene_.faces;
  if (facing_bytes > 0) {
    uint8_t* facing = job_mem + screen_bytes;
    const Status fs = model_facing(view_, reinterpret_cast<const Point3*>(arena_), scene_.vertices,
                                   in.triangles, in.n_triangles, facing);
    if (!ok(fs)) return fs;
    in.facing = facing;
  }
  // Capacities are unknown before the run: guess, then run again with the counts it reports.
  StageNeeds needs;
  needs.crossings = n_edges_ + 3 * scene_.faces + 64;
  needs.incidences = scene_.vertices + 16;
  const uint64_t t0 = clock_ ? clock_() : 0;
  HiddenReport report;
  SolidJobStage stage{&spec_, &in, &job_, &counters_, &report};
  FixedMemory memory{job_mem + screen_bytes + facing_bytes,
                     job_bytes - screen_bytes - facing_bytes};
  const Status s = run_sized(stage, memory.memory(), &needs);
  cut_runs_ += stage.cut_runs;
  if (clock_) prepare_ticks_ = clock_() - t0;
  if (!ok(s)) return s;
  return start_motion();
}

Status JobServer::replot(const uint8_t* p, uint16_t n) {
  DrawParams d;
  Status s = decode_halo(p, n, &d);
  if (!ok(s)) return s;
  if (!has_cut_ || spec_.drawing != DrawingEffect::kHaloed) return Status::kNoCutset;
  if (d.mode == HaloMode::kExact &&
      steps_to_units(d.halo, spec_.substep_bits) > job_.cutset.reach)  // the CUTSET's units
    return Status::kNoCutset;
  JobSpec next = spec_;
  next.draw = d;
  const uint64_t t0 = clock_ ? clock_() : 0;
  if (n_curves_ > 0) {  // DRAW and the path again on the hits the plot left
    const CurveCrossStats& cc = counters_.curve_cross;
    s = job_redraw_curves(
        next,
        CurveJobScene{reinterpret_cast<const BezierEdge3*>(arena_), n_curves_,
                      reinterpret_cast<const Edge3*>(arena_ + job_offset() - edge_bytes(scene_)),
                      n_edges_},
        2 * (cc.crossings + cc.touches), arena_ + job_offset(), arena_bytes_ - job_offset(), &job_,
        &counters_);
  } else {
    s = job_redraw(next, Edges{job_.cutset.edges, n_edges_}, crossing_capacity_,
                   arena_ + job_offset(), arena_bytes_ - job_offset(), &job_, &counters_);
  }
  if (clock_) redraw_ticks_ = clock_() - t0;
  draw_runs_ += counters_.draw_runs;
  if (!ok(s)) return s;
  spec_.draw = d;
  return start_motion();
}

Status JobServer::start_motion() {
  job_.resume_after_events = resume_events_;  // this plot only: a re-plot starts at the start
  resume_events_ = 0;
  JobSpec run = spec_;
  if (!run.effects.backlash) run.machine.backlash[0] = run.machine.backlash[1] = 0;
  const Status s = motion_.begin(motion_.ctx, run, job_);
  if (ok(s)) {
    state_ = ServerState::kPlotting;
    last_error_ = Status::kOk;  // from here on, last_error tells how this plot went
  }
  return s;
}

void JobServer::service() {
  if (state_ != ServerState::kPlotting || motion_.running(motion_.ctx)) return;
  const Status s = motion_.result(motion_.ctx);
  if (!ok(s)) last_error_ = s;
  state_ = ServerState::kReady;
  if (streamed_) {  // the bands are gone with the plot: another stream or upload comes next
    cut_runs_ += uint32_t(conductor_.stats().cut_runs);
    draw_runs_ += uint32_t(conductor_.stats().draw_runs);
    streamed_ = false;
    state_ = ServerState::kIdle;
  }
}

// kStreamBegin: the conductor takes the arena's front, the staging buffer the rest.
Status JobServer::stream_begin(const uint8_t* p, uint16_t n) {
  StreamBegin b;
  const Status s = decode_stream_begin(p, n, &b);
  if (!ok(s)) return s;
  const size_t arena = carve_round(b.arena_bytes);
  if (arena + kBandEdgeRecordBytes > arena_bytes_ || b.arena_bytes < 1024)
    return Status::kSceneTooLarge;
  stream_ = b;
  streamed_ = true;
  stream_end_ = false;
  staging_ = Staging::kEmpty;
  staging_capacity_ = uint32_t((arena_bytes_ - arena) / (sizeof(Edge3) + sizeof(uint32_t)));
  staged_edges_ = reinterpret_cast<Edge3*>(arena_ + arena);
  staged_ids_ = reinterpret_cast<uint32_t*>(staged_edges_ + staging_capacity_);
  stage_base_ = arena_ + arena;
  stage_bytes_ = arena_bytes_ - arena;
  scene_ = UploadBegin{};
  n_edges_ = 0;
  forget_cut();
  state_ = ServerState::kReady;
  return Status::kOk;
}

Status JobServer::band_begin(const uint8_t* p, uint16_t n) {
  if (!streamed_ || stream_end_) return Status::kUploadMismatch;
  if (staging_ != Staging::kEmpty) return Status::kBusy;  // the plot has not taken the last one
  BandBegin b;
  const Status s = decode_band_begin(p, n, &b);
  if (!ok(s)) return s;
  staged_vertices_ = staged_triangles_ = 0;
  if (!solid_stream()) {
    if (b.vertices != 0 || b.triangles != 0) return Status::kMalformedRequest;
    if (b.edges > staging_capacity_) return Status::kSceneTooLarge;
  } else {
    // [vertex ids | vertices | edge ids | vertex pairs | triangles], each 8-byte aligned.
    const uint64_t need = carve_round(uint64_t{b.vertices} * 4) +
                          carve_round(uint64_t{b.vertices} * sizeof(Point3)) +
                          carve_round(uint64_t{b.edges} * 4) + carve_round(uint64_t{b.edges} * 8) +
                          uint64_t{b.triangles} * sizeof(Triangle);
    if (need > stage_bytes_) return Status::kSceneTooLarge;
    Carver c(stage_base_, stage_bytes_);
    staged_vertex_ids_ = c.take<uint32_t>(b.vertices);
    staged_points_ = c.take<Point3>(b.vertices);
    staged_ids_ = c.take<uint32_t>(b.edges);
    staged_pairs_ = c.take<uint32_t>(size_t{b.edges} * 2);
    staged_faces_ = c.take<Triangle>(b.triangles);
  }
  staged_ = b;
  staged_received_ = 0;
  staging_ = Staging::kReceiving;
  check_staged();
  return Status::kOk;
}

// The staged band is whole once every record it announced has come.
void JobServer::check_staged() {
  if (staged_received_ == staged_.edges && staged_vertices_ == staged_.vertices &&
      staged_triangles_ == staged_.triangles)
    staging_ = Staging::kReady;
}

// A solid's band records, in their order: vertices (ascending scene indices), edges, triangles.
Status JobServer::band_solid(FrameType type, const uint8_t* p, uint16_t n) {
  if (!streamed_ || !solid_stream() || staging_ != Staging::kReceiving)
    return Status::kUploadMismatch;
  if (type == FrameType::kBandVertices) {
    if (n % kBandVertexRecordBytes || staged_received_ > 0 || staged_triangles_ > 0)
      return Status::kUploadMismatch;
    const uint32_t k = uint32_t(n / kBandVertexRecordBytes);
    if (k > staged_.vertices - staged_vertices_) return Status::kUploadMismatch;
    for (uint32_t i = 0; i < k; ++i, ++staged_vertices_) {
      const uint8_t* r = p + size_t{i} * kBandVertexRecordBytes;
      const uint32_t id = get_u32(r);
      if (staged_vertices_ > 0 && id <= staged_vertex_ids_[staged_vertices_ - 1])
        return Status::kMalformedRequest;
      staged_vertex_ids_[staged_vertices_] = id;
      staged_points_[staged_vertices_] = decode_vertex(r + 4);
      if (!in_range(staged_points_[staged_vertices_])) return Status::kCoordinateOutOfRange;
    }
  } else if (type == FrameType::kBandSolidEdges) {
    if (n % kBandSolidEdgeRecordBytes || staged_vertices_ != staged_.vertices ||
        staged_triangles_ > 0)
      return Status::kUploadMismatch;
    const uint32_t k = uint32_t(n / kBandSolidEdgeRecordBytes);
    if (k > staged_.edges - staged_received_) return Status::kUploadMismatch;
    for (uint32_t i = 0; i < k; ++i, ++staged_received_) {
      const uint8_t* r = p + size_t{i} * kBandSolidEdgeRecordBytes;
      staged_ids_[staged_received_] = get_u32(r);
      staged_pairs_[2 * staged_received_] = get_u32(r + 4);
      staged_pairs_[2 * staged_received_ + 1] = get_u32(r + 8);
    }
  } else {
    if (n % kBandTriangleRecordBytes || staged_vertices_ != staged_.vertices ||
        staged_received_ != staged_.edges)
      return Status::kUploadMismatch;
    const uint32_t k = uint32_t(n / kBandTriangleRecordBytes);
    if (k > staged_.triangles - staged_triangles_) return Status::kUploadMismatch;
    for (uint32_t i = 0; i < k; ++i, ++staged_triangles_)
      staged_faces_[staged_triangles_] = decode_face(p + size_t{i} * kBandTriangleRecordBytes);
  }
  check_staged();
  return Status::kOk;
}

Status JobServer::band_edges(const uint8_t* p, uint16_t n) {
  if (!streamed_ || solid_stream() || staging_ != Staging::kReceiving || n % kBandEdgeRecordBytes)
    return Status::kUploadMismatch;
  const uint32_t k = uint32_t(n / kBandEdgeRecordBytes);
  if (k > staged_.edges - staged_received_) return Status::kUploadMismatch;
  for (uint32_t i = 0; i < k; ++i) {
    const uint8_t* r = p + size_t{i} * kBandEdgeRecordBytes;
    staged_ids_[staged_received_ + i] = get_u32(r);
    staged_edges_[staged_received_ + i] = decode_edge(r + 4);
    if (!in_range(staged_edges_[staged_received_ + i])) return Status::kCoordinateOutOfRange;
  }
  staged_received_ += k;
  if (staged_received_ == staged_.edges) staging_ = Staging::kReady;
  return Status::kOk;
}

// The conductor's stream: the staged band once it is whole, the end after kStreamEnd.
Status JobServer::next_band(void* ctx, StreamedBand* band, bool* end) {
  auto* self = static_cast<JobServer*>(ctx);
  *end = false;
  if (self->staging_ != Staging::kReady) {
    *end = self->stream_end_ && self->staging_ == Staging::kEmpty;
    return *end ? Status::kOk : Status::kBusy;
  }
  band->y0 = self->staged_.y0;
  band->y1 = self->staged_.y1;
  band->edges = self->staged_edges_;
  band->ids = self->staged_ids_;
  band->n = self->staged_.edges;
  if (self->solid_stream()) {
    self->staged_solid_ = StagedSolidBand{
        self->staged_vertex_ids_, self->staged_points_, self->staged_.vertices, self->staged_pairs_,
        self->staged_.edges,      self->staged_faces_,  self->staged_.triangles};
    band->edges = nullptr;
    band->solid = &self->staged_solid_;
  }
  return Status::kOk;
}

void JobServer::release_band(void* ctx) {
  static_cast<JobServer*>(ctx)->staging_ = Staging::kEmpty;
}

Status JobServer::plot_streamed() {
  const bool edges =
      spec_.drawing == DrawingEffect::kHaloed || spec_.drawing == DrawingEffect::kAllEdges;
  const bool lines = spec_.drawing == DrawingEffect::kHiddenRemoved ||
                     spec_.drawing == DrawingEffect::kHiddenDashed;
  if (!(edges && !solid_stream()) && !(lines && solid_stream())) return Status::kUnsupported;
  BandStream stream;
  stream.ctx = this;
  stream.next = &JobServer::next_band;
  stream.release = &JobServer::release_band;
  const uint32_t bytes = stream_.arena_bytes & ~uint32_t{7};
  const Status s =
      solid_stream()
          ? conductor_.begin_streamed_solid(
                band_spec(spec_),
                ((stream_.flags & kStreamClosed) != 0 ? SolidStreamFlags::kClosed
                                                      : SolidStreamFlags::kNone) |
                    ((stream_.flags & kStreamTurned) != 0 ? SolidStreamFlags::kTurned
                                                          : SolidStreamFlags::kNone),
                stream, arena_, bytes)
          : conductor_.begin_streamed(band_spec(spec_), stream_.margin, stream, arena_, bytes);
  if (!ok(s)) return s;
  job_ = PreparedJob{};
  job_.feed = PointFeed{&BandConductor::feed, &conductor_};
  return start_motion();
}

void JobServer::send_status(uint8_t seq) {
  StatusReport r;
  r.seq = seq;
  r.state = state_;
  if (state_ == ServerState::kPlotting && motion_.paused && motion_.paused(motion_.ctx))
    r.state = ServerState::kPaused;
  r.last_error = last_error_;
  r.free_bytes = uint32_t(arena_bytes_ - job_offset());
  r.edges = n_edges_ + n_curves_;
  r.crossings = has_cut_ ? job_.cutset.n_crossings : 0;
  if (n_curves_ > 0) r.crossings = counters_.curve_cross.crossings;  // of its last plot
  r.cut_runs = cut_runs_;
  r.draw_runs = draw_runs_;
  r.step_events = motion_.step_events(motion_.ctx);
  r.bad_frames = decoder_.bad_frames();
  uint8_t payload[kStatusBytes];
  encode_status(r, payload);
  reply(FrameType::kStatus, payload, kStatusBytes);
}

void JobServer::reply(FrameType type, const uint8_t* payload, uint16_t n) {
  uint8_t frame[sizeof last_reply_];
  const size_t bytes = encode_frame(uint8_t(type), payload[0], payload, n, frame, sizeof frame);
  out_.write(out_.ctx, frame, uint32_t(bytes));
  if (type != FrameType::kNak) {
    for (size_t i = 0; i < bytes; ++i) last_reply_[i] = frame[i];
    last_reply_bytes_ = uint16_t(bytes);
  }
}

}  // namespace haloplot
