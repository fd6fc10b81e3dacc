#pragma once
// `texture { pattern texture_map { [v texture] ... } }` and `texture { checker texture {A} texture {B} }`
// (POV-Ray 3.7 reference, "Texture Maps", "Patterned Textures"): the pattern picks, per point, the one or
// two entries whose pigments and normals are blended there.
#include <memory>
#include <utility>
#include <vector>

#include "snell/material/texture.hpp"
#include "snell/texture/pattern_pigment.hpp"

namespace snell::texture {

using TexturePtr = std::shared_ptr<const material::Texture>;

class PatternTextureSelector final : public material::TextureSelector {
 public:
  /// A value pattern with `map` entries (sorted here), or a block pattern with one texture per block.
  /// Throws std::invalid_argument when they do not fit the pattern.
  PatternTextureSelector(PatternSpec pattern, std::vector<std::pair<double, TexturePtr>> map,
                         std::vector<TexturePtr> blocks);
  Choice at(const material::PatternPoint& point) const override;

 private:
  PatternSpec pattern_;
  std::vector<std::pair<double, TexturePtr>> map_;
  std::vector<TexturePtr> blocks_;
};

}  // namespace snell::texture
