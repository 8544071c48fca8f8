// The float gate's bad case (tests/rules/float_gate_plant.sh): one function that computes in
// double, compiled with the core's own flags and added to a copy of the core library, which the
// gate (cmake/check_no_float.cmake) must then refuse. A soft-float CPU (the M0+, RV32IMAC) calls
// software routines for it (__aeabi_dmul, __muldf3); the M4F's single-precision FPU has no
// double either.
#include <stdint.h>

int32_t planted_scale(int32_t a, int32_t b) {
  return static_cast<int32_t>(static_cast<double>(a) * b / 3.0);
}
