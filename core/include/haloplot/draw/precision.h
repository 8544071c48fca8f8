// Compile-time precision policies for DRAW: one core, every mode, chosen by a template
// argument (draw_with<Precision> in draw.h). Two axes:
//
//   Sqrt      how the halo gets |dq| (the front edge's length, in Q10, rounded up) for the
//             paper's W / sin(theta):
//               SqrtExact   bit-pair integer root, exact ceiling (the default);
//               SqrtNewton  two Newton steps from a power-of-two seed: two 64-bit divisions,
//                           an upper bound within 2.5 % (always at least the true root);
//               SqrtTable   a 256-entry table on the top 8 bits of the square: no division,
//                           an upper bound within 0.8 %.
//             Every method errs upward, so a gap is never smaller than its definition.
//   Position  the grid of gap ends along an edge: Q0.32 (the default) or Q0.16, rounded
//             outward. Q16 halves the bits a position needs (a 16-bit field) at an error of
//             up to |edge| / 2^16 steps.
//
// The crossings themselves come from CUT's exact predicates in every mode: no policy here can
// miss a crossing or flip a front/back decision.
#pragma once
#include <stdint.h>

namespace haloplot {

struct SqrtExact {
  static constexpr const char* kName = "exact root";
  static uint64_t length_q10_ceil(int64_t dx, int64_t dy);
};
struct SqrtNewton {
  static constexpr const char* kName = "Newton, 2 steps";
  static uint64_t length_q10_ceil(int64_t dx, int64_t dy);
};
struct SqrtTable {
  static constexpr const char* kName = "table, 256";
  static uint64_t length_q10_ceil(int64_t dx, int64_t dy);
};

template <int kBits>
struct PositionBits {
  static_assert(kBits == 16 || kBits == 32, "Q0.16 or Q0.32 positions");
  static constexpr int kDrop = 32 - kBits;
  static constexpr int64_t kMask = (int64_t{1} << kDrop) - 1;
  // Outward to the grid: a gap's start down, its end up (two's complement & floors).
  static int64_t floor(int64_t t) { return t & ~kMask; }
  static int64_t ceil(int64_t t) { return (t + kMask) & ~kMask; }
};

template <typename SqrtT, typename PositionT>
struct DrawPrecision {
  using Sqrt = SqrtT;
  using Position = PositionT;
};

using DefaultDrawPrecision = DrawPrecision<SqrtExact, PositionBits<32>>;

}  // namespace haloplot
