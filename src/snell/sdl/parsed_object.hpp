#pragma once
// An object while the scene is being parsed: POV-Ray's objects keep their CSG tree until the end of
// parsing (a declared union can be reused and transformed), so the parser holds this tree and flattens it
// into scene::Objects once the object is placed in the scene.
#include <memory>
#include <optional>
#include <vector>

#include "snell/scene/light.hpp"
#include "snell/scene/object.hpp"

namespace snell::sdl {

struct ParsedObject {
  /// How the children combine: a plain union is flattened into the scene (fast); the others become one
  /// scene::Object with a scene::Csg, and so does a union nested inside one of them.
  enum class Combine { union_of, merge, intersection, difference };

  /// Null for a union or CSG (children hold the parts) or a light.
  std::shared_ptr<const geometry::Shape> shape;
  std::optional<scene::Light> light;
  /// A light's `projected_through` object, in the light's space.
  std::shared_ptr<const ParsedObject> projected_through;
  std::vector<ParsedObject> children;
  Combine combine = Combine::union_of;
  /// `clipped_by` objects, in this object's own space (before `transform`).
  std::vector<ParsedObject> clipped_by;
  /// `bounded_by` objects, in its own space: their box culls rays (accel), and `clipped_by { bounded_by }`.
  std::vector<ParsedObject> bounded_by;
  /// Object space -> parent space, leaving out the motion blocks.
  math::Transform transform;
  /// `motion { ... }` blocks (motion blur), their frames mapping each block's space to parent space.
  std::vector<scene::MotionLayer> motion;
  /// Its transform maps texture space to parent space (the object's later transforms are folded in).
  std::shared_ptr<const material::Texture> texture;
  std::shared_ptr<const material::Interior> interior;
  scene::ObjectFlags flags;
  /// `uv_mapping` among the object's modifiers: pigments attached after it are looked up at (u, v, 0).
  bool uv_mapping = false;
  std::string name;
  scene::SourceLocation where;

  /// Applies `t` after everything so far: the object, its texture and (for a light) its position move.
  void apply(const math::Transform& t);
};

/// Nodes in the object's tree (itself, children, clipping and bounding objects); counting stops once the
/// total passes `limit`, so a tree that doubled itself many times is not walked to its end.
long long count_nodes(const ParsedObject& object, long long limit);

/// Flattens `object` into scene objects and lights: children get composed transforms and inherit the
/// union's texture, interior and flags where they have none of their own.
void flatten(const ParsedObject& object, std::vector<std::shared_ptr<const scene::Object>>& objects,
             std::vector<scene::Light>& lights);

}  // namespace snell::sdl
