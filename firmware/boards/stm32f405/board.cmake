# The STM32F405 board (QEMU: netduinoplus2): what firmware/CMakeLists.txt asks of a board.
#   haloplot_fw_board        its start-up, drivers and instruction counter, with this folder on
#                            the include path (board/board.h names the Board type);
#   HALOPLOT_BOARD_LINKER    its linker script;
#   HALOPLOT_BOARD_STEP_ISR  the interrupt the step path starts from (the division gate);
#   HALOPLOT_BOARD_FLASH_BUDGET, _RAM_BUDGET  the image gates' limits, bytes;
#   HALOPLOT_BOARD_ARENA_KB  the controller's job arena.
add_library(haloplot_fw_board STATIC
  ${CMAKE_CURRENT_LIST_DIR}/startup/startup.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drivers/instruction_counter.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drivers/gpio.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drivers/step_timer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drivers/servo_pwm.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drivers/usart.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drivers/watchdog.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drivers/limit_switches.cpp)
set(HALOPLOT_BOARD_LINKER ${PROJECT_SOURCE_DIR}/linker/stm32f405.ld)
# SysTick is the step clock: its handler is the controller's step interrupt itself.
set(HALOPLOT_BOARD_STEP_ISR step_timer_irq)
# Flash: 144 KB of the F405's 1 MB since the controller walks curve gaps by arc length and
# re-plots curves, and simplifies strokes (128 KB before, for solids in bands; 96 KB for
# Franklin's hidden surfaces and hatching); the gate is there to catch a library or a table
# creeping in, not to fit the part. RAM: the 128 KB SRAM less the 16 KB stack.
set(HALOPLOT_BOARD_FLASH_BUDGET 147456)
set(HALOPLOT_BOARD_RAM_BUDGET 114688)
set(HALOPLOT_BOARD_ARENA_KB 96)
