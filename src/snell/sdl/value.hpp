#pragma once
// The values an identifier can hold. POV-Ray evaluates while it parses (no syntax tree), so `#declare`
// stores finished values: numbers, colours, strings, transforms, materials, objects and macros.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "snell/function/function.hpp"
#include "snell/material/interior.hpp"
#include "snell/material/material.hpp"
#include "snell/material/pigment.hpp"
#include "snell/material/texture.hpp"
#include "snell/scene/camera.hpp"
#include "snell/scene/scene.hpp"
#include "snell/sdl/parsed_object.hpp"
#include "snell/sdl/spline.hpp"
#include "snell/sdl/token.hpp"
#include "snell/texture/color_map.hpp"
#include "snell/texture/pattern_pigment.hpp"

namespace snell::sdl {

/// A float (size 1), a 2-5 component vector, or a colour (always 5: r g b filter transmit). POV-Ray
/// promotes floats to vectors and vectors to colours as the context asks.
struct Numeric {
  std::array<double, 5> v{};
  int size = 1;
  bool color = false;

  static Numeric of(double x) { return Numeric{{x, x, x, x, x}, 1, false}; }
  double x() const { return v[0]; }
  math::Vec3 vec3() const { return {v[0], v[1], v[2]}; }
};

/// `#macro Name(params) ... #end`: where the body lies in its file's tokens.
struct Macro {
  std::string name;
  std::vector<std::string> parameters;
  std::shared_ptr<const std::vector<Token>> tokens;
  size_t body_start = 0;
  scene::SourceLocation where;
};

struct Array;

struct Value {
  std::variant<
      Numeric, std::string, math::Transform, std::shared_ptr<const material::Pigment>,
      std::shared_ptr<const material::Texture>, material::Finish, std::shared_ptr<const material::Interior>,
      ParsedObject, std::shared_ptr<const Macro>, scene::CameraSpec, std::shared_ptr<const texture::ColorMap>,
      std::shared_ptr<const texture::PigmentMap>, std::shared_ptr<const function::Function>,
      std::shared_ptr<const material::Material>, std::shared_ptr<Array>, std::shared_ptr<const Spline>,
      std::shared_ptr<const material::Normal>, std::shared_ptr<const scene::SkySphere>,
      std::shared_ptr<const material::Media>, std::shared_ptr<const material::Density>,
      std::shared_ptr<const scene::Fog>>
      data;

  const char* type_name() const {
    static const char* names[] = {"number",   "string",   "transform", "pigment", "texture",   "finish",
                                  "interior", "object",   "macro",     "camera",  "color_map", "pigment_map",
                                  "function", "material", "array",     "spline",   "normal",    "sky_sphere",
                                  "media",    "density",  "fog"};
    if (const auto* n = std::get_if<Numeric>(&data))
      return n->color ? "color" : (n->size == 1 ? "float" : "vector");
    return names[data.index()];
  }
};

/// `array[d1][d2]... [{ items }]` (POV-Ray 3.7 reference, "Array Identifiers"): elements in row-major
/// order; an element never assigned is empty, and reading it is an error.
struct Array {
  std::vector<int> sizes;
  std::vector<std::optional<Value>> items;
  /// The items' memory against --max-memory, released with the array.
  memory::Charge charge;
};

}  // namespace snell::sdl
