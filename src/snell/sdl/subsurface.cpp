// `subsurface {}` blocks: in a finish and in global_settings (POV-Ray 3.7 reference, "Subsurface Light
// Transport"), plus snell's `material "name"` shortcut for Jensen et al. 2001's measured materials.
#include <string>

#include "snell/material/dipole.hpp"
#include "snell/sdl/parser.hpp"

namespace snell::sdl {

void Parser::parse_finish_subsurface(material::Finish& f) {
  expect("{", "subsurface");
  f.subsurface = true;
  for (;;) {
    const Token t = raw_next();
    if (t.is_symbol("}")) return;
    if (t.is_word("translucency")) {
      f.subsurface_translucency = parse_color().rgb;
    } else if (t.is_word("material") || t.is_word("jensen")) {
      const std::string name = parse_string();
      f.subsurface_material = material::measured_material(name);
      if (!f.subsurface_material)
        fail(t.where, "unknown subsurface material \"" + name +
                          "\"; known: " + std::string(material::measured_material_names()));
    } else if (t.is_word("samples")) {
      // Per-object sample counts (3.7 accepts them here too); the global count is used.
      parse_float();
      if (peek().is_symbol(",")) raw_next();
      if (starts_numeric()) parse_float();
    } else {
      fail(t.where, "unexpected '" + t.text + "' in finish subsurface");
    }
  }
}

void Parser::parse_global_subsurface() {
  expect("{", "subsurface");
  for (;;) {
    const Token t = raw_next();
    if (t.is_symbol("}")) return;
    if (t.is_word("samples")) {
      scene_.settings.subsurface_samples = parse_int("subsurface samples", 1, 100000);
      if (peek().is_symbol(",")) raw_next();
      if (starts_numeric())
        scene_.settings.subsurface_single_samples = parse_int("subsurface single samples", 1, 100000);
    } else if (t.is_word("radiosity")) {
      parse_bool_optional(true);
    } else {
      fail(t.where, "unexpected '" + t.text + "' in global_settings subsurface");
    }
  }
}

}  // namespace snell::sdl
