#pragma once
#include <string>
#include <vector>

#include "snell/material/pigment.hpp"
#include "snell/sdl/parse.hpp"

namespace snell::sdl::test {

/// Parses `text`, collecting warnings and #debug output in `messages` when given.
inline scene::Scene parse(const std::string& text, std::vector<std::string>* messages = nullptr) {
  ParseOptions options;
  options.library_paths.push_back(POVRAY_INCLUDE_DIR);
  options.message_sink = [messages](const std::string& m) {
    if (messages) messages->push_back(m);
  };
  return parse_scene_string(text, "test.pov", options);
}

/// The error text a scene produces ("" when it parses).
inline std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

inline material::Rgbft solid_color(const scene::Object& o) {
  const auto* solid = dynamic_cast<const material::SolidPigment*>(o.texture->pigment.get());
  return solid ? solid->color() : material::Rgbft{math::Color(-1), -1, -1};
}

}  // namespace snell::sdl::test
