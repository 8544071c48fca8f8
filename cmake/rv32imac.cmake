# A toolchain file for a 32-bit RISC-V microcontroller without FPU (RV32IMAC, the ilp32 ABI:
# GD32VF103, ESP32-C3-class and SiFive E31-class cores), with Debian's bare-metal toolchain
# (gcc-riscv64-unknown-elf: one compiler for RV32 and RV64, picked by -march/-mabi). No board:
#   cmake -S . -B build/rv32 -DCMAKE_TOOLCHAIN_FILE=cmake/rv32imac.cmake -DCMAKE_BUILD_TYPE=MinSizeRel
#   cmake --build build/rv32 && cmake --install build/rv32 --prefix /opt/haloplot-rv32imac
# builds and installs haloplot::core and haloplot::hal for it (docs/porting.md, "RISC-V"). For
# another RISC-V CPU, copy this file and change -march/-mabi (the float gate refuses any
# floating-point instruction the F or D extension would bring into the core).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)
set(CMAKE_C_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_CXX_COMPILER riscv64-unknown-elf-g++)
set(CMAKE_ASM_COMPILER riscv64-unknown-elf-gcc)
# Only compile-test static libraries while CMake probes the compiler: there is no OS to link.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(rv32_flags "-march=rv32imac -mabi=ilp32 -mcmodel=medlow -ffunction-sections -fdata-sections")
set(CMAKE_C_FLAGS_INIT "${rv32_flags}")
set(CMAKE_CXX_FLAGS_INIT "${rv32_flags}")
set(CMAKE_ASM_FLAGS_INIT "-march=rv32imac -mabi=ilp32")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
