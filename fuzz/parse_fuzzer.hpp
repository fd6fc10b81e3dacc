#pragma once
// The scene-language fuzz target, shared by the libFuzzer build (fuzz/parse_fuzzer.cpp, SNELL_FUZZ=ON) and
// the deterministic replay test that runs in every build (tests/fuzz/).
#include <cstddef>
#include <cstdint>

#include "snell/sdl/parse.hpp"

namespace snell::fuzz {

/// The limits a fuzzed scene runs under: the parser's own guards, set low enough that one input costs
/// at most a fraction of a second and a few hundred MiB (libFuzzer's -timeout and -rss_limit_mb are
/// the backstop, not the mechanism).
sdl::ParseOptions fuzz_parse_options();

/// Parses `size` bytes as a scene with --parse-only semantics (scene built, nothing rendered or written).
/// Returns true when the scene parsed, false when it gave a ParseError; anything else escapes (a bug).
bool parse_scene_bytes(const uint8_t* data, size_t size);

}  // namespace snell::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
