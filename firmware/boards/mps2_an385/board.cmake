# The Arm MPS2 board with the AN385 FPGA image (a Cortex-M3 and CMSDK peripherals at 25 MHz;
# QEMU: mps2-an385): what firmware/CMakeLists.txt asks of a board (the variables are listed in
# boards/stm32f405/board.cmake).
add_library(haloplot_fw_board STATIC
  ${CMAKE_CURRENT_LIST_DIR}/startup/startup.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drivers/instruction_counter.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drivers/gpio.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drivers/step_timer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drivers/uart.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drivers/watchdog.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drivers/limit_switches.cpp)
set(HALOPLOT_BOARD_LINKER ${PROJECT_SOURCE_DIR}/linker/mps2_an385.ld)
# The step clock is the CMSDK APB timer 0: its interrupt acknowledges the timer and calls the
# controller's step interrupt (drivers/step_timer.cpp).
set(HALOPLOT_BOARD_STEP_ISR timer0_irq_handler)
# The same budgets as the STM32F405 (the AN385 has 4 MB of each, but the gates are there to
# catch growth, and the same job arena runs the same jobs).
set(HALOPLOT_BOARD_FLASH_BUDGET 147456)
set(HALOPLOT_BOARD_RAM_BUDGET 114688)
set(HALOPLOT_BOARD_ARENA_KB 96)
