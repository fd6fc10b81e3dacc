#pragma once
#include <memory>
#include <utility>
#include <vector>

#include "snell/material/finish.hpp"
#include "snell/material/normal.hpp"
#include "snell/material/pigment.hpp"
#include "snell/math/transform.hpp"

namespace snell::material {

struct Texture;

/// A texture made of other textures chosen per point (POV-Ray 3.7 reference, "Texture Maps": `texture_map`
/// and checker/hexagon/brick of textures). The entries' transforms are relative to the mapped texture's
/// space, so moving the mapped texture moves them along.
class TextureSelector {
 public:
  virtual ~TextureSelector() = default;
  /// The entries around the pattern's value at `point` (in the mapped texture's space): `second`
  /// weighs `weight`, `first` the rest; `second` is null when one entry covers the point.
  struct Choice {
    const Texture* first = nullptr;
    const Texture* second = nullptr;
    double weight = 0;
    /// Where the entries are evaluated: the point as the map's warps leave it (POV-Ray trace.cpp,
    /// ComputeOneTextureColour evaluates an entry at the warped point).
    math::Vec3 point{};
  };
  virtual Choice at(const PatternPoint& point) const = 0;
};

/// POV-Ray `texture { pigment normal finish }`. `transform` maps texture space to WORLD space: it holds the
/// texture's own transforms plus every transform applied to the object after the texture was attached, so
/// a pattern moves with its object exactly as in POV-Ray (which evaluates textures at the world point).
struct Texture {
  std::shared_ptr<const Pigment> pigment;
  /// `normal {}`: bends the shading normal; null for a smooth surface.
  std::shared_ptr<const Normal> normal;
  Finish finish;
  /// Set for a texture_map texture: then pigment, normal and finish come from the chosen entries.
  std::shared_ptr<const TextureSelector> selector;
  math::Transform transform;
  /// The layer under this one (POV-Ray 3.7 reference, "Layered Textures": `texture {A} texture {B}` puts
  /// B on top of A; where B's pigment is transparent, A shows through). Null for a single texture.
  std::shared_ptr<const Texture> below;
  /// `average texture_map {..}` (POV-Ray trace.cpp, ComputeAverageTextureColours): the entries with their
  /// weights, already placed in world space. The renderer lights each entry on its own and averages the
  /// results; pigment, normal and finish above hold one blended stand-in for shadows and other uses.
  std::vector<std::pair<double, std::shared_ptr<const Texture>>> averaged;

  /// This texture with `t` applied after its transforms, on every layer.
  std::shared_ptr<const Texture> transformed(const math::Transform& t) const;
  /// Applies `t` after this texture's transforms in place: its own, its layers' and its averaged entries'.
  void move(const math::Transform& t);
  /// `top` placed over `bottom` (each may already be layered): a copy of top's chain ending on bottom.
  static std::shared_ptr<const Texture> layered(const std::shared_ptr<const Texture>& top,
                                                std::shared_ptr<const Texture> bottom);
  /// The pigment of the whole stack at a world point: each layer's colour over the ones below by its
  /// filter and transmit. `ray_direction` (unit) is the ray that met the point, for patterns that
  /// depend on it (`aoi`); zero where there is none.
  Rgbft pigment_at(const math::Vec3& world_point, const math::Vec3& world_normal, const math::Vec2& uv,
                   const math::Vec3& ray_direction = {}) const;

  /// The shading normal at a world point: `world_normal` (unit) bent by the first layer that has a
  /// `normal {}`, in that layer's texture space; `world_normal` itself when none has.
  math::Vec3 shading_normal(const math::Vec3& world_point, const math::Vec3& world_normal,
                            const math::Vec2& uv) const;

  /// False only when no point of the stack can let light through: some layer's pigment never transmits
  /// (it stops whatever the layers above pass on). Texture maps count as transmitting (not analysed).
  bool may_transmit() const;

  /// This layer alone, without the layers below: its pigment, and `world_normal` bent by its own
  /// `normal {}` (unchanged without one). POV-Ray lights each layer with its own finish and normal
  /// (trace.cpp, ComputeLightedTexture), which render/layered_shading.cpp follows.
  Rgbft own_pigment_at(const math::Vec3& world_point, const math::Vec3& world_normal, const math::Vec2& uv,
                       const math::Vec3& ray_direction = {}) const;
  math::Vec3 own_shading_normal(const math::Vec3& world_point, const math::Vec3& world_normal,
                                const math::Vec2& uv) const;

  /// The finish at a world point: this layer's own, or for a texture map the finish of the entry that
  /// weighs most there (finishes are not blended). Patterns that read the surface (`slope`, `aoi`) need
  /// `world_normal` (unit, as the pigment gets it) and `ray_direction`; zero where there are none.
  const Finish& finish_at(const math::Vec3& world_point, const math::Vec3& world_normal = {},
                          const math::Vec3& ray_direction = {}) const;

  /// One entry of a texture map as POV-Ray lights it on its own before blending the lit colours
  /// (trace.cpp, ComputeTextureColour): its pigment, its finish and the normal it bends (world space).
  struct MapEntry {
    Rgbft pigment;
    const Finish* finish = nullptr;
    math::Vec3 normal;
    double weight = 0;
  };
  /// For a texture map whose point falls between two entries: both of them into `out` and true; false
  /// for any other texture or a point one entry covers (then the blended values above are exact).
  /// `world_normal` is the hit's, `facing_normal` the one turned to the ray that the bumps bend.
  bool map_entries_at(const math::Vec3& world_point, const math::Vec3& world_normal,
                      const math::Vec3& facing_normal, const math::Vec2& uv, const math::Vec3& ray_direction,
                      MapEntry (&out)[2]) const;

  /// POV-Ray's default texture: black pigment, default finish.
  static std::shared_ptr<const Texture> default_texture();
};

}  // namespace snell::material
