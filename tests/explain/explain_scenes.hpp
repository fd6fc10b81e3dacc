#pragma once
// Scenes for the explain tests, written in the scene language so objects carry names and source locations.
#include <string>

#include "snell/accel/accelerator.hpp"
#include "snell/sdl/parse.hpp"

namespace snell::test {

inline scene::Scene parse(const std::string& text) {
  sdl::ParseOptions options;
  options.library_paths.emplace_back(POVRAY_INCLUDE_DIR);
  return sdl::parse_scene_string(text, "explain.pov", options);
}

/// A glass sphere of radius 1 at the origin (ior 1.5, some reflection) seen from -z, over a floor.
inline const char* kGlassSphere = R"(
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 5 }
camera { location <0, 0, -5> direction z right x up y look_at <0, 0, 0> }
light_source { <3, 5, -4> color rgb 1 }
#declare Glass = sphere { 0, 1 pigment { rgbf <1, 1, 1, 0.9> } finish { reflection { 0.1 } } interior { ior 1.5 } }
object { Glass }
plane { y, -2 pigment { rgb 0.5 } }
background { rgb <0.1, 0.2, 0.4> }
)";

}  // namespace snell::test
