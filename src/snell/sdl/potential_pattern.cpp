// `potential { Blob_or_Isosurface } [threshold on|off]` (POV-Ray 3.7 reference, "Potential Pattern"; as
// POV-Ray's Blob/IsoSurface::GetPotential): the object's field, taken in the object's own space.
#include "snell/geometry/blob.hpp"
#include "snell/geometry/isosurface.hpp"
#include "snell/sdl/parser.hpp"
#include "snell/texture/object_pattern.hpp"

namespace snell::sdl {

std::shared_ptr<const texture::ValuePattern> Parser::parse_potential_pattern() {
  expect("{", "potential");
  const Token at = peek();
  const ParsedObject object = parse_object_argument("the potential pattern");
  expect("}", "potential");
  bool subtract_threshold = false;
  if (peek().is_word("threshold")) {
    raw_next();
    subtract_threshold = parse_bool_optional(true);
  }
  const math::Transform to_object = object.transform;
  if (auto blob = std::dynamic_pointer_cast<const geometry::Blob>(object.shape)) {
    const double offset = subtract_threshold ? blob->threshold() : 0.0;
    return std::make_shared<texture::PotentialPattern>([blob, to_object, offset](const math::Vec3& p) {
      return blob->density(to_object.inverse_point(p)) - offset;
    });
  }
  if (auto iso = std::dynamic_pointer_cast<const geometry::Isosurface>(object.shape)) {
    // Isosurface::field is f - threshold; POV-Ray's potential is f unless told to subtract.
    const double offset = subtract_threshold ? 0.0 : iso->settings().threshold;
    return std::make_shared<texture::PotentialPattern>([iso, to_object, offset](const math::Vec3& p) {
      return iso->field(to_object.inverse_point(p)) + offset;
    });
  }
  fail(at.where, "the potential pattern needs a blob or an isosurface");
}

}  // namespace snell::sdl
