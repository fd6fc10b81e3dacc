#pragma once
// The ray tree as JSON for tools (`snell explain --json FILE`); the format is docs/explain.schema.json.
#include <string>

#include "snell/render/explain/explain_pixel.hpp"

namespace snell::render::explain {

std::string tree_json(const PixelExplanation& explanation, const std::string& scene_file);

}  // namespace snell::render::explain
