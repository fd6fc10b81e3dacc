#include "snell/sdl/parsed_object.hpp"

namespace snell::sdl {

void ParsedObject::apply(const math::Transform& t) {
  transform = t * transform;
  if (texture) {
    auto moved = std::make_shared<material::Texture>(*texture);
    moved->transform = t * moved->transform;
    texture = std::move(moved);
  }
}

namespace {

scene::ObjectFlags merge(const scene::ObjectFlags& own, const scene::ObjectFlags& inherited) {
  scene::ObjectFlags f = own;
  f.no_shadow = own.no_shadow || inherited.no_shadow;
  f.no_image = own.no_image || inherited.no_image;
  f.no_reflection = own.no_reflection || inherited.no_reflection;
  f.hollow = own.hollow || inherited.hollow;
  f.double_illuminate = own.double_illuminate || inherited.double_illuminate;
  // `inverse` on a union would turn it into an intersection of complements: not a per-child flag.
  return f;
}

void flatten_into(const ParsedObject& o, const math::Transform& parent,
                  const std::shared_ptr<const material::Texture>& inherited_texture,
                  const std::shared_ptr<const material::Interior>& inherited_interior,
                  const scene::ObjectFlags& inherited_flags, const std::string& inherited_name,
                  std::vector<std::shared_ptr<const scene::Object>>& objects,
                  std::vector<scene::Light>& lights) {
  const math::Transform to_world = parent * o.transform;
  std::shared_ptr<const material::Texture> texture = inherited_texture;
  if (o.texture) {
    if (parent.is_identity()) {
      texture = o.texture;
    } else {
      auto placed = std::make_shared<material::Texture>(*o.texture);
      placed->transform = parent * placed->transform;
      texture = std::move(placed);
    }
  }
  const auto interior = o.interior ? o.interior : inherited_interior;
  const scene::ObjectFlags flags = merge(o.flags, inherited_flags);
  const std::string& name = o.name.empty() ? inherited_name : o.name;

  if (o.light) {
    scene::Light light = *o.light;
    light.position = to_world.point(light.position);
    light.point_at = to_world.point(light.point_at);
    light.axis1 = to_world.vector(light.axis1);
    light.axis2 = to_world.vector(light.axis2);
    lights.push_back(light);
  }
  if (o.shape) {
    auto object = std::make_shared<scene::Object>();
    object->shape = o.shape;
    object->transform = to_world;
    object->texture = texture ? texture : material::Texture::default_texture();
    object->interior = interior;
    object->flags = flags;
    object->name = name;
    object->where = o.where;
    objects.push_back(std::move(object));
  }
  for (const auto& child : o.children)
    flatten_into(child, to_world, texture, interior, flags, name, objects, lights);
}

}  // namespace

void flatten(const ParsedObject& object, std::vector<std::shared_ptr<const scene::Object>>& objects,
             std::vector<scene::Light>& lights) {
  flatten_into(object, math::Transform{}, nullptr, nullptr, scene::ObjectFlags{}, "", objects, lights);
}

}  // namespace snell::sdl
