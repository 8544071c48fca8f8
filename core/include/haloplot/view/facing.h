// Each triangle's facing as the model has it, from the world vertices. The projected area of a
// face decides its facing only up to the rounding of its corners: a sliver nearly edge-on
// (hundreds of steps long, hundredths of a step tall) can flip, and its polygon's diagonal
// then becomes a contour line that the model does not have. Here the facing is the sign of
// the face's world normal n = (B - A) x (C - A) against the direction to the viewer w
// (orthographic) or against E - A, E the eye (perspective): the same rotation as the
// projection, w = (-sin az cos el, -cos az cos el, sin el) with the view's Q2.30 sine and
// cosine, rounded once to Q2.30 per component.
//
// Numbers: world coordinates within +-2^20, so n's components are below 2^43; w in Q2.30 and
// E - A below 2^52 in Q30 (D <= 2^21). The dot product, below 2^97, is summed exactly in
// 128-bit limbs (geometry/wide.h): no rounding decides the sign. A face seen exactly edge-on
// is back.
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"
#include "haloplot/geometry/triangle.h"
#include "haloplot/status/status.h"
#include "haloplot/view/projection.h"

namespace haloplot {

// out[t] = 1 when triangle t faces the viewer in the model, else 0. kBadParameter for a bad
// view or a triangle corner beyond n_world; kCoordinateOutOfRange for a world point beyond
// kWorldLimit.
Status model_facing(const View& view, const Point3* world, uint32_t n_world,
                    const Triangle* triangles, uint32_t n_triangles, uint8_t* out);

}  // namespace haloplot
