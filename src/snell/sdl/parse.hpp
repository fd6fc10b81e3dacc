#pragma once
// Entry point of the POV-Ray scene language: text in, scene::Scene out. The rest of snell never sees
// tokens; the language never sees an integrator.
#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "snell/memory/budget.hpp"
#include "snell/scene/scene.hpp"

namespace snell::sdl {

struct ParseOptions {
  /// Folders searched by `#include` after the scene's own folder (POV-Ray's +L).
  std::vector<std::filesystem::path> library_paths;
  /// Values of `image_width` / `image_height`.
  int image_width = 320;
  int image_height = 240;
  /// Animation (POV-Ray's Initial_Frame, Final_Frame, Initial_Clock, Final_Clock options): the frame
  /// parsed and the range it belongs to. `clock_on` is true when an animation was asked for.
  double clock = 0;
  int frame_number = 0;
  bool clock_on = false;
  int initial_frame = 1;
  int final_frame = 1;
  double initial_clock = 0;
  double final_clock = 1;
  /// Cyclic_Animation (+KC): the last frame stops one step short of final_clock, so a loop repeats
  /// seamlessly.
  bool cyclic = false;
  /// The clock step between frames; POV-Ray uses 1 for a single frame (its animationprocessing.cpp).
  double clock_delta() const {
    if (final_frame == initial_frame) return 1.0;
    return (final_clock - initial_clock) / double(final_frame - initial_frame + (cyclic ? 1 : 0));
  }
  /// `Declare=NAME=value` from the command line / ini files.
  std::map<std::string, double> declares;
  /// Called with each file the scene reads (itself, includes, images, fonts, #fopen), e.g. for --watch.
  std::function<void(const std::filesystem::path&)> on_file_read;
  /// Receives each warning and `#debug` text, formatted; null prints to stderr.
  std::function<void(const std::string&)> message_sink;
  /// Guards against runaway scenes (each breach is a ParseError at the offending line).
  long max_while_iterations = 10'000'000;
  int max_include_depth = 64;
  int max_macro_depth = 256;
  /// Tokens read or skipped in all (loops and macros replay tokens): bounds the work of any scene, such
  /// as a macro that calls itself twice per level, which no depth or iteration limit catches.
  long long max_tokens = 1'000'000'000;
  /// Elements of one array, and characters of one string value.
  long long max_array_elements = 10'000'000;
  /// The longest string a scene may build (concat, str...); longer is an error, not unbounded memory.
  long long max_string_length = 1 << 20;
  /// Objects (shapes, lights and CSG nodes) in one object tree: `union { object { A } object { A } }`
  /// declared as A again doubles each time.
  long long max_objects = 20'000'000;
  /// The memory the scene's big arrays may take (--max-memory); null: memory::default_limit().
  std::shared_ptr<memory::Budget> memory_budget;
};

/// A scene error. `what()` is the whole message as printed: `file:line:col: error: message`, the source
/// line and a caret under the column (and, inside macros or includes, the chain of call sites).
class ParseError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Parses and builds a scene. Throws ParseError for any error in the scene text or files it names.
scene::Scene parse_scene_file(const std::filesystem::path& path, const ParseOptions& options);
scene::Scene parse_scene_string(const std::string& text, const std::string& file_name,
                                const ParseOptions& options);

}  // namespace snell::sdl
