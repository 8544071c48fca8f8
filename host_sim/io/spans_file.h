// The .spans file: one "s EDGE X0 Y0 X1 Y1" line per visible piece, integer steps, in the
// order DRAW emits them (edge by edge, along each edge).
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

#include "haloplot/draw/draw.h"

namespace haloplot::host {

void write_spans(std::ostream& out, const std::vector<Span>& spans);

// "0", "1", "0.5": a QI counted in halves, as the .spans file writes it ("?": not decided).
std::string qi_text(int32_t halves);

// The hidden-line modes' form: "s EDGE X0 Y0 X1 Y1 QI" (QI as a number of front faces in
// front, halves for pieces lying along a face side), then "o EDGE X0 Y0 X1 Y1 0" for the
// outline pass, then "h POLYGON X0 Y0 X1 Y1 0" for the hatching. Edges numbered past the input's
// are contour diagonals of split polygons.
void write_spans_qi(std::ostream& out, const std::vector<Span>& spans,
                    const std::vector<int32_t>& qi, const std::vector<Span>& outline,
                    const std::vector<Span>& hatch = {});

}  // namespace haloplot::host
