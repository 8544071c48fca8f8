// Hatching as lines on the faces: each hatched face is filled with its polygon's parallel
// lines (solid/hatch_pattern.h: a lattice anchored at the origin, the angle from the polygon's
// mean depth), and what shows of each line is decided as an intersection line's is
// (solid/segment_pass.h): cut where it crosses a face's side on paper, meets a corner or passes
// through a face, and the middle of each piece asked against every face but its own polygon's
// flat part. It needs no planar graph and no memory of its own, so a band can draw its rows'
// part of every line, cut exactly at its borders, and the banded hatching is the whole one.
//
// Rounding: a line's ends are where the exact lattice line meets the triangle's sides, rounded
// to units, within 1/2 + 2^-9 of the exact point on each axis (each side computed from its
// lesser end, so the two triangles of a quad round the point on their diagonal alike: a flat
// polygon's pieces are joined into one line); its depth is the face's plane there, rounded.
// Franklin's regions (surface/region_hatch.h) fill the same areas and are what the tests check this
// against.
#pragma once
#include <stdint.h>

#include "haloplot/solid/hatch_pattern.h"
#include "haloplot/solid/segment_pass.h"

namespace haloplot {

struct HatchLineStats : LineCounts {
  uint32_t faces = 0;  // triangles hatched
  uint64_t lines = 0;  // lattice lines laid (in a band: those meeting its rows)
};

// Is triangle t hatched? With `front` (closed solids), the front faces; otherwise those whose
// projection has area, front-facing only when params.front_only.
bool hatched_face(const Topology& topo, const uint8_t* front, uint32_t t,
                  const HatchParams& params);

// kBadParameter for a spacing outside [1, kCoordMax]. Lines are numbered from `first_index`
// in the order they are laid (triangles, then levels).
Status draw_hatch_lines(const Topology& topo, const uint8_t* front, const FaceGrid& fg,
                        const HatchParams& params, uint32_t first_index, LineSink sink,
                        HatchLineStats* stats, LineRows rows = LineRows{});

}  // namespace haloplot
