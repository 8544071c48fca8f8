// The whole freestanding core in one include: status codes, the numeric contract, CUT, DRAW.
#pragma once
#include "cut/cut.h"
#include "cut/cutset.h"
#include "cut/grid.h"
#include "draw/draw.h"
#include "draw/halo.h"
#include "geometry/contract.h"
#include "geometry/fraction.h"
#include "geometry/predicates.h"
#include "geometry/wide.h"
#include "status/status.h"
