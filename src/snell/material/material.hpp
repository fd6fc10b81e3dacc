#pragma once
#include <memory>

#include "snell/material/interior.hpp"
#include "snell/material/texture.hpp"

namespace snell::material {

/// POV-Ray `material { texture {..} interior {..} }` (POV-Ray 3.7 reference, "Material"): a texture and an
/// interior carried together. Either may be absent; an object keeps its own where the material has none.
struct Material {
  std::shared_ptr<const Texture> texture;
  std::shared_ptr<const Interior> interior;
};

}  // namespace snell::material
