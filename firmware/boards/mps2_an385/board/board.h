// The board this image is built for, checked against hal/include/haloplot/hal/board_hal.h at
// compile time: a board that lacks a capability fails here with the name of the missing function.
#pragma once
#include "board/mps2_an385_board.h"
#include "haloplot/hal/board_hal.h"  // hal/: the contract

namespace haloplot::fw {

using Board = Mps2An385Board;
static_assert(hal::check_board<Board>(),
              "the firmware's board (hal/include/haloplot/hal/board_hal.h)");

}  // namespace haloplot::fw
