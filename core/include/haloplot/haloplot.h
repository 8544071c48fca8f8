// The whole freestanding core in one include, stage by stage as a plot flows through it. Each
// header can also be included on its own, as <haloplot/<folder>/<file>.h>.
#pragma once
// Status codes, the numeric contract, caller-owned memory and the sized-stage protocol.
#include "haloplot/geometry/contract.h"
#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/predicates.h"
#include "haloplot/geometry/wide.h"
#include "haloplot/memory/sized_stage.h"
#include "haloplot/status/status.h"
// Scenes and views: generated scenes, the projection of a model and each face's facing.
#include "haloplot/scene/cube_array.h"
#include "haloplot/scene/random_edges.h"
#include "haloplot/view/facing.h"
#include "haloplot/view/projection.h"
// HALO: CUT finds every crossing, DRAW cuts the halo gaps.
#include "haloplot/cut/cut.h"
#include "haloplot/cut/cutset.h"
#include "haloplot/cut/grid.h"
#include "haloplot/draw/draw.h"
#include "haloplot/draw/halo.h"
// Hidden lines and surfaces of solids, and the visible edges of a polygon from a point.
#include "haloplot/solid/hidden_lines.h"
#include "haloplot/surface/hidden_surface.h"
#include "haloplot/view2d/polygon_view.h"
// A job (pieces to strokes, the pen path), bands in a fixed arena, motion and the step tick.
#include "haloplot/band/conductor.h"
#include "haloplot/controller/motion_runner.h"
#include "haloplot/job/job.h"
#include "haloplot/motion/machine.h"
#include "haloplot/motion/planner.h"
#include "haloplot/motion/step_engine.h"
#include "haloplot/motion/step_prep.h"
#include "haloplot/motion/virtual_run.h"
// The controller's side of the link, and the step trace.
#include "haloplot/protocol/job_server.h"
#include "haloplot/trace/trace_encoder.h"
#include "haloplot/trace/traced_queue.h"
