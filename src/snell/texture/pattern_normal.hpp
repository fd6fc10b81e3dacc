#pragma once
// `normal { pattern [bump_size] [slope_map | normal_map] [accuracy a] modifiers }` (POV-Ray 3.7 reference,
// "Normal", "Slope Maps", "Normal Maps"; behaviour as in POV-Ray's normal.cpp):
// - bumps, dents, wrinkles, ripples and waves bend the normal their own way (texture::BumpSource);
// - bump_map and facets set the bent normal themselves (texture::NormalSetter);
// - every other value pattern bends it along minus its gradient, found by finite differences at the
//   four corners of a tetrahedron `accuracy` across, through the wave and the optional slope map;
// - a normal_map bends it by the two entries around the pattern's value, blended.
// The bending happens in pattern space (through the transforms written in the block), so a scaled
// pattern keeps the same depth of bumps.
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "snell/material/normal.hpp"
#include "snell/texture/pattern.hpp"
#include "snell/texture/warp.hpp"
#include "snell/texture/wave.hpp"

namespace snell::texture {

using NormalPtr = std::shared_ptr<const material::Normal>;

/// `slope_map { [v <height, slope>] ... }`: the pattern's value becomes a height through a cubic Hermite
/// curve through the entries, so the bending follows a chosen profile.
class SlopeMap {
 public:
  struct Entry {
    double value;
    double height;
    double slope;
  };
  explicit SlopeMap(std::vector<Entry> entries);
  double height(double value) const;

 private:
  std::vector<Entry> entries_;
};

struct NormalSpec {
  std::shared_ptr<const ValuePattern> pattern;
  WaveShaping wave;
  WarpList warps;
  /// POV-Ray's default depth of bumps.
  double bump_size = 0.5;
  /// Size of the finite-difference tetrahedron.
  double accuracy = 0.02;
  std::optional<SlopeMap> slope_map;
  /// `normal_map` entries, sorted by value; empty for none.
  std::vector<std::pair<double, NormalPtr>> normal_map;
  /// `uv_mapping`: the pattern is looked up at the surface's (u, v, 0).
  bool uv_mapping = false;
};

class PatternNormal final : public material::Normal {
 public:
  /// Throws std::invalid_argument without a pattern or with a non-positive accuracy.
  explicit PatternNormal(NormalSpec spec);
  math::Vec3 perturb(const math::Vec3& normal, const material::PatternPoint& point) const override;
  const NormalSpec& spec() const { return spec_; }

 private:
  /// Where the pattern is looked up before the warps: the point, or (u, v, 0) with uv_mapping.
  Vec3 pattern_point(const material::PatternPoint& point) const;
  /// The bending vector in pattern space at pattern point q.
  Vec3 bend(const Vec3& q) const;
  Vec3 perturb_by_map(const Vec3& normal, const material::PatternPoint& point) const;

  NormalSpec spec_;
};

/// A normal_map entry without a pattern: the normal unchanged.
class FlatNormal final : public material::Normal {
 public:
  math::Vec3 perturb(const math::Vec3& normal, const material::PatternPoint&) const override {
    return normal;
  }
};

/// A normal moved as a whole by `transform` (a transform after a declared normal).
class TransformedNormal final : public material::Normal {
 public:
  TransformedNormal(NormalPtr inner, const math::Transform& transform)
      : inner_(std::move(inner)), transform_(transform) {}
  math::Vec3 perturb(const math::Vec3& normal, const material::PatternPoint& point) const override;

 private:
  NormalPtr inner_;
  math::Transform transform_;
};

}  // namespace snell::texture
