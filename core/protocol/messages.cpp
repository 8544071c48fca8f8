#include "haloplot/protocol/messages.h"

#include "haloplot/geometry/contract.h"

namespace haloplot {

void encode_upload_begin(const UploadBegin& b, uint8_t out[kUploadBeginBytes]) {
  out[0] = uint8_t(b.format);
  put_u32(out + 1, b.vertices);
  put_u32(out + 5, b.edges);
  put_u32(out + 9, b.faces);
}

void encode_upload_begin_curves(const UploadBegin& b, uint8_t out[kUploadBeginCurvesBytes]) {
  encode_upload_begin(b, out);
  put_u32(out + kUploadBeginBytes, b.curves);
}

void encode_upload_begin_bands(const UploadBegin& b, uint8_t out[kUploadBeginBandsBytes]) {
  encode_upload_begin_curves(b, out);
  put_u32(out + kUploadBeginCurvesBytes, b.band_arena);
}

void encode_curve(const BezierEdge3& c, uint8_t out[kCurveRecordBytes]) {
  for (int i = 0; i < 4; ++i) encode_vertex(c.p[i], out + i * kVertexRecordBytes);
}

BezierEdge3 decode_curve(const uint8_t* p) {
  BezierEdge3 c;
  for (int i = 0; i < 4; ++i) c.p[i] = decode_vertex(p + i * kVertexRecordBytes);
  return c;
}

void encode_edge(const Edge3& e, uint8_t out[kEdgeRecordBytes]) {
  encode_vertex(e.a, out);
  encode_vertex(e.b, out + kVertexRecordBytes);
}

void encode_vertex(const Point3& p, uint8_t out[kVertexRecordBytes]) {
  put_i32(out, p.x);
  put_i32(out + 4, p.y);
  put_i32(out + 8, p.z);
}

void encode_view(const View& v, uint8_t out[kViewBytes]) {
  const int32_t f[6] = {v.azimuth_mdeg, v.elevation_mdeg, v.width,
                        v.height,       v.margin,         v.perspective};
  for (int i = 0; i < 6; ++i) put_i32(out + 4 * i, f[i]);
}

void encode_halo(const DrawParams& d, uint8_t out[kHaloBytes]) {
  put_u32(out, uint32_t(d.halo));
  out[4] = d.mode == HaloMode::kExact ? 1 : 0;
}

void encode_effects(const JobSpec& spec, uint8_t out[kEffectsBytes]) {
  const PlotterEffects& e = spec.effects;
  out[0] = uint8_t(spec.drawing);
  out[1] = uint8_t((e.acceleration ? 1 : 0) | (e.pen_servo ? 2 : 0) | (e.backlash ? 4 : 0) |
                   (spec.finish_home ? 0 : 8) | (spec.clean.on ? 0 : 16));
  out[2] = uint8_t(spec.substep_bits);
  put_u32(out + 3, spec.clean.min_stroke);
  put_u32(out + 7, spec.clean.simplify);
}

namespace {
// The machine's u32 fields in wire order.
template <typename M, typename U>
void machine_fields(M& m, U* (&f)[13]) {
  U* fields[13] = {&m.steps_num,          &m.steps_den,        &m.tick_hz,          &m.min_interval,
                   &m.max_step_rate,      &m.draw_speed,       &m.travel_speed,     &m.accel,
                   &m.junction_deviation, &m.pen_travel_ticks, &m.pen_settle_ticks, &m.backlash[0],
                   &m.backlash[1]};
  for (int i = 0; i < 13; ++i) f[i] = fields[i];
}
}  // namespace

void encode_machine(const JobSpec& spec, uint8_t out[kMachineBytes]) {
  out[0] = uint8_t(spec.machine.kinematics);
  const uint32_t* f[13];
  machine_fields(spec.machine, f);
  for (int i = 0; i < 13; ++i) put_u32(out + 1 + 4 * i, *f[i]);
  put_i32(out + 53, spec.start_x);
  put_i32(out + 57, spec.start_y);
}

void encode_status(const StatusReport& r, uint8_t out[kStatusBytes]) {
  out[0] = r.seq;
  out[1] = uint8_t(r.status);
  out[2] = uint8_t(r.state);
  out[3] = uint8_t(r.last_error);
  const uint32_t f[7] = {r.free_bytes, r.edges,       r.crossings, r.cut_runs,
                         r.draw_runs,  r.step_events, r.bad_frames};
  for (int i = 0; i < 7; ++i) put_u32(out + 4 + 4 * i, f[i]);
}

Status decode_upload_begin(const uint8_t* p, size_t n, UploadBegin* out) {
  if ((n != kUploadBeginBytes && n != kUploadBeginCurvesBytes && n != kUploadBeginBandsBytes) ||
      p[0] > uint8_t(SceneFormat::kIndexed))
    return Status::kMalformedRequest;
  out->format = SceneFormat(p[0]);
  out->vertices = get_u32(p + 1);
  out->edges = get_u32(p + 5);
  out->faces = get_u32(p + 9);
  out->curves = n >= kUploadBeginCurvesBytes ? get_u32(p + kUploadBeginBytes) : 0;
  out->band_arena = n == kUploadBeginBandsBytes ? get_u32(p + kUploadBeginCurvesBytes) : 0;
  // Bands are the curve job's: a scene with curves, in an arena a band can use.
  if (n == kUploadBeginBandsBytes && (out->curves == 0 || out->band_arena < kMinBandArena))
    return Status::kMalformedRequest;
  if (out->format == SceneFormat::kEdges && out->vertices != 0) return Status::kMalformedRequest;
  // Curves come with projected edges only: the indexed format's view projects vertices.
  if (out->format != SceneFormat::kEdges && out->curves != 0) return Status::kMalformedRequest;
  return Status::kOk;
}

Edge3 decode_edge(const uint8_t* p) {
  return Edge3{decode_vertex(p), decode_vertex(p + kVertexRecordBytes)};
}

Point3 decode_vertex(const uint8_t* p) {
  return Point3{get_i32(p), get_i32(p + 4), get_i32(p + 8)};
}

Status decode_view(const uint8_t* p, size_t n, View* out) {
  if (n != kViewBytes) return Status::kMalformedRequest;
  *out = View{get_i32(p),      get_i32(p + 4),  get_i32(p + 8),
              get_i32(p + 12), get_i32(p + 16), get_i32(p + 20)};
  return Status::kOk;
}

Status decode_halo(const uint8_t* p, size_t n, DrawParams* out) {
  if (n != kHaloBytes || p[4] > 1 || get_u32(p) > uint32_t(kCoordMax))
    return Status::kMalformedRequest;
  out->halo = int32_t(get_u32(p));
  out->mode = p[4] ? HaloMode::kExact : HaloMode::kPaper;
  return Status::kOk;
}

Status decode_effects(const uint8_t* p, size_t n, JobSpec* spec) {
  if ((n != kEffectsBytes && n != kEffectsNoSimplifyBytes && n != kEffectsShortBytes) ||
      p[0] > uint8_t(DrawingEffect::kHatch) || (p[1] & ~31u) || p[2] > kMaxSubstepBits)
    return Status::kMalformedRequest;
  spec->substep_bits = p[2];
  spec->drawing = DrawingEffect(p[0]);
  spec->effects.acceleration = p[1] & 1;
  spec->effects.pen_servo = p[1] & 2;
  spec->effects.backlash = p[1] & 4;
  spec->finish_home = (p[1] & 8) == 0;
  spec->clean.on = (p[1] & 16) == 0;
  spec->clean.min_stroke = n >= kEffectsNoSimplifyBytes ? get_u32(p + 3) : 0;
  spec->clean.simplify = n == kEffectsBytes ? get_u32(p + 7) : 0;
  return Status::kOk;
}

Status decode_machine(const uint8_t* p, size_t n, JobSpec* spec) {
  if (n != kMachineBytes || p[0] > uint8_t(Kinematics::kCoreXY)) return Status::kMalformedRequest;
  Machine m;
  m.kinematics = Kinematics(p[0]);
  uint32_t* f[13];
  machine_fields(m, f);
  for (int i = 0; i < 13; ++i) *f[i] = get_u32(p + 1 + 4 * i);
  // The pen's start is a plot position: inside the coordinate range like every vertex (the
  // path planner spans it together with the strokes).
  const int32_t x = get_i32(p + 53), y = get_i32(p + 57);
  if (x < 0 || x >= kCoordLimit || y < 0 || y >= kCoordLimit) return Status::kCoordinateOutOfRange;
  spec->machine = m;
  spec->start_x = x;
  spec->start_y = y;
  return Status::kOk;
}

Status decode_status(const uint8_t* p, size_t n, StatusReport* out) {
  if (n != kStatusBytes || p[2] > uint8_t(ServerState::kPaused)) return Status::kMalformedRequest;
  out->seq = p[0];
  out->status = Status(p[1]);
  out->state = ServerState(p[2]);
  out->last_error = Status(p[3]);
  uint32_t* f[7] = {&out->free_bytes, &out->edges,       &out->crossings, &out->cut_runs,
                    &out->draw_runs,  &out->step_events, &out->bad_frames};
  for (int i = 0; i < 7; ++i) *f[i] = get_u32(p + 4 + 4 * i);
  return Status::kOk;
}

void encode_face(const Triangle& t, uint8_t out[kFaceRecordBytes]) {
  for (int i = 0; i < 3; ++i) put_u32(out + 4 * i, t.v[i]);
  put_u32(out + 12, t.polygon);
}

Triangle decode_face(const uint8_t* p) {
  return Triangle{{get_u32(p), get_u32(p + 4), get_u32(p + 8)}, get_u32(p + 12)};
}

void encode_hidden(const HiddenJob& h, uint8_t out[kHiddenBytes]) {
  out[0] = uint8_t(h.method);
  out[1] = uint8_t((h.outline ? 1 : 0) | (h.hatch ? 2 : 0) | (h.intersections ? 4 : 0));
  put_i32(out + 2, h.dash);
  put_i32(out + 6, h.gap);
  put_i32(out + 10, h.hatch_spacing);
  put_i32(out + 14, h.hatch_angle_mdeg);
  put_i32(out + 18, h.hatch_mdeg_per_depth);
}

Status decode_hidden(const uint8_t* p, size_t n, HiddenJob* out) {
  if (n != kHiddenBytes || p[0] > uint8_t(HiddenMethod::kFallback) || (p[1] & ~7u))
    return Status::kMalformedRequest;
  HiddenJob h;
  h.method = HiddenMethod(p[0]);
  h.outline = p[1] & 1;
  h.hatch = (p[1] & 2) != 0;
  h.intersections = (p[1] & 4) != 0;
  h.dash = get_i32(p + 2);
  h.gap = get_i32(p + 6);
  h.hatch_spacing = get_i32(p + 10);
  h.hatch_angle_mdeg = get_i32(p + 14);
  h.hatch_mdeg_per_depth = get_i32(p + 18);
  if (h.dash < 1 || h.gap < 1 || h.dash > kCoordMax || h.gap > kCoordMax)
    return Status::kMalformedRequest;
  // Angles within a few turns keep the hatching's angle sum far from int32 overflow.
  if (h.hatch_spacing < 1 || h.hatch_spacing > kCoordMax || h.hatch_angle_mdeg < -3600000 ||
      h.hatch_angle_mdeg > 3600000 || h.hatch_mdeg_per_depth < -3600000 ||
      h.hatch_mdeg_per_depth > 3600000)
    return Status::kMalformedRequest;
  *out = h;
  return Status::kOk;
}

void encode_stream_begin(const StreamBegin& b, uint8_t out[kStreamBeginBytes]) {
  put_i32(out, b.margin);
  put_u32(out + 4, b.arena_bytes);
  out[8] = b.flags;
}

Status decode_stream_begin(const uint8_t* p, size_t n, StreamBegin* out) {
  if (n != kStreamBeginBytes || get_i32(p) < 0 || get_i32(p) > 2 * kCoordLimit ||
      (p[8] & ~(kStreamSolid | kStreamClosed | kStreamTurned)) != 0 ||
      ((p[8] & (kStreamClosed | kStreamTurned)) != 0 && (p[8] & kStreamSolid) == 0))
    return Status::kMalformedRequest;
  out->margin = get_i32(p);
  out->arena_bytes = get_u32(p + 4);
  out->flags = p[8];
  return Status::kOk;
}

void encode_band_begin(const BandBegin& b, uint8_t out[kBandBeginBytes]) {
  put_i32(out, b.y0);
  put_i32(out + 4, b.y1);
  put_u32(out + 8, b.edges);
  put_u32(out + 12, b.vertices);
  put_u32(out + 16, b.triangles);
}

Status decode_band_begin(const uint8_t* p, size_t n, BandBegin* out) {
  if (n != kBandBeginBytes) return Status::kMalformedRequest;
  const int32_t y0 = get_i32(p), y1 = get_i32(p + 4);
  if (y0 < 0 || y1 <= y0 || y1 > kCoordLimit) return Status::kMalformedRequest;
  out->y0 = y0;
  out->y1 = y1;
  out->edges = get_u32(p + 8);
  out->vertices = get_u32(p + 12);
  out->triangles = get_u32(p + 16);
  return Status::kOk;
}

}  // namespace haloplot
