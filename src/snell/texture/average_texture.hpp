#pragma once
// `texture { average texture_map { [w1 T1] [w2 T2] ... } }` (POV-Ray 3.7 reference, "Average"): the
// weighted mean of several textures. POV-Ray lights each entry with its own finish and averages the
// colours; snell folds the entries into one texture instead: the weighted mean of their pigments and of
// their bent normals, with the finish of the entry that weighs most. Entries that are themselves
// patterned or layered take part with their top layer's pigment and normal.
#include <memory>
#include <utility>
#include <vector>

#include "snell/material/texture.hpp"

namespace snell::texture {

/// Sets `out`'s pigment, normal and finish to the average of `entries` (weight, texture). Throws
/// std::invalid_argument when the weights sum to zero.
void average_textures(const std::vector<std::pair<double, std::shared_ptr<const material::Texture>>>& entries,
                      material::Texture& out);

}  // namespace snell::texture
