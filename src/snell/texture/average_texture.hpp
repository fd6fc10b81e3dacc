#pragma once
// `texture { average texture_map { [w1 T1] [w2 T2] ... } }` (POV-Ray 3.7 reference, "Average"): the
// weighted mean of several textures. POV-Ray lights each entry with its own finish and averages the
// colours (trace.cpp, ComputeAverageTextureColours), and so does the Whitted integrator with the entries
// kept in Texture::averaged (render/average_shading.cpp). Where a texture is not lit (shadow rays, the
// path tracer, photons) the entries are folded into one stand-in: the weighted mean of their pigments and
// of their bent normals, with the finish of the entry that weighs most.
#include <memory>
#include <utility>
#include <vector>

#include "snell/material/texture.hpp"

namespace snell::texture {

/// Sets `out`'s averaged entries (placed by `out.transform`, which must be final) and its stand-in
/// pigment, normal and finish to the average of `entries` (weight, texture). Throws
/// std::invalid_argument when the weights sum to zero.
void average_textures(const std::vector<std::pair<double, std::shared_ptr<const material::Texture>>>& entries,
                      material::Texture& out);

}  // namespace snell::texture
