#include "haloplot/status/status.h"

namespace haloplot {

const char* status_name(Status s) {
  switch (s) {
    case Status::kOk:
      return "ok";
    case Status::kCoordinateOutOfRange:
      return "coordinate outside [0, 2^20)";
    case Status::kTooManyEdges:
      return "too many edges for 32-bit indices";
    case Status::kWorkspaceTooSmall:
      return "workspace buffer too small";
    case Status::kCutsetStorageTooSmall:
      return "cutset buffer too small for the edge index";
    case Status::kCrossingCapacity:
      return "crossing capacity exceeded";
    case Status::kCellPairOverflow:
      return "too many (cell, edge) pairs";
    case Status::kBadParameter:
      return "parameter out of range";
    case Status::kSinkFull:
      return "span sink full";
    case Status::kCutsetInconsistent:
      return "cutset inconsistent";
    case Status::kStepRateExceeded:
      return "step rate above the motor limit";
    case Status::kTimerFloor:
      return "step interval below the timer floor";
    case Status::kQueueFull:
      return "motion queue full";
    case Status::kIntervalTooLong:
      return "step interval too long for the tick";
    case Status::kSceneTooLarge:
      return "scene too large for the controller's memory";
    case Status::kBusy:
      return "busy plotting";
    case Status::kNoScene:
      return "no complete scene uploaded";
    case Status::kNoCutset:
      return "no CUT result for this scene and view: plot first";
    case Status::kUploadMismatch:
      return "upload does not match its declared counts";
    case Status::kUnsupported:
      return "not supported by this build";
    case Status::kMalformedRequest:
      return "malformed request";
    case Status::kAborted:
      return "aborted";
    case Status::kLimitSwitch:
      return "limit switch triggered";
    case Status::kStepUnderrun:
      return "step queue underrun";
    case Status::kSelfIntersecting:
      return "polygon is self-intersecting";
    case Status::kVisibilityInconsistent:
      return "visibility walk inconsistent";
    case Status::kIncidenceCapacity:
      return "more vertex-on-edge incidences than the buffer holds";
    case Status::kNotManifold:
      return "mesh is not a closed, consistently oriented manifold";
    case Status::kNoFaces:
      return "hidden lines need faces: upload them with the vertices";
    case Status::kSegmentCapacity:
      return "visible segment capacity exceeded";
    case Status::kArenaTooSmall:
      return "arena too small for a band one step high";
    case Status::kBandCarryLost:
      return "a piece carried across a band border was lost";
    case Status::kNotPlotting:
      return "no plot in motion";
    case Status::kMisalignedBuffer:
      return "buffer not on an 8-byte boundary";
    case Status::kBandInputReused:
      return "a band's run was asked again after its input was reused";
  }
  return "unknown status";
}

}  // namespace haloplot
