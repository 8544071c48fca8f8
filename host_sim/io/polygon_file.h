// The polygon file of `haloplot view2d`: one vertex "x y" per line, in order around the
// polygon (either sense); '#' comments and blank lines are skipped. Coordinates are integers
// in [-2^20, 2^20].
#pragma once
#include <istream>
#include <string>
#include <vector>

#include "haloplot/view2d/polygon_view.h"
#include "io/input_error.h"

namespace haloplot::host {

InputError read_polygon(std::istream& in, const std::string& name, std::vector<Point2>* out);
InputError read_polygon_file(const std::string& path, std::vector<Point2>* out);

}  // namespace haloplot::host
