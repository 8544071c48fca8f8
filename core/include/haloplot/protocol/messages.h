// Payload layouts of the job protocol (little-endian, packed, fixed length per type), with
// the encoders the host tool uses and the decoders the controller uses. One definition for
// both ends, so the two cannot drift apart.
//
//   kUploadBegin       u8 format (0 edges, 1 vertices + edge indices), u32 vertices,
//                      u32 edges, u32 faces                                      13 bytes
//                      or the same and u32 curves (format 0 only: a scene with cubic
//                      Bézier edges, drawn haloed by the curve stages)          17 bytes
//                      or the same and u32 band arena bytes (>= 1024: the curve job drawn
//                      in bands of that arena, band/curve_bands.h)              21 bytes
//   kUploadEdges       Edge3 records: 6 x i32 (x0 y0 z0 x1 y1 z1)            24 per edge
//   kUploadCurves      BezierEdge3 records: 4 control points of 3 x i32      48 per curve
//   kUploadVertices    world Point3: 3 x i32                                  12 per vertex
//   kUploadEdgeIndices 2 x u32 vertex indices                                  8 per edge
//   kSetView           i32 azimuth, elevation (millidegrees), width, height, margin,
//                      perspective distance (0: orthographic)                         24
//   kSetHalo           u32 width (steps), u8 mode (0 paper, 1 exact)                   5
//   kSetEffects        u8 drawing (DrawingEffect), u8 flags (1 acceleration, 2 pen servo,
//                      4 backlash, 8 stay), u8 sub-step bits (the scene's units)       3
//   kUploadFaces       4 x u32: three vertex indices (counter-clockwise from outside) and
//                      the polygon id (sides shared inside a polygon are not drawn) 16 per face
//   kSetHidden         u8 method (0 auto, 1 QI, 2 fallback), u8 flags (1 outline, 2 hatch,
//                      4 intersection lines), u32 dash, u32 gap, u32 hatch spacing (steps), i32
//                      hatch angle, i32 hatch turn across the depth range (millidegrees) 22
//   kSetMachine        u8 kinematics, 13 x u32 (steps num, den, tick Hz, min interval,
//                      max step rate, draw speed, travel speed, accel, junction deviation,
//                      pen travel, pen settle, backlash 0, 1), 2 x i32 start x, y      61
//   kPlot              (empty), or u32 step events: resume a plot stopped there          4
//   kReplot            as kSetHalo                                                      5
//   kStreamBegin       i32 margin (rows), u32 arena bytes for the bands, u8 flags (1 a
//                      solid's bands, 2 its model is closed)                               9
//   kBandBegin         i32 y0, i32 y1 (rows [y0, y1)), u32 edges, u32 vertices,
//                      u32 triangles (a solid's; 0 for edges)                              20
//   kBandEdges         u32 scene index, then an Edge3 record                       28 per edge
//   kBandVertices      u32 scene index (ascending), projected Point3             16 per vertex
//   kBandSolidEdges    u32 scene index, u32 v0, u32 v1 (scene vertex indices)   12 per edge
//   kBandTriangles     as kUploadFaces, scene vertex indices                  16 per triangle
//   kStreamEnd         (empty)
//   kPause, kResume    (empty)
//   kAck               u8 seq, u8 status                                                2
//   kNak               u8 expected seq                                                  1
//   kStatus            u8 seq, u8 status, u8 state, u8 last error, then u32 free bytes,
//                      edges, crossings, CUT runs, DRAW runs, step events, bad frames  32
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/curve/bezier.h"
#include "haloplot/job/job.h"
#include "haloplot/status/status.h"
#include "haloplot/view/projection.h"

