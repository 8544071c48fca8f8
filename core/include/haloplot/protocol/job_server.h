// The controller's side of the job protocol: frames in (byte by byte from the USART), replies
// out, a stored scene and job settings, and plots handed to the platform's motion.
//
// Reliability: stop-and-wait with an 8-bit sequence number. A verified frame with the
// expected seq is acted on and acknowledged (kAck carries the request's status: an error is
// an answer, never a crash). A damaged frame, or one out of sequence, gets kNak with the seq
// expected, and the sender resends from there. A repeat of the last frame (its ACK was lost)
// gets the same reply again and is not acted on twice. The stored job changes only through
// verified, in-sequence frames, so no damage on the line can corrupt it.
//
// Memory: one caller arena. The scene takes the front, sized by kUploadBegin (refused with
// kSceneTooLarge when it cannot fit, before a byte of it is stored): world vertices, index
// pairs and triangles for the indexed format, then the projected edges (after a scene's
// projected Bézier edges, kUploadCurves); the rest is the job buffer for CUT, DRAW and the path
// (core/job), for a scene with curves the curve stages and the path (job_prepare_curves; with
// kUploadBegin's band arena, in bands of that many of its bytes: band/curve_bands.h), or
// for a hidden-line drawing the projected vertices, the hidden-line run and its strokes
// (job_prepare_solid).
//
// Streamed plots (kStreamBegin): the scene never comes whole. The arena is split into the band
// conductor's arena (the size the host planned its bands for) and a staging buffer behind it
// that receives the next band (kBandBegin, kBandEdges: accepted while plotting, kBusy while the
// staging buffer still holds a band the plot has not taken). kPlot starts the motion at once;
// the planner waits for each band (band/conductor.h begin_streamed), and kStreamEnd says no
// band follows.
//
// last_error is the most recent failure: of a request, or of the plot in motion. A plot that
// starts clears it, so after a plot it says how that plot ended. The CUTSET stays at the front of
// the job buffer after a plot, so kReplot with a new halo width runs only DRAW and the path.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/band/conductor.h"
#include "haloplot/job/job.h"
#include "haloplot/protocol/frame.h"
#include "haloplot/protocol/messages.h"
#include "haloplot/view/projection.h"

namespace haloplot {

// What the server needs from the platform's motion (the step timer on the chip, a virtual run
// on the host). begin() starts the plot and may return before it ends; the server polls
// running() and reads the outcome with result().
struct MotionPort {
  void* ctx = nullptr;
  Status (*begin)(void* ctx, const JobSpec& spec, const PreparedJob& job) = nullptr;
  void (*abort)(void* ctx) = nullptr;
  bool (*running)(void* ctx) = nullptr;
  Status (*result)(void* ctx) = nullptr;
  uint32_t (*step_events)(void* ctx) = nullptr;
  // Feed hold (motion/step_prep.h); null where the platform has none (kPause is then
  // kUnsupported). paused(): at rest with the pen lifted.
  void (*pause)(void* ctx) = nullptr;
  void (*resume)(void* ctx) = nullptr;
  bool (*paused)(void* ctx) = nullptr;
};

struct ByteOutput {
  void* ctx = nullptr;
  void (*write)(void* ctx, const uint8_t* bytes, uint32_t n) = nullptr;
};

// Request types from kPlatformTypeFirst up belong to the platform (test hooks, board
// specifics): the server passes them to the extension, if one is set.
inline constexpr uint8_t kPlatformTypeFirst = 0x70;

class JobServer {
 public:
  struct Extension {
    void* ctx = nullptr;
    Status (*handle)(void* ctx, const Frame& f) = nullptr;
  };
  static constexpr uint16_t kMaxPayload = 1024;
  // rx_buffer holds the frame decoder's bytes: at least kMaxPayload + kFrameOverhead. The
  // arena may start anywhere: the server uses it from its first kBufferAlignment boundary on.
  JobServer(uint8_t* arena, size_t arena_bytes, uint8_t* rx_buffer, size_t rx_bytes, ByteOutput out,
            MotionPort motion);

  void push(uint8_t byte);  // one received byte
  void idle();              // the line went quiet mid-frame (the link's idle timeout)
  // Called by the main loop: notices a finished plot and records its outcome.
  void service();

