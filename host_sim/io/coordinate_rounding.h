// How far a model file's stored coordinates may lie from the ones its exporter meant: the
// rounding of printed decimals or of binary floats. mesh_repair.h uses it to weld the corners
// one point became and to tell faces that are flat but for that rounding (pipeline/scene_input
// turns it into world units).
//
// The bound per coordinate, in file units, M the largest coordinate magnitude in the file:
// - text (OBJ, ASCII STL, ASCII PLY): half a unit in the last printed place. A file printed
//   with a fixed number of decimals D ("%f") rounds each coordinate by at most 0.5 * 10^-D; one
//   printed with S significant digits ("%g", "%e") by at most 0.5 * 10^(1-S) * M. Which way the
//   exporter printed is not known, so the larger of the two, D and S the most the file shows
//   (a shorter number is a longer one with its trailing zeros left off). Never below the
//   float32 bound below. A file none of whose coordinates shows 6 significant digits was not
//   rounded by an exporter (they print at least 6): its numbers are taken as exact as written,
//   to the float32 bound. Most exporters compute in float32 (Blender, Maya, MilkShape, 3ds Max),
//   so digits past float32's are noise (assimp's OBJ/regr01.obj prints 8 decimals of corners
//   that differ by one float32 step: 19.99987030 and 19.99987221).
// - float32 (binary STL and PLY): storing rounds by at most 2^-24 * M (half a float32 step of
//   the largest magnitude); twice that, 2^-23 * M, allows for the exporter's own float32
//   arithmetic before it stored the value (a transform rounds each product and sum once more).
// - float64 (binary PLY): 2^-52 * M, the same way; integer coordinates: exact.
#pragma once
#include <string_view>

namespace haloplot::host {

class CoordinateRounding {
 public:
  // A coordinate as printed ("-12.5", "1.25e-3", "7"): its decimals and significant digits.
  void note_text(std::string_view number);
  // Binary coordinates with `mantissa_bits` bits after the point (23 for float32, 52 for
  // float64; 0 for integers, exact).
  void note_binary(int mantissa_bits);
  // The bound per coordinate in file units, given the largest coordinate magnitude M.
  double bound(double magnitude) const;

 private:
  bool text_ = false;
  int decimals_ = -1000;  // the most decimals any printed coordinate shows (10^-decimals)
  int significant_ = 0;   // the most significant digits any printed coordinate shows
  int binary_bits_ = -1;  // the fewest mantissa bits of a binary coordinate (-1: none seen)
};

}  // namespace haloplot::host
