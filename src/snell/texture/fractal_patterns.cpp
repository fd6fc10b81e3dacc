#include "snell/texture/fractal_patterns.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace snell::texture {

using Complex = std::complex<double>;

namespace {

/// Types 2-5, the same for exterior and interior: the real or imaginary part of z, or its square.
double part_of_z(int type, double re, double im) {
  return type == 2 ? re : type == 3 ? im : type == 4 ? re * re : im * im;
}

}  // namespace

double fractal_exterior(const FractalShading& s, int iteration, double re, double im) {
  const double f = s.exterior_factor;
  const int type = s.exterior_type;
  if (type >= 2 && type <= 5) return part_of_z(type, re, im) * f;
  if (type == 0) return f;
  if (type == 1) return static_cast<double>(iteration) / s.max_iterations;
  if (type == 6) return std::sqrt(re * re + im * im) * f;
  if (type == 7 || type == 8) {
    // Iterations taken in bands of f (type 7) or 1 + f (type 8); a band width below 1 means none.
    const int band = static_cast<int>(type == 7 ? f : 1 + f);
    return band >= 1 && f != 0 ? (iteration % band) / f : 0.0;
  }
  return 0;
}

double fractal_interior(const FractalShading& s, double re, double im, double closest2) {
  const double f = s.interior_factor;
  const int type = s.interior_type;
  if (type >= 2 && type <= 5) return part_of_z(type, re, im) * f;
  if (type == 0) return f;
  if (type == 1) return std::sqrt(closest2) * f;
  if (type == 6) return re * re + im * im * f;  // sic: POV-Ray 3.7 scales only the imaginary square
  return 0;
}

namespace {

Complex power(Complex z, int n) {
  Complex out = z;
  for (int i = 1; i < n; ++i) out *= z;
  return out;
}

/// Iterates z -> z^exponent + c from z0 until |z| > 2 and values the result by `s`.
double escape_time(Complex z, Complex c, const FractalShading& s) {
  double closest2 = std::norm(z);
  for (int i = 0; i < s.max_iterations; ++i) {
    z = power(z, s.exponent) + c;
    const double d2 = std::norm(z);
    closest2 = std::min(closest2, d2);
    if (d2 > 4) return fractal_exterior(s, i, z.real(), z.imag());
  }
  return fractal_interior(s, z.real(), z.imag(), closest2);
}

Complex magnet_step(int type, Complex z, Complex c) {
  if (type == 1) {
    const Complex q = (z * z + c - 1.0) / (2.0 * z + c - 2.0);
    return q * q;
  }
  const Complex c1 = c - 1.0, c2 = c - 2.0;
  const Complex q = (z * z * z + 3.0 * c1 * z + c1 * c2) / (3.0 * z * z + 3.0 * c2 * z + c1 * c2 + 1.0);
  return q * q;
}

}  // namespace

double MandelPattern::value(const Vec3& p) const {
  const Complex c(p.x, p.y);
  return escape_time(c, c, shading_);
}

double JuliaPattern::value(const Vec3& p) const {
  return escape_time(Complex(p.x, p.y), Complex(c_real_, c_imaginary_), shading_);
}

double MagnetPattern::value(const Vec3& p) const {
  const Complex point(p.x, p.y);
  Complex z = params_.julia ? point : Complex(0, 0);
  const Complex c = params_.julia ? Complex(params_.c_real, params_.c_imaginary) : point;
  // POV-Ray starts the closest approach at 10000 for the mandel form, at |z0|^2 for the julia form.
  double closest2 = params_.julia ? std::norm(z) : 10000.0;
  for (int i = 0; i < shading_.max_iterations; ++i) {
    z = magnet_step(params_.type, z, c);
    const double d2 = std::norm(z);
    closest2 = std::min(closest2, d2);
    if (d2 > 10000 || std::norm(z - 1.0) < 1e-4) return fractal_exterior(shading_, i, z.real(), z.imag());
  }
  return fractal_interior(shading_, z.real(), z.imag(), closest2);
}

}  // namespace snell::texture
