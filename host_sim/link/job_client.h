// The host's side of the job protocol (core/include/haloplot/protocol/job_server.h): stop-and-wait
// frames with resends, over any byte transport (a serial port, QEMU's emulated USART through a
// socket, or an in-process loopback in the tests). It can damage its own frames on purpose, to
// prove that the controller NAKs them and the job still arrives whole.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "haloplot/job/job.h"
#include "haloplot/protocol/frame.h"
#include "haloplot/protocol/messages.h"
#include "haloplot/solid/mesh.h"
#include "haloplot/view/projection.h"
#include "pipeline/band_stream.h"

namespace haloplot::host {

class Transport {
 public:
  virtual ~Transport() = default;
  virtual bool write(const uint8_t* bytes, size_t n) = 0;
  // Up to `cap` bytes; 0 when nothing arrived within timeout_ms.
  virtual size_t read(uint8_t* out, size_t cap, int timeout_ms) = 0;
  // The other end hung up (a socket's server closed it): reads will never return data.
  virtual bool closed() const { return false; }
};

// Deliberate damage to the first transmission of chosen frames.
struct FaultPlan {
  uint32_t corrupt_every = 0;   // every k-th frame: one byte flipped (0: never)
  uint32_t truncate_every = 0;  // every k-th frame: only its first half sent (0: never)
  uint64_t seed = 1;            // which byte is flipped
};

struct LinkStats {
  uint32_t frames = 0, resends = 0, naks = 0, timeouts = 0, corrupted = 0, truncated = 0;
};

class JobClient {
 public:
  JobClient(Transport& t, FaultPlan faults = {}) : t_(t), faults_(faults) {}

  // Sends one request and waits for its reply, resending on NAK or silence (up to `tries`).
  // On success *status is the controller's answer to the request (kAck's status). With
  // `first_wait_ms`, the first try waits that long for a reply and each next one twice as long
  // as the last, up to timeout_ms.
  bool request(FrameType type, const std::vector<uint8_t>& payload, Status* status,
               std::vector<uint8_t>* reply_payload = nullptr, int first_wait_ms = 0);

  // The session's first request. A controller still starting up misses it without a NAK (its
  // serial port is not listening yet), so it is resent after 100 ms, then 200 ms, and so on up
  // to timeout_ms: a controller that comes up is answered at once, not after a whole timeout,
  // and a slow one on a loaded machine still gets the full timeout in the end.
  bool sync();
  // The whole job: machine, effects, halo, then the scene as projected edges (and, when
  // `curves` is given and not empty, its projected Bézier edges before them: kUploadCurves).
  // band_arena > 0 (with curves): the controller draws them in bands of that arena.
  bool upload(const JobSpec& spec, const std::vector<Edge3>& edges, Status* status,
              const std::vector<BezierEdge3>* curves = nullptr, uint32_t band_arena = 0);
  // The scene as world vertices and index pairs, projected on the controller with `view`.
  // With `faces` (triangles, for the hidden-line drawings) they are uploaded too.
  bool upload_indexed(const JobSpec& spec, const View& view, const std::vector<Point3>& world,
                      const std::vector<uint32_t>& pairs, Status* status,
                      const std::vector<Triangle>* faces = nullptr);
  // A streamed plot (the controller never holds the scene): the settings, the plan's margin and
  // arena, the plot started at once, then each band as the controller takes it (while it
  // still stages the last one it answers kBusy, and the band is offered again), then the end.
  // *status is the first refusal; a plot that ends early stops the stream.
  bool stream(const JobSpec& spec, const BandPlan& plan, uint32_t arena_bytes, Status* status);
  bool solid_band(const PlannedBand& band, Status* status);
  bool query(StatusReport* report);
  // Polls status until the plot ends; false on a link failure.
  bool wait_idle(StatusReport* report, int poll_ms = 20);

  const LinkStats& stats() const { return stats_; }
  const std::string& error() const { return error_; }
  int timeout_ms = 2000;
  int tries = 20;

 private:
  bool settings(const JobSpec& spec, Status* status);
  bool chunks(FrameType type, const std::vector<uint8_t>& records, size_t record_bytes,
              Status* status);
  bool read_frame(Frame* f, std::vector<uint8_t>* payload, int wait_ms);

  Transport& t_;
  FaultPlan faults_;
  LinkStats stats_;
  std::string error_;
  uint8_t seq_ = 0;
  std::vector<uint8_t> rx_buf_ = std::vector<uint8_t>(2048);
  FrameDecoder decoder_{rx_buf_.data(), rx_buf_.size(), 1024};
  std::vector<uint8_t> pending_;  // bytes read but not yet fed to the decoder
};

}  // namespace haloplot::host
