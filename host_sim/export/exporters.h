// Exporters for plotters that run other firmware. Both take the planned path (pen-up travel
// and pen-down strokes, in plot steps) and a scale in plot steps per millimetre.
//
// G-code (grbl-style pen plotters): G21 G90, G0 travel and G1 drawing at feeds in mm/min, and
// the pen by one of three profiles:
//   servo   "M3 S<value>" down, "M5" up, each followed by "G4 P<seconds>" (the machine's pen
//           travel and settle time); Marlin: "M400", "M280 P0 S<angle>", "G4 P<milliseconds>"
//   z       "G0 Z<up>" up, "G1 Z<down> F<z feed>" down (a Z axis waits for itself: no dwell)
//   custom  the given text for each change, line by line, nothing added
// HPGL: IN; SP1; then PU x,y; / PD x,y,...; in plotter units of 0.025 mm (40 per mm).
// Asked for, a pen change between line kinds: M0 in G-code, SPn in HPGL (ExportStyle).
// Both write paper coordinates (export/page.h): a path point plus the style's offset, from the
// page's lower-left corner, y up; the SVG of the same plot places every point at the same spot.
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

#include "haloplot/motion/machine.h"
#include "haloplot/motion/path_plan.h"

namespace haloplot::host {

enum class PenProfile : uint8_t { kServo, kZ, kCustom };
// The G-code's dialect. grbl: G4 P in seconds, the servo on the spindle (M3 S / M5), M2 at the
// end. Marlin: G4 P in whole milliseconds, the servo on M280 P0 S<angle> (Marlin's servo
// command, no spindle or laser feature needed) after an M400, which waits for the queued moves
// (M280 does not), and no M2 (Marlin has none).
enum class GcodeFlavor : uint8_t { kGrbl, kMarlin };

struct ExportStyle {
  uint32_t steps_per_mm = 80;  // plot steps per millimetre
  PenProfile pen = PenProfile::kServo;
  GcodeFlavor flavor = GcodeFlavor::kGrbl;
  int32_t pen_down_s = 1000;               // servo: the M3 S value (marlin: the down angle)
  int32_t servo_up_angle = 90;             // servo, marlin: the M280 angle with the pen up
  std::string header_text, footer_text;    // as given: after G90, and before the end
  int32_t z_up_um = 2000, z_down_um = 0;   // z: pen heights, micrometres
  int64_t z_feed_milli = 1000000;          // z: the pen-down feed, thousandths of mm/min
  std::string pen_up_text, pen_down_text;  // custom: G-code lines, '\n' between them
  // Feeds in thousandths of mm/min as given (0: the machine's speeds in mm/min); the machine's
  // speeds are set from them too (apply_feeds), so a plot runs as its G-code says.
  int64_t draw_feed_milli = 0, travel_feed_milli = 0;
  // The page placement (export/page.h): added to every point, in plot steps.
  int32_t offset_x = 0, offset_y = 0;
  // A pen change between the path's layers (motion/path_plan.h LayerCounts): G-code stops
  // (M0) with the pen up before each layer after the first; HPGL selects the layer's pen
  // (SP1 visible, SP2 hidden, SP3 intersections, SP4 hatching, SP5 outlines).
  bool pause_between_layers = false;
};

// The machine's draw and travel speeds (plot steps/s) from the style's feeds, when given.
// False with *error when a feed is out of the machine's range.
bool apply_feeds(const ExportStyle& s, Machine* m, std::string* error);

// `layers`: how many of the path's points each layer has (PreparedJob::layer_points; the
// points after them, the travel home, belong to the last); used with pause_between_layers.
void write_gcode(std::ostream& out, const std::vector<PathPoint>& path, const Machine& m,
                 const ExportStyle& s, const LayerCounts& layers = LayerCounts{});
void write_hpgl(std::ostream& out, const std::vector<PathPoint>& path, const ExportStyle& s,
                const LayerCounts& layers = LayerCounts{});

// "12.345": plot steps in millimetres, exactly rounded to 3 decimals (integer arithmetic).
std::string mm_text(int64_t steps, uint32_t steps_per_mm);
// The same text appended to *out (the writers' loops build no string per number).
void append_mm(std::string* out, int64_t steps, uint32_t steps_per_mm);
// Thousandths as "-12.345" (exactly three decimals), appended to *out.
void append_thousandths(std::string* out, int64_t thousandths);
// A decimal integer, appended to *out.
void append_int(std::string* out, int64_t v);

// Text for a stream gathered in blocks: one write per 64 KB instead of a formatted insertion per
// number. flush() (or the destructor) writes what is left.
class BlockWriter {
 public:
  explicit BlockWriter(std::ostream& out) : out_(out) { text.reserve(kBlock + 256); }
  ~BlockWriter() { flush(); }
  BlockWriter(const BlockWriter&) = delete;
  BlockWriter& operator=(const BlockWriter&) = delete;
  // Call after each piece of text: writes the block once it is full.
  void maybe_flush() {
    if (text.size() >= kBlock) flush();
  }
  void flush();
  std::string text;

 private:
  static constexpr size_t kBlock = size_t{1} << 16;
  std::ostream& out_;
};

}  // namespace haloplot::host
