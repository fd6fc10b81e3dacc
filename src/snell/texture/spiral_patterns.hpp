#pragma once
// Spirals around the z axis and the quilted pattern (POV-Ray 3.7 reference, "spiral1", "spiral2",
// "quilted"; definitions as in POV-Ray's pattern.cpp).
#include "snell/texture/pattern.hpp"

namespace snell::texture {

/// `spiral1 arms`: z + r + arms * angle / 2 pi around the z axis: a helical band for each arm.
class Spiral1Pattern final : public ValuePattern {
 public:
  explicit Spiral1Pattern(double arms) : arms_(arms) {}
  double value(const Vec3& p) const override;

 private:
  double arms_;
};

/// `spiral2 arms`: triangle(r) + triangle(z + r + arms * angle / 2 pi): two spirals crossing.
class Spiral2Pattern final : public ValuePattern {
 public:
  explicit Spiral2Pattern(double arms) : arms_(arms) {}
  double value(const Vec3& p) const override;

 private:
  double arms_;
};

/// `quilted control0 c0 control1 c1`: cushions in each unit cube. The distance from the cube's centre
/// goes through the cubic Bezier curve (0, c0, c1, 1), and the value is the mean |coordinate| of the
/// centre offset scaled by it.
class QuiltedPattern final : public ValuePattern {
 public:
  QuiltedPattern(double control0 = 1, double control1 = 1) : control0_(control0), control1_(control1) {}
  double value(const Vec3& p) const override;

 private:
  double control0_, control1_;
};

}  // namespace snell::texture
