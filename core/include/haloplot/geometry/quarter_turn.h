// The page turned a quarter, for a solid plotted in bands across a drawing wider than tall
// (band/conductor.h, BandSpec::turn_wide). A band is a strip of rows that the pen crosses once,
// so strips along the drawing's longer side cost it less travel; the conductor then works in
// this turned frame and turns every point back before it leaves. The turn is a proper rotation
// by whole units (every face keeps its facing, every exact predicate its answer, every
// parameter along an edge its value), and its offset keeps each coordinate in [0, kCoordMax].
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"

namespace haloplot {

// page (x, y) -> turned (y, kTurnOffset - x): a clockwise quarter turn, depth unchanged.
inline constexpr int32_t kTurnOffset = kCoordMax;

inline Point3 turn_point(const Point3& p) { return Point3{p.y, kTurnOffset - p.x, p.z}; }
inline Point3 unturn_point(const Point3& p) { return Point3{kTurnOffset - p.y, p.x, p.z}; }
inline Edge3 unturn_edge(const Edge3& e) { return Edge3{unturn_point(e.a), unturn_point(e.b)}; }

}  // namespace haloplot
