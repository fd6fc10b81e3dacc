// `global_settings { radiosity { ... } }` (POV-Ray 3.7 reference, "Radiosity Basics"): every setting is
// read and range-checked; which ones change the image is documented in docs/language.md.
#include "snell/sdl/parser.hpp"

namespace snell::sdl {

scene::RadiositySettings Parser::parse_radiosity_block() {
  // The cache is charged to --max-memory while rendering (render/radiosity/solver.hpp): make sure the
  // scene carries the budget even when nothing else charged it.
  keep_memory(peek().where, 0, "radiosity cache");
  expect("{", "radiosity");
  scene::RadiositySettings r;
  for (;;) {
    if (accept("}")) return r;
    const Token t = peek();
    if (t.kind != Token::Kind::identifier) fail(t.where, "unexpected '" + t.text + "' in radiosity");
    const std::string w = t.text;
    raw_next();
    if (w == "count") {
      r.count = parse_int("radiosity count", 1, 10000);
      accept(",");
      if (starts_numeric()) r.direction_pool = parse_int("radiosity count's direction pool", 1);
    } else if (w == "recursion_limit") {
      r.recursion_limit = parse_int("recursion_limit", 1, 20);
    } else if (w == "nearest_count") {
      r.nearest_count = parse_int("nearest_count", 1, 20);
      accept(",");
      if (starts_numeric()) parse_int("nearest_count's pretrace value", 1, 20);
    } else if (w == "brightness") {
      r.brightness = parse_float();
    } else if (w == "error_bound") {
      r.error_bound = parse_float();
    } else if (w == "pretrace_start") {
      r.pretrace_start = parse_float();
    } else if (w == "pretrace_end") {
      r.pretrace_end = parse_float();
    } else if (w == "low_error_factor") {
      r.low_error_factor = parse_float();
    } else if (w == "gray_threshold") {
      r.gray_threshold = parse_float();
    } else if (w == "minimum_reuse") {
      r.minimum_reuse = parse_float();
    } else if (w == "maximum_reuse") {
      r.maximum_reuse = parse_float();
    } else if (w == "adc_bailout") {
      r.adc_bailout = parse_float();
    } else if (w == "normal") {
      r.normal = parse_bool_optional(true);
    } else if (w == "media") {
      r.media = parse_bool_optional(true);
    } else if (w == "always_sample") {
      r.always_sample = parse_bool_optional(true);
    } else if (w == "subsurface") {
      parse_bool_optional(true);
    } else if (w == "max_sample") {
      r.max_sample = parse_float();
    } else if (w == "distance_maximum") {
      parse_float();
    } else if (w == "brilliance" || w == "save_file" || w == "load_file") {
      warn(t.where, "radiosity " + w + " is not supported; ignored");
      if (w == "brilliance")
        parse_bool_optional(true);
      else
        parse_string();
    } else {
      fail(t.where, "unknown radiosity keyword '" + w + "'");
    }
  }
}

}  // namespace snell::sdl
