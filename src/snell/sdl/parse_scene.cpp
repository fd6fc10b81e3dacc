// The public entry points: one Parser per scene.
#include "snell/sdl/parse.hpp"

#include "snell/sdl/parser.hpp"

namespace snell::sdl {

scene::Scene parse_scene_file(const std::filesystem::path& path, const ParseOptions& options) {
  return Parser(options).parse_file(path);
}

scene::Scene parse_scene_string(const std::string& text, const std::string& file_name,
                                const ParseOptions& options) {
  return Parser(options).parse_text(text, file_name);
}

}  // namespace snell::sdl
