#pragma once
// The ray tree as an indented text tree, one ray per block (`snell explain` without --json).
#include <string>

#include "snell/render/explain/explain_pixel.hpp"

namespace snell::render::explain {

std::string tree_text(const PixelExplanation& explanation, const scene::Scene& scene);

}  // namespace snell::render::explain
