// The picture of a 2-D visibility solution, as in Freeman and Loutrel's Figures 5 to 7:
// visible parts solid, hidden parts dashed, the vantage point marked, y up.
#pragma once
#include <ostream>
#include <vector>

#include "haloplot/view2d/polygon_view.h"

namespace haloplot::host {

void write_view2d_svg(std::ostream& out, const std::vector<Point2>& polygon, Point2 eye,
                      const std::vector<VisibleSpan>& visible);

}  // namespace haloplot::host
