// `function { pigment {..} }`, `function { pattern {..} }`, `function { spline {..} }` and
// `function { transform {..} }` (POV-Ray 3.7 reference, "Declaring User-Defined Color Functions" and
// "Declaring User-Defined Vector Functions"): functions of the point that return what a pigment, a
// pattern, a spline or a transform gives there. Pigment, spline and transform functions are
// vector-valued, used through a member (`F(x,y,z).red`, `.gray`) inside functions and as a whole in scene
// expressions; a pattern function returns the pattern's value (0..1 for most) without any map.
#include "snell/sdl/parser.hpp"
#include "snell/sdl/pigment_builder.hpp"
#include "snell/sdl/spline.hpp"

namespace snell::sdl {

namespace {

using function::Function;

std::shared_ptr<const Function> pigment_function(std::shared_ptr<const material::Pigment> pigment) {
  return Function::vector("function { pigment }", 3, 5, [pigment](const double* a, double* out) {
    const material::Rgbft c = pigment->at(material::PatternPoint{{a[0], a[1], a[2]}, {}, {}});
    out[0] = c.rgb.r, out[1] = c.rgb.g, out[2] = c.rgb.b, out[3] = c.filter, out[4] = c.transmit;
  });
}

/// The pattern's value as a colour map would see it: after warps and the wave, or a block pattern's
/// block number (checker 0 or 1), as POV-Ray's pattern functions return them.
std::shared_ptr<const Function> pattern_function(texture::PatternSpec spec) {
  auto shared = std::make_shared<const texture::PatternSpec>(std::move(spec));
  return Function::vector("function { pattern }", 3, 1, [shared](const double* a, double* out) {
    const math::Vec3 p = shared->warps.apply({a[0], a[1], a[2]});
    if (shared->block_pattern) {
      out[0] = shared->block_pattern->block(p);
      return;
    }
    out[0] = shared->wave.apply(shared->value_pattern->value_at(p, {}, {}));
  });
}

std::shared_ptr<const Function> spline_function(std::shared_ptr<const Spline> spline) {
  const auto components = static_cast<std::size_t>(spline->size);
  return Function::vector("function { spline }", 1, components, [spline](const double* a, double* out) {
    const std::array<double, 5> v = spline->evaluate(a[0]);
    std::copy(v.begin(), v.end(), out);
  });
}

std::shared_ptr<const Function> transform_function(const math::Transform& transform) {
  return Function::vector("function { transform }", 3, 3, [transform](const double* a, double* out) {
    const math::Vec3 p = transform.point({a[0], a[1], a[2]});
    out[0] = p.x, out[1] = p.y, out[2] = p.z;
  });
}

}  // namespace

std::shared_ptr<const function::Function> Parser::parse_block_function(const Token& kind) {
  if (kind.is_word("pigment")) {
    auto pigment = parse_pigment_block(nullptr);
    if (!pigment) pigment = std::make_shared<material::SolidPigment>(material::Rgbft{});
    return pigment_function(std::move(pigment));
  }
  if (kind.is_word("pattern")) {
    expect("{", "pattern");
    PigmentBuilder builder;
    parse_pigment_body(builder, "}");
    if (!builder.patterned) fail(kind.where, "a pattern function needs a pattern (bozo, gradient x, ...)");
    return pattern_function(builder.build_spec());
  }
  if (kind.is_word("spline")) return spline_function(parse_spline_block());
  return transform_function(parse_transform_block());
}

}  // namespace snell::sdl
