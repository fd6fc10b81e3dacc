// snell's rough-surface extension of `finish`: `reflection { ... blur A samples N }` (glossy reflection)
// and `transmission { blur A samples N }` (frosted refraction), rendered by render/glossy.cpp.
// POV-Ray's own `roughness` is the size of the specular highlight, so the GGX width is called `blur`.
#include "snell/sdl/parser.hpp"

namespace snell::sdl {

namespace {
/// GGX alpha above 1 is rougher than any real surface and makes the visible-normal sampling degenerate.
constexpr double kMaxBlur = 1;
/// Enough for a smooth picture; the bound keeps a typo from asking for unbounded work.
constexpr int kMaxSamples = 1024;
}  // namespace

bool Parser::parse_rough_item(const std::string& word, double& blur, int& samples) {
  if (word == "blur") {
    raw_next();
    const scene::SourceLocation where = peek().where;
    blur = parse_float();
    if (!(blur >= 0 && blur <= kMaxBlur)) fail(where, "blur must be from 0 (a mirror) to 1");
    return true;
  }
  if (word == "samples") {
    raw_next();
    samples = parse_int("samples", 1, kMaxSamples);
    return true;
  }
  return false;
}

void Parser::parse_transmission(material::Finish& f) {
  expect("{", "transmission");
  for (;;) {
    const Token t = peek();
    if (t.is_symbol("}")) {
      raw_next();
      return;
    }
    if (t.kind == Token::Kind::identifier &&
        parse_rough_item(t.text, f.transmission_blur, f.transmission_samples))
      continue;
    fail(t.where, "unexpected '" + t.text + "' in transmission (expected blur or samples)");
  }
}

}  // namespace snell::sdl
