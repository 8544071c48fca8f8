// The .spans file: one "s EDGE X0 Y0 X1 Y1" line per visible piece, integer steps, in the
// order DRAW emits them (edge by edge, along each edge).
#pragma once
#include <iosfwd>
#include <vector>

#include "draw/draw.h"

namespace haloplot::host {

void write_spans(std::ostream& out, const std::vector<Span>& spans);

}  // namespace haloplot::host
