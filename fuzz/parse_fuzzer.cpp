// libFuzzer target for the lexer and parser: bytes in, a parsed and built scene (or a ParseError) out.
// Built with clang and -fsanitize=fuzzer,address,undefined by -DSNELL_FUZZ=ON (tools/fuzz.sh runs it);
// the replay test in tests/fuzz/ calls the same entry point from a plain gcc build.
#include "fuzz/parse_fuzzer.hpp"
#include "fuzz/temp_folder.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace snell::fuzz {

namespace {

/// An empty private folder that plays the scene's folder: `#include "x"` relative to the scene finds
/// nothing there, and nothing the parser could write would land outside it.
const std::filesystem::path& scene_folder() {
  static const std::filesystem::path folder = make_private_folder("snell-fuzz");
  return folder;
}

}  // namespace

sdl::ParseOptions fuzz_parse_options() {
  sdl::ParseOptions options;
  options.library_paths.emplace_back(POVRAY_INCLUDE_DIR);
  options.message_sink = [](const std::string&) {};
  // Sized for ASan+UBSan builds, which parse 10-20 times slower than a Release build.
  options.max_while_iterations = 2'000;
  options.max_tokens = 300'000;
  options.max_array_elements = 100'000;
  options.max_string_length = 100'000;
  options.max_objects = 20'000;
  return options;
}

bool parse_scene_bytes(const uint8_t* data, size_t size) {
  static const sdl::ParseOptions options = fuzz_parse_options();
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    sdl::parse_scene_string(text, (scene_folder() / "fuzz.pov").string(), options);
    return true;
  } catch (const sdl::ParseError&) {
    return false;
  }
}

}  // namespace snell::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  snell::fuzz::parse_scene_bytes(data, size);
  return 0;
}
