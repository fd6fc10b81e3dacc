#pragma once
// Pigments built from patterns (POV-Ray 3.7 reference, "Pattern Pigments", "Color Maps", "Pigment
// Maps"): a value pattern through a wave into a colour map or a pigment map, or a block pattern (checker,
// hexagon, brick) choosing between sub-pigments. Warps (in-pigment transforms, turbulence) move the point
// the pattern is looked up at; sub-pigments are evaluated at the unwarped point, as in POV-Ray (where an
// outer transform reaches them because the parser transforms them too: see TransformedPigment).
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "snell/geometry/surface_uv.hpp"
#include "snell/material/pigment.hpp"
#include "snell/math/transform.hpp"
#include "snell/texture/color_map.hpp"
#include "snell/texture/pattern.hpp"
#include "snell/texture/warp.hpp"
#include "snell/texture/wave.hpp"

namespace snell::texture {

using PigmentPtr = std::shared_ptr<const material::Pigment>;

/// `pigment_map { [v pigment {..}] ... }`: pigments at sorted values, their colours blended linearly
/// between neighbouring entries and held outside the first and last.
class PigmentMap {
 public:
  using Entry = std::pair<double, PigmentPtr>;
  explicit PigmentMap(std::vector<Entry> entries);
  material::Rgbft at(double value, const material::PatternPoint& point) const;
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::vector<Entry> entries_;
};

/// Everything a patterned pigment is made of; the parser fills one in, possibly starting from a declared
/// pigment's (`pigment { Ident turbulence 0.3 }`).
struct PatternSpec {
  std::shared_ptr<const ValuePattern> value_pattern;  // exactly one of value_pattern, block_pattern
  std::shared_ptr<const BlockPattern> block_pattern;
  WaveShaping wave;
  WarpList warps;
  std::optional<ColorMap> color_map;      // value pattern: colour map (the default one when neither)
  std::optional<PigmentMap> pigment_map;  // value pattern: pigment map
  std::vector<PigmentPtr> block_entries;  // block pattern: one pigment per block
};

class PatternPigment final : public material::Pigment {
 public:
  /// Throws std::invalid_argument when the spec is inconsistent (no pattern, wrong entry count).
  explicit PatternPigment(PatternSpec spec);
  material::Rgbft at(const material::PatternPoint& point) const override;
  /// A colour map blends its entries, so it transmits only if an entry does; likewise the sub-pigments.
  bool may_transmit() const override { return may_transmit_; }
  const PatternSpec& spec() const { return spec_; }

 private:
  /// Known once the spec is: shadow rays ask it at every blocker (a granite map has 20-odd entries).
  bool any_entry_transmits() const;

  PatternSpec spec_;
  bool may_transmit_ = true;
};

/// A pigment moved by `transform` as a whole, sub-pigments and turbulence included: what a transform
/// after a pigment identifier or after a pigment map's entries does in POV-Ray.
class TransformedPigment final : public material::Pigment {
 public:
  TransformedPigment(PigmentPtr inner, const math::Transform& transform)
      : inner_(std::move(inner)), transform_(transform) {}
  material::Rgbft at(const material::PatternPoint& point) const override;
  bool is_constant() const override { return inner_->is_constant(); }
  bool may_transmit() const override { return inner_->may_transmit(); }

 private:
  PigmentPtr inner_;
  math::Transform transform_;
};

/// `uv_mapping` (POV-Ray 3.7 reference, "UV Mapping"): the inner pigment sees the surface's (u, v, 0)
/// instead of the point in space; transforms written after uv_mapping move the pattern within uv space.
class UvMappedPigment final : public material::Pigment {
 public:
  explicit UvMappedPigment(PigmentPtr inner) : inner_(std::move(inner)) { geometry::request_surface_uv(); }
  material::Rgbft at(const material::PatternPoint& point) const override;
  bool is_constant() const override { return inner_->is_constant(); }
  bool may_transmit() const override { return inner_->may_transmit(); }

 private:
  PigmentPtr inner_;
};

/// `transform` applied to `pigment`, skipping the wrapper where it changes nothing.
PigmentPtr transform_pigment(const PigmentPtr& pigment, const math::Transform& transform);

}  // namespace snell::texture
