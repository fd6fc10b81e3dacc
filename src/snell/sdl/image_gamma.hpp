#pragma once
#include "snell/io/image.hpp"

namespace snell::sdl {

/// POV-Ray 3.7 decodes an image by its file gamma (sRGB, about 2.2, for the usual 8-bit files) into the
/// scene's working gamma: stored^(file_gamma / assumed_gamma). Used by image_map and imported meshes.
void decode_gamma(io::Image& image, double file_gamma, double assumed_gamma);

}  // namespace snell::sdl
