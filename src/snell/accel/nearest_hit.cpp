#include "snell/accel/nearest_hit.hpp"

namespace snell::accel {

PlainTriangle plain_triangle(const scene::Object& object) {
  if (object.csg || object.motion || object.bounded_by) return {};
  const auto* shape = dynamic_cast<const geometry::Triangle*>(object.shape.get());
  if (!shape) return {};
  return {.object = &object,
          .shape = shape,
          .transform = object.transform.is_identity() ? nullptr : &object.transform,
          .vertices = shape->vertices(),
          .smooth = shape->smooth(),
          .inverse = object.flags.inverse};
}

std::vector<PlainTriangle> plain_triangles(const std::vector<const scene::Object*>& objects) {
  std::vector<PlainTriangle> out;
  out.reserve(objects.size());
  for (const scene::Object* o : objects) out.push_back(plain_triangle(*o));
  return out;
}

}  // namespace snell::accel
