// Status codes for every core stage. The core never throws, never aborts and never
// truncates silently: a stage either finishes or returns a code that names the problem.
#pragma once
#include <stdint.h>

namespace haloplot {

// [[nodiscard]]: a status returned and not looked at is a compile error (-Werror); where one is
// rightly ignored, the call says so with a (void) cast and a comment.
enum class [[nodiscard]] Status : uint8_t{
    kOk = 0,
    kCoordinateOutOfRange,    // an input coordinate is outside [0, 2^20)
    kTooManyEdges,            // more edges than the 32-bit indices and counters allow
    kWorkspaceTooSmall,       // the caller's scratch buffer is smaller than the plan asked for
    kCutsetStorageTooSmall,   // the caller's CUTSET buffer cannot hold the edge index
    kCrossingCapacity,        // more crossings than the CUTSET buffer holds (see needed count)
    kCellPairOverflow,        // more (cell, edge) pairs than a 32-bit counter holds
    kBadParameter,            // a parameter is outside its documented range
    kSinkFull,                // the span sink refused a span (its buffer is full)
    kCutsetInconsistent,      // a CUTSET read from outside breaks an invariant
    kStepRateExceeded,        // a speed needs more steps per second than a motor may take
    kTimerFloor,              // a step interval below the step clock's floor
    kQueueFull,               // a fixed-size motion queue has no room (retry after a tick)
    kIntervalTooLong,         // a step interval beyond the tick's 32-bit Q8 field (2^23 ticks)
    kSceneTooLarge,           // the uploaded scene does not fit the controller's memory
    kBusy,                    // a plot is running: only status and abort are accepted
    kNoScene,                 // plot before a complete scene upload
    kNoCutset,                // re-plot before a plot of this scene and view
    kUploadMismatch,          // an upload chunk beyond, or short of, the declared counts
    kUnsupported,             // a request this build cannot serve yet (names the reason)
    kMalformedRequest,        // a request payload of the wrong length or with bad fields
    kAborted,                 // motion stopped by an abort request
    kLimitSwitch,             // motion stopped by a limit switch
    kStepUnderrun,            // the step timer found the queue empty in the middle of a move
    kSelfIntersecting,        // a polygon's edges meet other than at consecutive shared vertices
    kVisibilityInconsistent,  // the visibility walk lost its way (a bug: never on valid input)
    kIncidenceCapacity,       // more vertex-on-edge incidences than the caller's buffer holds
    kNotManifold,             // the QI method needs a closed, consistently oriented mesh
    kNoFaces,                 // hidden lines need faces: the scene was uploaded without them
    kSegmentCapacity,         // more visible segments than the regions buffer holds (see count)
    kArenaTooSmall,           // a band one step high does not fit the arena (see the bytes needed)
    kBandCarryLost,           // a piece carried across a band border found no continuation (a bug)
    kNotPlotting,             // pause or resume with no plot in motion
    kMisalignedBuffer,        // a caller buffer does not start on a kBufferAlignment boundary
    kBandInputReused,         // a solid band's run asked again after its input was reused (a bug)
};

// Every buffer a caller hands the core (scratch, storage, workspace, arena) must start on this
// boundary: the core stores 64-bit fields there, which a Cortex-M reads with LDRD/STRD, and
// those fault on an address that is not a multiple of 4 (and x86 hides the mistake). An entry
// given a buffer off this boundary returns kMisalignedBuffer before it touches it; the sizes
// the *_bytes() queries give hold for aligned buffers, exactly. `alignas(8)` on a static array,
// or any malloc/new result, is enough.
constexpr uintptr_t kBufferAlignment = 8;
inline bool buffer_misaligned(const void* buffer) {
  return (reinterpret_cast<uintptr_t>(buffer) & (kBufferAlignment - 1)) != 0;
}

// A short, stable, human-readable name, e.g. "crossing capacity exceeded".
const char* status_name(Status s);

[[nodiscard]] inline bool ok(Status s) { return s == Status::kOk; }

}  // namespace haloplot
