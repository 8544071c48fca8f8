// Framing for the host link (USART): what the plotter and the host tool exchange.
//
//   0x7E | length (u16 LE) | type (u8) | seq (u8) | payload (length bytes) | CRC-32 (u32 LE)
//
// The CRC covers type, seq and payload. There is no byte stuffing: the decoder finds frames by
// the start byte and trusts one only when its length is in range and its CRC matches. After a
// failure it rescans the bytes it already has, from the one after the false start, so a real
// frame that began inside a damaged one is still found. A damaged frame is never delivered
// (short of a CRC-32 collision); the receiver answers it with a NAK and the sender resends.
#pragma once
#include <stddef.h>
#include <stdint.h>

namespace haloplot {

inline constexpr uint8_t kFrameStart = 0x7E;
inline constexpr size_t kFrameOverhead = 1 + 2 + 1 + 1 + 4;

// Message types; payload layouts are in protocol/messages.h, their handling in job_server.h.
enum class FrameType : uint8_t {
  kAck = 0x01,   // payload: acknowledged seq, status of the request
  kNak = 0x02,   // payload: the seq expected next; the sender resends from there
  kSync = 0x03,  // accepted with any seq: starts a session, the next seq expected is seq + 1
  kUploadBegin = 0x0F,
  kUploadEdges = 0x10,  // projected Edge3 records (.edges)
  kSetView = 0x11,
  kSetHalo = 0x12,
  kSetEffects = 0x13,
  kUploadVertices = 0x14,     // world vertices, projected with the view on the controller
  kUploadEdgeIndices = 0x15,  // vertex index pairs
  kUploadFaces = 0x16,        // triangles (vertex indices + polygon id) for hidden lines
  kSetMachine = 0x17,
  kSetHidden = 0x18,    // hidden-line method, outline pass, dash and gap
  kStreamBegin = 0x19,  // the next plot's scene comes as bands (see messages.h)
  kBandBegin = 0x1A,    // one band's rows and edge count; accepted while plotting
  kBandEdges = 0x1B,    // the band's edges with their scene indices; accepted while plotting
  kStreamEnd = 0x1C,    // no band follows
  // A solid's band (kStreamBegin flag kStreamSolid): its vertices, drawn edges and triangles.
  kBandVertices = 0x1D,
  kBandSolidEdges = 0x1E,
  kBandTriangles = 0x1F,
  kPlot = 0x20,
  kReplot = 0x21,        // another halo width: DRAW only, CUT's result is kept
  kUploadCurves = 0x22,  // cubic Bézier edges (projected control points)
  kQueryStatus = 0x30,
  kStatus = 0x31,  // the reply to kQueryStatus
  kPause = 0x3D,   // feed hold: brake to rest, lift the pen, wait (state kPaused once at rest)
  kResume = 0x3E,  // lower the pen where the hold lifted it and go on
  kAbort = 0x3F,
};

// Writes one frame into out (capacity at least payload_length + kFrameOverhead); returns the
// bytes written, or 0 if it does not fit.
size_t encode_frame(uint8_t type, uint8_t seq, const uint8_t* payload, uint16_t payload_length,
                    uint8_t* out, size_t capacity);

struct Frame {
  uint8_t type = 0, seq = 0;
  const uint8_t* payload = nullptr;  // valid until the next push()
  uint16_t length = 0;
};

// A byte-at-a-time decoder over a caller-owned buffer of at least max_payload + 9 bytes.
class FrameDecoder {
 public:
  enum class Event : uint8_t {
    kNone,      // need more bytes
    kFrame,     // a whole, verified frame: see frame()
    kBadFrame,  // a frame failed its length or CRC check: answer with a NAK
  };

  FrameDecoder(uint8_t* buffer, size_t capacity, uint16_t max_payload);
  // Add a byte; at most one event per call.
  Event push(uint8_t byte);
  // A frame already complete in the buffer (several can arrive inside one damaged frame's
  // bytes): call until it returns kNone after each push.
  Event poll();
  // The line went quiet in the middle of a frame: a damaged length may be waiting for bytes
  // that will never come. Give up the current candidate and rescan what is buffered. The
  // link calls this after its idle timeout (a few byte times), then poll() as usual.
  Event idle();
  const Frame& frame() const { return frame_; }
  uint32_t bad_frames() const { return bad_frames_; }

 private:
  Event scan();    // look for a complete frame at the start of the buffered bytes
  void compact();  // drop the frame delivered last and anything before the next start byte
  Event reject();  // the candidate at the start is bad: drop it, rescan from the next start

  uint8_t* buf_;
  size_t capacity_;
  uint16_t max_payload_;
  size_t have_ = 0;      // bytes buffered, starting at a candidate start byte
  size_t consumed_ = 0;  // bytes of the frame delivered last, dropped on the next call
  Frame frame_;
  uint32_t bad_frames_ = 0;
};

}  // namespace haloplot
