#pragma once
// Pigments built from patterns: a value pattern through a wave and a colour map, or a block pattern
// choosing between sub-pigments (each may itself be patterned).
#include <memory>
#include <vector>

#include "snell/material/pigment.hpp"
#include "snell/texture/color_map.hpp"
#include "snell/texture/pattern.hpp"
#include "snell/texture/wave.hpp"

namespace snell::texture {

class MappedPigment final : public material::Pigment {
 public:
  MappedPigment(std::shared_ptr<const ValuePattern> pattern, ColorMap map, WaveShaping wave)
      : pattern_(std::move(pattern)), map_(std::move(map)), wave_(wave) {}
  material::Rgbft at(const material::PatternPoint& point) const override {
    return map_.at(wave_.apply(pattern_->value(point.p)));
  }

 private:
  std::shared_ptr<const ValuePattern> pattern_;
  ColorMap map_;
  WaveShaping wave_;
};

class BlockPigment final : public material::Pigment {
 public:
  /// `entries` has exactly pattern->block_count() pigments.
  BlockPigment(std::shared_ptr<const BlockPattern> pattern,
               std::vector<std::shared_ptr<const material::Pigment>> entries)
      : pattern_(std::move(pattern)), entries_(std::move(entries)) {}
  material::Rgbft at(const material::PatternPoint& point) const override {
    return entries_[pattern_->block(point.p)]->at(point);
  }

 private:
  std::shared_ptr<const BlockPattern> pattern_;
  std::vector<std::shared_ptr<const material::Pigment>> entries_;
};

}  // namespace snell::texture
