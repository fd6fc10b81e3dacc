#include "snell/texture/noise_patterns.hpp"

#include <algorithm>
#include <cmath>

#include "snell/texture/povray_noise.hpp"

namespace snell::texture {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;

double cycloidal(double v) {
  return std::sin(v * kTwoPi);
}
}  // namespace

double MarblePattern::value(const Vec3& p) const {
  if (!turbulence_) return p.x;
  const TurbulenceParams& t = *turbulence_;
  return p.x + t.amount.x * povray_turbulence(p, t.octaves, t.lambda, t.omega, noise_.get());
}

double WoodPattern::value(const Vec3& p) const {
  double x = p.x, y = p.y;
  if (turbulence_) {
    const TurbulenceParams& t = *turbulence_;
    const Vec3 d = vector_turbulence(p, t.octaves, t.omega, t.lambda);
    x += cycloidal((p.x + d.x) * t.amount.x);
    y += cycloidal((p.y + d.y) * t.amount.y);
  }
  return std::sqrt(x * x + y * y);
}

double AgatePattern::value(const Vec3& p) const {
  const TurbulenceParams& t = turbulence_;
  const double turb = agate_turb_ * povray_turbulence(p, t.octaves, t.lambda, t.omega, noise_.get());
  const double v = 0.5 * (cycloidal(1.3 * turb + 1.1 * p.z) + 1.0);
  return std::pow(std::clamp(v, 0.0, 1.0), 0.77);
}

double GranitePattern::value(const Vec3& p) const {
  // POV-Ray's granite (pattern.cpp): six octaves at 4 times 1, 2, .., 32; generator 1 takes |0.5 - noise|,
  // generators 2 and 3 |1 - 2 noise| capped at 0.5. The six noises are computed together.
  const NoiseGenerator generator = noise_.get();
  constexpr int kOctaves = 6;
  static constexpr double kScales[kOctaves] = {4, 8, 16, 32, 64, 128};
  double noise[kOctaves];
  povray_noise_scaled(p, kScales, kOctaves, noise, generator);
  double sum = 0, frequency = 1;
  for (int i = 0; i < kOctaves; ++i, frequency *= 2) {
    const double n = noise[i];
    const double octave =
        generator == NoiseGenerator::original ? std::fabs(0.5 - n) : std::min(std::fabs(1.0 - 2.0 * n), 0.5);
    sum += octave / frequency;
  }
  return sum;
}

double WrinklesPattern::value(const Vec3& p) const {
  // POV-Ray's wrinkles (pattern.cpp): ten octaves of the noise as it is (generator 1) or of 2 noise - 0.5
  // clamped to [0, 1] (generators 2 and 3), at frequencies 1, 2, .., 512, computed together.
  const NoiseGenerator generator = noise_.get();
  constexpr int kOctaves = 10;
  static constexpr double kScales[kOctaves] = {1, 2, 4, 8, 16, 32, 64, 128, 256, 512};
  double noise[kOctaves];
  povray_noise_scaled(p, kScales, kOctaves, noise, generator);
  double sum = 0, amplitude = 1;
  for (int i = 0; i < kOctaves; ++i, amplitude *= 0.5) {
    const double n = noise[i];
    sum += amplitude * (generator == NoiseGenerator::original ? n : std::clamp(2.0 * n - 0.5, 0.0, 1.0));
  }
  return sum / 2;
}

Vec3 WrinklesPattern::bump(const Vec3& p) const {
  Vec3 sum{0, 0, 0};
  double frequency = 1;
  for (int i = 0; i < 10; ++i, frequency *= 2) sum = sum + abs(vector_noise(p * frequency)) * (1 / frequency);
  return sum;
}

double BumpsPattern::value(const Vec3& p) const {
  return povray_noise(p, noise_.get());
}

Vec3 BumpsPattern::bump(const Vec3& p) const {
  return vector_noise(p);
}

double DentsPattern::value(const Vec3& p) const {
  const double n = povray_noise(p, noise_.get());
  return n * n * n;
}

Vec3 DentsPattern::bump(const Vec3& p) const {
  return vector_noise(p) * value(p);
}

}  // namespace snell::texture
