#pragma once
// `mandel n [exponent e]`, `julia <c>, n [exponent e]` (POV-Ray 3.7 reference, "mandel", "julia") and
// `magnet 1|2 mandel n` / `magnet 1|2 julia <c>, n` ("magnet"); iteration and colouring as in POV-Ray's
// pattern.cpp: the point is the complex number x + iy.
#include "snell/texture/pattern.hpp"

namespace snell::texture {

/// How points that escape (exterior) or stay (interior) are valued, after POV-Ray's FractalPattern
/// ExteriorColour/InteriorColour. Exterior types: 0 the factor, 1 iterations / n (no factor, as POV-Ray),
/// 2 and 3 the real and imaginary parts, 4 and 5 their squares, 6 the modulus (each times the factor),
/// 7 iterations mod f over f, 8 iterations mod (1 + f) over f. Interior types: 0 the factor, 1 the closest
/// approach to 0, 2-5 as exterior, 6 re^2 + im^2 * factor (POV-Ray's operator precedence).
struct FractalShading {
  int max_iterations = 1;
  /// The power of z for mandel and julia, 2 to 33.
  int exponent = 2;
  int interior_type = 0;
  double interior_factor = 1;
  int exterior_type = 1;
  double exterior_factor = 1;
};

/// The value of a point that escaped after `iteration` steps (0-based) at z = re + i im.
double fractal_exterior(const FractalShading& s, int iteration, double re, double im);
/// The value of a point still bounded after all iterations at z, closest squared distance to 0 `closest2`.
double fractal_interior(const FractalShading& s, double re, double im, double closest2);

class MandelPattern final : public ValuePattern {
 public:
  explicit MandelPattern(const FractalShading& shading) : shading_(shading) {}
  double value(const Vec3& p) const override;

 private:
  FractalShading shading_;
};

class JuliaPattern final : public ValuePattern {
 public:
  JuliaPattern(double c_real, double c_imaginary, const FractalShading& shading)
      : c_real_(c_real), c_imaginary_(c_imaginary), shading_(shading) {}
  double value(const Vec3& p) const override;

 private:
  double c_real_, c_imaginary_;
  FractalShading shading_;
};

/// `magnet`: the renormalisation maps of the Ising model ("magnet" fractals),
/// type 1: z -> ((z^2 + c - 1) / (2z + c - 2))^2,
/// type 2: z -> ((z^3 + 3(c-1)z + (c-1)(c-2)) / (3z^2 + 3(c-2)z + (c-1)(c-2) + 1))^2,
/// from z = 0 with c the point (mandel) or from the point with a fixed c (julia); a point escapes when
/// |z|^2 > 10000 or it has converged to the fixed point 1 (|z-1|^2 < 1e-4).
struct MagnetParams {
  int type = 1;
  bool julia = false;
  double c_real = 0, c_imaginary = 0;
};

class MagnetPattern final : public ValuePattern {
 public:
  MagnetPattern(const MagnetParams& params, const FractalShading& shading)
      : params_(params), shading_(shading) {}
  double value(const Vec3& p) const override;

 private:
  MagnetParams params_;
  FractalShading shading_;
};

}  // namespace snell::texture
