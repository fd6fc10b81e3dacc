#include "snell/render/explain/object_label.hpp"

#include <fmt/core.h>

#include "snell/geometry/shape.hpp"

namespace snell::render::explain {

std::string object_kind(const scene::Object& object) {
  return object.shape ? std::string(object.shape->kind()) : std::string("csg");
}

std::string object_label(const scene::Object& object) {
  const std::string where = object.where.to_string();
  if (object.name.empty()) return fmt::format("{} ({})", object_kind(object), where);
  return fmt::format("{} \"{}\" ({})", object_kind(object), object.name, where);
}

}  // namespace snell::render::explain
