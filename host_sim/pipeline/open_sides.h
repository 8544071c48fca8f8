// A model's open sides (on exactly one face) measured, for the plot's word on them: are they
// gaps a weld would close (corners of two open sides a small distance apart, much closer than
// the model's sides are long), or is the model open as made (a sheet, a hemisphere, a hole's
// rim: no corner of another open side anywhere near)? And if gaps, which --weld EPS closes
// them, checked by welding a copy (never a value that leaves more open sides, or a side on
// three faces or a shell that cannot be oriented more).
//
// In doubles on the host: a hint, not a decision the drawing depends on (the drawing is right
// either way: an open shell's faces hide from both sides).
#pragma once
#include <cstdint>
#include <vector>

#include "io/obj_file.h"

namespace haloplot::host {

struct OpenSides {
  uint32_t sides = 0;              // sides on exactly one face
  uint32_t nonmanifold_sides = 0;  // sides on three or more faces
  uint32_t corners = 0;            // vertices on an open side
  double typical_side = 0;         // the median side length (world units)
  // For each open corner with one within typical_side / 2: the distance to the nearest corner
  // of another open side that it shares no face with (world units), ascending.
  std::vector<double> gaps;
};

// The open sides of a welded model (after weld_vertices).
OpenSides measure_open_sides(const ObjModel& model);

// What welding a model further within `tolerance` world units does, as weld_vertices and
// orient_shells leave it.
struct WeldTrial {
  uint32_t open_sides = 0, nonmanifold_sides = 0;
  uint32_t shells = 0, closed_shells = 0, unorientable_shells = 0;
  uint32_t dropped_faces = 0;
};
WeldTrial try_weld(ObjModel model, double tolerance);

// The gaps' scale exists when at least kMinGapCorners open corners (and one in ten) have a
// partner within typical_side / kGapBelowSide, and the nearest gaps beyond them are at least
// kGapJump times farther: the weld's EPS goes in that jump.
inline constexpr double kGapBelowSide = 8;
inline constexpr double kGapJump = 4;
inline constexpr uint32_t kMinGapCorners = 3;

struct WeldHint {
  uint32_t near = 0;  // open corners with a partner within typical_side / kGapBelowSide
  double nearest = 0, farthest = 0;  // their gaps' range (file units)
  bool gaps = false;                 // a gap scale was found among them
  bool tried = false;                // eps was tried on a copy (a gap scale, or their median gap)
  bool suggest = false;              // ... and closes open sides without harm
  double eps = 0;                    // file units: a round number ("0.0004")
  uint32_t within = 0;               // open corners with a partner within eps
  WeldTrial before, after;           // the model as welded, and welded further at eps
};

// The measurement read: EPS at the two widest jumps in the near gaps (twice the gap below the
// jump where the jump leaves room, then the gap itself), then their median gap; each rounded
// up to one significant digit and tried on a copy; the first that closes open sides without
// harm is suggested, else the first tried is reported.
WeldHint weld_hint(const ObjModel& model, const OpenSides& open);

}  // namespace haloplot::host
