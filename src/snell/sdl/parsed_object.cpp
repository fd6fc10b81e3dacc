#include "snell/sdl/parsed_object.hpp"

#include "snell/scene/csg.hpp"

namespace snell::sdl {

void ParsedObject::apply(const math::Transform& t) {
  transform = t * transform;
  for (scene::MotionLayer& layer : motion) layer.frame = t * layer.frame;
  if (texture) texture = texture->transformed(t);
  interior = material::Interior::transformed(interior, t);
}

long long count_nodes(const ParsedObject& object, long long limit) {
  long long n = 1;
  for (const auto* list : {&object.children, &object.clipped_by, &object.bounded_by})
    for (const ParsedObject& child : *list) {
      if (n > limit) return n;
      n += count_nodes(child, limit - n);
    }
  return n;
}

namespace {

using ObjectPtr = std::shared_ptr<const scene::Object>;
using TexturePtr = std::shared_ptr<const material::Texture>;
using InteriorPtr = std::shared_ptr<const material::Interior>;

scene::ObjectFlags merge(const scene::ObjectFlags& own, const scene::ObjectFlags& inherited) {
  scene::ObjectFlags f = own;
  f.no_shadow = own.no_shadow || inherited.no_shadow;
  f.no_image = own.no_image || inherited.no_image;
  f.no_reflection = own.no_reflection || inherited.no_reflection;
  f.hollow = own.hollow || inherited.hollow;
  f.double_illuminate = own.double_illuminate || inherited.double_illuminate;
  f.photons = scene::inherit_photons(own.photons, inherited.photons);
  // `inverse` on a union would turn it into an intersection of complements: not a per-child flag.
  return f;
}

/// What a parent hands down to its children: placement and the texture, interior, flags and name they
/// fall back on.
struct Inherited {
  math::Transform to_world;
  TexturePtr texture;
  InteriorPtr interior;
  scene::ObjectFlags flags;
  std::string name;
  /// World box of the `bounded_by` objects of this object and its ancestors, if any.
  std::optional<math::Bounds3> bounded_by;
  /// Motion of this object and its ancestors up to the nearest CSG (which moves its children itself),
  /// outermost first, framed in world space.
  std::vector<scene::MotionLayer> motion;
};

/// `own` for the parts of a CSG object: the CSG object moves them, so they carry no inherited motion.
Inherited without_motion(Inherited own) {
  own.motion.clear();
  return own;
}

/// The object's own values resolved against its parent's.
Inherited resolve(const ParsedObject& o, const Inherited& parent) {
  Inherited r;
  r.to_world = parent.to_world * o.transform;
  r.texture = parent.texture;
  if (o.texture) {
    if (parent.to_world.is_identity()) {
      r.texture = o.texture;
    } else {
      r.texture = o.texture->transformed(parent.to_world);
    }
  }
  r.interior = o.interior ? material::Interior::transformed(o.interior, parent.to_world) : parent.interior;
  r.flags = merge(o.flags, parent.flags);
  r.name = o.name.empty() ? parent.name : o.name;
  r.bounded_by = parent.bounded_by;
  r.motion = parent.motion;
  for (scene::MotionLayer layer : o.motion) {
    layer.frame = parent.to_world * layer.frame;
    r.motion.push_back(std::move(layer));
  }
  return r;
}

void flatten_into(const ParsedObject& o, const Inherited& parent, std::vector<ObjectPtr>& objects,
                  std::vector<scene::Light>& lights);

void add_light(const ParsedObject& o, const math::Transform& to_world, std::vector<scene::Light>& lights) {
  scene::Light light = *o.light;
  if (o.projected_through) {
    Inherited placed;
    placed.to_world = to_world;
    std::vector<scene::Light> ignored;
    flatten_into(*o.projected_through, placed, light.projected_through, ignored);
  }
  light.position = to_world.point(light.position);
  light.point_at = to_world.point(light.point_at);
  light.axis1 = to_world.vector(light.axis1);
  light.axis2 = to_world.vector(light.axis2);
  lights.push_back(light);
}

std::shared_ptr<scene::Object> make_object(const ParsedObject& o, const Inherited& own) {
  auto object = std::make_shared<scene::Object>();
  object->transform = own.to_world;
  object->texture = own.texture ? own.texture : material::Texture::default_texture();
  object->interior = own.interior;
  object->flags = own.flags;
  object->name = own.name;
  object->where = o.where;
  object->bounded_by = own.bounded_by;
  if (!own.motion.empty()) {
    object->motion = std::make_shared<scene::Motion>(own.motion);
    if (object->bounded_by) object->bounded_by = object->motion->swept(*object->bounded_by);
  }
  return object;
}

ObjectPtr build(const ParsedObject& o, const Inherited& parent, std::vector<scene::Light>& lights);

/// Narrows `own.bounded_by` to the box of `o`'s bounded_by objects; a ray must hit every one of them
/// (POV-Ray reference, "Bounded_By"), so their boxes intersect. Their lights and flags play no part.
void add_user_bounds(const ParsedObject& o, Inherited& own) {
  if (o.bounded_by.empty()) return;
  math::Bounds3 box = own.bounded_by.value_or(math::Bounds3::infinite());
  Inherited space = without_motion(own);
  space.flags = {};
  std::vector<scene::Light> ignored;
  for (const auto& bound : o.bounded_by)
    if (ObjectPtr built = build(bound, space, ignored)) box = box.intersection(built->world_bounds());
  own.bounded_by = box;
}

/// One scene object for `o` and everything under it (a CSG object for unions and CSG), or null when
/// it holds only lights.
ObjectPtr build(const ParsedObject& o, const Inherited& parent, std::vector<scene::Light>& lights) {
  Inherited own = resolve(o, parent);
  add_user_bounds(o, own);
  if (o.light) add_light(o, own.to_world, lights);

  std::shared_ptr<scene::Object> object;
  if (o.shape) {
    object = make_object(o, own);
    object->shape = o.shape;
    object->bake_placement();
  } else if (!o.children.empty()) {
    std::vector<ObjectPtr> children;
    for (const auto& child : o.children) {
      ObjectPtr built = build(child, without_motion(own), lights);
      if (!built) continue;
      // POV-Ray's difference is the intersection of the first child with the complements of the others.
      if (o.combine == ParsedObject::Combine::difference && !children.empty()) {
        auto inverted = std::make_shared<scene::Object>(*built);
        inverted->flags.inverse = !inverted->flags.inverse;
        built = std::move(inverted);
      }
      children.push_back(std::move(built));
    }
    if (children.empty()) return nullptr;
    scene::CsgKind kind = scene::CsgKind::union_of;
    if (o.combine == ParsedObject::Combine::merge) kind = scene::CsgKind::merge;
    if (o.combine == ParsedObject::Combine::intersection || o.combine == ParsedObject::Combine::difference)
      kind = scene::CsgKind::intersection;
    object = make_object(o, own);
    object->transform = math::Transform{};  // the children carry the placement
    object->csg = std::make_shared<scene::Csg>(kind, std::move(children));
  }
  if (!object) return nullptr;
  if (o.clipped_by.empty()) return object;

  // clipped_by: the object's surface where it lies inside every clipping object (POV-Ray reference,
  // "Clipped_By"); the clipping objects are in the object's space and show no surface of their own.
  object->motion = nullptr;  // the clipped object moves as a whole
  std::vector<ObjectPtr> parts{object};
  Inherited clip_parent = without_motion(own);
  clip_parent.flags = {};
  for (const auto& clip : o.clipped_by)
    if (ObjectPtr built = build(clip, clip_parent, lights)) parts.push_back(std::move(built));
  auto clipped = make_object(o, own);
  clipped->transform = math::Transform{};
  clipped->flags.inverse = false;  // the inverse stays with the clipped object itself
  clipped->csg = std::make_shared<scene::Csg>(scene::CsgKind::intersection, std::move(parts), 1);
  return clipped;
}

void flatten_into(const ParsedObject& o, const Inherited& parent, std::vector<ObjectPtr>& objects,
                  std::vector<scene::Light>& lights) {
  const bool plain_union = !o.shape && o.combine == ParsedObject::Combine::union_of && !o.flags.inverse;
  if (!plain_union || !o.clipped_by.empty()) {
    if (ObjectPtr object = build(o, parent, lights)) objects.push_back(std::move(object));
    return;
  }
  Inherited own = resolve(o, parent);
  add_user_bounds(o, own);
  if (o.light) add_light(o, own.to_world, lights);
  for (const auto& child : o.children) flatten_into(child, own, objects, lights);
}

}  // namespace

void flatten(const ParsedObject& object, std::vector<std::shared_ptr<const scene::Object>>& objects,
             std::vector<scene::Light>& lights) {
  flatten_into(object, Inherited{}, objects, lights);
}

}  // namespace snell::sdl
