#pragma once
#include <cstdint>

#include "cli/options.hpp"

namespace snell::cli {

/// What a resume file is valid for: snell's version, the scene file's bytes and every flag that changes
/// pixels (size, region, anti-aliasing, declares, library paths). Throws UsageError when the scene cannot be
/// read.
uint64_t render_fingerprint(const CliOptions& options, const PixelBounds& region);

}  // namespace snell::cli
