#pragma once
// `mandel n` and `julia <c>, n` (POV-Ray 3.7 reference, "mandel", "julia"; colouring as in POV-Ray's
// pattern.cpp): z -> z^2 + c in the x-y plane, iterated until |z| > 2 or n times.
#include "snell/texture/pattern.hpp"

namespace snell::texture {

/// How points that escape (exterior) or stay (interior) are valued. Types: 0 the factor itself,
/// 1 iterations / n (exterior) or the closest approach to 0 (interior), 2 and 3 the final real and
/// imaginary parts; each times its factor.
struct FractalShading {
  int max_iterations = 1;
  int interior_type = 0;
  double interior_factor = 1;
  int exterior_type = 1;
  double exterior_factor = 1;
};

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

}  // namespace snell::texture
