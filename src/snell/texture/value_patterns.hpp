#pragma once
// POV-Ray's geometric value patterns (POV-Ray 3.7 reference, "Patterns"; definitions as in POV-Ray's
// pattern.cpp). Values are raw: the wave shaping (texture/wave.hpp) folds them into [0,1].
#include "snell/texture/pattern.hpp"
#include "snell/texture/povray_noise.hpp"

namespace snell::texture {

/// `gradient <v>`: dot(p, v), reduced modulo 1 above 1 (so a point at exactly 1 keeps the value 1).
class GradientPattern final : public ValuePattern {
 public:
  explicit GradientPattern(const Vec3& direction) : direction_(direction) {}
  double value(const Vec3& p) const override;

 private:
  Vec3 direction_;
};

/// `onion`: concentric spheres about the origin, the distance modulo 1.
class OnionPattern final : public ValuePattern {
 public:
  double value(const Vec3& p) const override;
};

/// `spherical`: 1 at the origin falling linearly to 0 at distance 1, and 0 beyond.
class SphericalPattern final : public ValuePattern {
 public:
  double value(const Vec3& p) const override;
};

/// `cylindrical`: like spherical, with the distance from the y axis.
class CylindricalPattern final : public ValuePattern {
 public:
  double value(const Vec3& p) const override;
};

/// `planar`: like spherical, with the distance from the x-z plane.
class PlanarPattern final : public ValuePattern {
 public:
  double value(const Vec3& p) const override;
};

/// `boxed`: like spherical, with the max-norm distance (1 at the origin, 0 on and outside the unit box).
class BoxedPattern final : public ValuePattern {
 public:
  double value(const Vec3& p) const override;
};

/// `radial`: the angle around the y axis as a fraction of a turn: 0 (mod 1) on +x, then 0.25 on -z,
/// 0.5 on -x and 0.75 on +z; 0.25 on the axis itself.
class RadialPattern final : public ValuePattern {
 public:
  double value(const Vec3& p) const override;
};

/// `leopard`: ((sin x + sin y + sin z) / 3)^2, regular spots.
class LeopardPattern final : public ValuePattern {
 public:
  double value(const Vec3& p) const override;
};

/// `bozo` / `spotted`: smooth noise in [0,1], POV-Ray's Noise() from the pattern's `noise_generator`.
class BozoPattern final : public ValuePattern {
 public:
  explicit BozoPattern(NoiseChoice noise = {}) : noise_(std::move(noise)) {}
  double value(const Vec3& p) const override;

 private:
  NoiseChoice noise_;
};

}  // namespace snell::texture
