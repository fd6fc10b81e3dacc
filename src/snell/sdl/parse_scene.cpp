// Placeholder until the parser lands (sdl helper replaces this file).
#include "snell/sdl/parse.hpp"

namespace snell::sdl {
scene::Scene parse_scene_file(const std::filesystem::path& path, const ParseOptions&) {
  throw ParseError(path.string() + ":1:1: error: the scene parser is not built yet");
}
scene::Scene parse_scene_string(const std::string&, const std::string& file_name, const ParseOptions&) {
  throw ParseError(file_name + ":1:1: error: the scene parser is not built yet");
}
}  // namespace snell::sdl