  void set_extension(Extension e) { extension_ = e; }
  // A clock for the cost of each plot's preparation (CUT, DRAW, path) and each re-plot's
  // (DRAW, path), in the clock's ticks; none is read without it.
  void set_clock(uint64_t (*now)()) { clock_ = now; }
  uint64_t prepare_ticks() const { return prepare_ticks_; }
  uint64_t redraw_ticks() const { return redraw_ticks_; }

  ServerState state() const { return state_; }
  Status last_error() const { return last_error_; }
  const JobCounters& counters() const { return counters_; }
  const JobSpec& spec() const { return spec_; }
  uint32_t edges() const { return n_edges_ + n_curves_; }  // the stored scene's, curves too

 private:
  void on_event(FrameDecoder::Event ev);
  void on_frame(const Frame& f);
  Status act(const Frame& f);
  Status upload_begin(const uint8_t* p, uint16_t n);
  Status upload_records(FrameType type, const uint8_t* p, uint16_t n);
  Status plot();
  Status plot_hidden(uint8_t* job_mem, size_t job_bytes);
  Status plot_curves(const Edge3* edges, uint8_t* job_mem, size_t job_bytes);
  Status plot_curve_bands(const Edge3* edges, uint8_t* job_mem, size_t job_bytes);
  Status replot(const uint8_t* p, uint16_t n);
  Status start_motion();
  Status stream_begin(const uint8_t* p, uint16_t n);
  Status band_begin(const uint8_t* p, uint16_t n);
  Status band_edges(const uint8_t* p, uint16_t n);
  Status band_solid(FrameType type, const uint8_t* p, uint16_t n);
  bool solid_stream() const { return (stream_.flags & kStreamSolid) != 0; }
  void check_staged();
  Status plot_streamed();
  static Status next_band(void* ctx, StreamedBand* band, bool* end);
  static void release_band(void* ctx);
  void reply(FrameType type, const uint8_t* payload, uint16_t n);
  void send_status(uint8_t seq);
  void forget_cut() { has_cut_ = false; }
  size_t job_offset() const;

  uint8_t* arena_;
  size_t arena_bytes_;
  FrameDecoder decoder_;
  ByteOutput out_;
  MotionPort motion_;

  ServerState state_ = ServerState::kIdle;
  Status last_error_ = Status::kOk;
  uint8_t expected_seq_ = 0;
  uint8_t last_reply_[kStatusBytes + kFrameOverhead] = {};
  uint16_t last_reply_bytes_ = 0;

  UploadBegin scene_;
  uint32_t received_vertices_ = 0, received_edges_ = 0, received_faces_ = 0, received_curves_ = 0;
  uint32_t n_edges_ = 0, n_curves_ = 0;
  bool has_cut_ = false;  // a curve scene: its hits kept at the job buffer's front
  uint32_t crossing_capacity_ = 0;

  JobSpec spec_;
  View view_;
  PreparedJob job_;
  JobCounters counters_;
  uint32_t cut_runs_ = 0, draw_runs_ = 0;
  uint32_t resume_events_ = 0;  // the kPlot's resume point, for start_motion()
  Extension extension_;
  uint64_t (*clock_)() = nullptr;
  uint64_t prepare_ticks_ = 0, redraw_ticks_ = 0;

  // A streamed plot: its settings, the conductor, and the staged band.
  enum class Staging : uint8_t { kEmpty, kReceiving, kReady };
  bool streamed_ = false, stream_end_ = false;
  StreamBegin stream_{};
  BandConductor conductor_;
  CurveBands curve_bands_;  // a curve scene uploaded with a band arena
  Staging staging_ = Staging::kEmpty;
  BandBegin staged_{};
  uint32_t staged_received_ = 0, staging_capacity_ = 0;
  Edge3* staged_edges_ = nullptr;
  uint32_t* staged_ids_ = nullptr;
  // A solid's band: carved from the same staging bytes, vertices, then edges, then triangles.
  uint8_t* stage_base_ = nullptr;
  size_t stage_bytes_ = 0;
  uint32_t staged_vertices_ = 0, staged_triangles_ = 0;  // received so far
  uint32_t* staged_vertex_ids_ = nullptr;
  Point3* staged_points_ = nullptr;
  uint32_t* staged_pairs_ = nullptr;
  Triangle* staged_faces_ = nullptr;
  StagedSolidBand staged_solid_{};
};

}  // namespace haloplot