namespace haloplot {

inline constexpr size_t kUploadBeginBytes = 13, kUploadBeginCurvesBytes = 17,
                        kUploadBeginBandsBytes = 21, kCurveRecordBytes = 48, kEdgeRecordBytes = 24,
                        kVertexRecordBytes = 12, kIndexRecordBytes = 8, kViewBytes = 24,
                        kHaloBytes = 5, kEffectsBytes = 11, kMachineBytes = 61, kStatusBytes = 32,
                        kFaceRecordBytes = 16, kHiddenBytes = 22, kStreamBeginBytes = 9,
                        kBandBeginBytes = 20, kBandEdgeRecordBytes = 4 + kEdgeRecordBytes,
                        kBandVertexRecordBytes = 16, kBandSolidEdgeRecordBytes = 12,
                        kBandTriangleRecordBytes = 16;
// The effects as a host before the path clean-up sent them (no minimum stroke), and before the
// simplification (a minimum stroke, no tolerance): still taken.
inline constexpr size_t kEffectsShortBytes = 3, kEffectsNoSimplifyBytes = 7;

// A streamed plot (band/conductor.h begin_streamed): the host's margin and the arena its bands
// were sized for; then each band's rows and edge count.
// kStreamTurned: the host's plan turned a wide solid's page a quarter (BandSpec::turn_wide).
inline constexpr uint8_t kStreamSolid = 1, kStreamClosed = 2, kStreamTurned = 4;
struct StreamBegin {
  int32_t margin = 0;
  uint32_t arena_bytes = 0;
  // kStreamSolid (begin_streamed_solid), kStreamClosed (the model's check), kStreamTurned
  uint8_t flags = 0;
};
struct BandBegin {
  int32_t y0 = 0, y1 = 0;
  uint32_t edges = 0;
  uint32_t vertices = 0, triangles = 0;  // a solid's band
};

enum class SceneFormat : uint8_t { kEdges = 0, kIndexed = 1 };

struct UploadBegin {
  SceneFormat format = SceneFormat::kEdges;
  uint32_t vertices = 0, edges = 0, faces = 0;
  uint32_t curves = 0;  // the 17-byte form's: Bézier edges besides the straight ones
  // The 21-byte form's: the curves drawn in bands of this many bytes of the job arena (0: the
  // curve job whole, in all of it), as `sim` of a job with that arena draws them.
  uint32_t band_arena = 0;
};
inline constexpr uint32_t kMinBandArena = 1024;  // as a streamed plot's (kStreamBegin)

// kPaused: a plot held by kPause, at rest with its pen lifted, until kResume (or kAbort).
enum class ServerState : uint8_t {
  kIdle = 0,
  kUploading = 1,
  kReady = 2,
  kPlotting = 3,
  kPaused = 4
};

struct StatusReport {
  uint8_t seq = 0;
  Status status = Status::kOk;  // of the query itself
  ServerState state = ServerState::kIdle;
  Status last_error = Status::kOk;
  uint32_t free_bytes = 0, edges = 0, crossings = 0, cut_runs = 0, draw_runs = 0, step_events = 0,
           bad_frames = 0;
};

// Little-endian field access, byte by byte: no alignment or endianness assumptions.
inline void put_u32(uint8_t* p, uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = uint8_t(v >> (8 * i));
}
inline uint32_t get_u32(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}
inline void put_i32(uint8_t* p, int32_t v) { put_u32(p, uint32_t(v)); }
inline int32_t get_i32(const uint8_t* p) { return int32_t(get_u32(p)); }

// Encoders write exactly the documented bytes into `out`.
void encode_upload_begin(const UploadBegin& b, uint8_t out[kUploadBeginBytes]);
// The 17-byte form, with b.curves.
void encode_upload_begin_curves(const UploadBegin& b, uint8_t out[kUploadBeginCurvesBytes]);
// The 21-byte form, with b.curves and b.band_arena.
void encode_upload_begin_bands(const UploadBegin& b, uint8_t out[kUploadBeginBandsBytes]);
void encode_edge(const Edge3& e, uint8_t out[kEdgeRecordBytes]);
void encode_curve(const BezierEdge3& c, uint8_t out[kCurveRecordBytes]);
void encode_vertex(const Point3& p, uint8_t out[kVertexRecordBytes]);
void encode_view(const View& v, uint8_t out[kViewBytes]);
void encode_halo(const DrawParams& d, uint8_t out[kHaloBytes]);
void encode_effects(const JobSpec& spec, uint8_t out[kEffectsBytes]);
void encode_machine(const JobSpec& spec, uint8_t out[kMachineBytes]);
void encode_status(const StatusReport& r, uint8_t out[kStatusBytes]);
void encode_face(const Triangle& t, uint8_t out[kFaceRecordBytes]);
void encode_hidden(const HiddenJob& h, uint8_t out[kHiddenBytes]);
void encode_stream_begin(const StreamBegin& b, uint8_t out[kStreamBeginBytes]);
void encode_band_begin(const BandBegin& b, uint8_t out[kBandBeginBytes]);

// Decoders check the length and every enumerated field: kMalformedRequest otherwise. Ranges
// (speeds, plot area) are checked later by validate() of the machine and the view.
Status decode_upload_begin(const uint8_t* p, size_t n, UploadBegin* out);
Edge3 decode_edge(const uint8_t* p);
BezierEdge3 decode_curve(const uint8_t* p);
Point3 decode_vertex(const uint8_t* p);
Status decode_view(const uint8_t* p, size_t n, View* out);
Status decode_halo(const uint8_t* p, size_t n, DrawParams* out);
Status decode_effects(const uint8_t* p, size_t n, JobSpec* spec);
Status decode_machine(const uint8_t* p, size_t n, JobSpec* spec);
Status decode_status(const uint8_t* p, size_t n, StatusReport* out);
Triangle decode_face(const uint8_t* p);
Status decode_hidden(const uint8_t* p, size_t n, HiddenJob* out);
Status decode_stream_begin(const uint8_t* p, size_t n, StreamBegin* out);
Status decode_band_begin(const uint8_t* p, size_t n, BandBegin* out);

}  // namespace haloplot
