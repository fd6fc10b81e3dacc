#pragma once
// How explain output names an object: its shape, its #declare name when it has one, and where it was
// written (file:line:col), so a student can find it in the scene file.
#include <string>

#include "snell/scene/object.hpp"

namespace snell::render::explain {

/// "sphere", "plane", ... or "csg" for a CSG object.
std::string object_kind(const scene::Object& object);
/// `sphere "Glass" (scene.pov:12:3)`, or `sphere (scene.pov:12:3)` without a #declare name.
std::string object_label(const scene::Object& object);

}  // namespace snell::render::explain
