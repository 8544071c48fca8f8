# Cross toolchain for the plotter controller boards (arm-none-eabi, Thumb-2). The board
# (HALOPLOT_BOARD, a folder of firmware/boards/) names its CPU in its own cpu.cmake, which sets
# HALOPLOT_MCU_FLAGS: a port brings its flags with it and this file does not change.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_AR arm-none-eabi-ar)
set(CMAKE_RANLIB arm-none-eabi-ranlib)
set(CMAKE_SIZE arm-none-eabi-size)
set(CMAKE_NM arm-none-eabi-nm)

# Only compile-test static libraries while CMake probes the compiler: there is no OS to link.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

if(NOT HALOPLOT_BOARD)
  set(HALOPLOT_BOARD stm32f405)
endif()
set(HALOPLOT_BOARD ${HALOPLOT_BOARD} CACHE STRING "The controller board (a folder of firmware/boards/)")
# The try-compile projects CMake runs while probing see the same board.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES HALOPLOT_BOARD)
set(board_cpu ${CMAKE_CURRENT_LIST_DIR}/../firmware/boards/${HALOPLOT_BOARD}/cpu.cmake)
if(NOT EXISTS ${board_cpu})
  message(FATAL_ERROR "HALOPLOT_BOARD=${HALOPLOT_BOARD}: no ${board_cpu}")
endif()
include(${board_cpu})  # HALOPLOT_MCU_FLAGS

set(CMAKE_C_FLAGS_INIT "${HALOPLOT_MCU_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "${HALOPLOT_MCU_FLAGS} -ffunction-sections -fdata-sections -ffreestanding -fno-exceptions -fno-rtti")
set(CMAKE_ASM_FLAGS_INIT "${HALOPLOT_MCU_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-nostartfiles -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
