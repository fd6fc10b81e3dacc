#pragma once
// Text outputs (JSON, SVG) are written to a temporary file beside the target and renamed into place, so a
// failed or interrupted run never leaves half a file.
#include <filesystem>
#include <string>

namespace snell::cli {

/// Throws UsageError (one line) when `path`'s folder does not exist or cannot be written to.
void check_writable(const std::filesystem::path& path, const char* what);
/// Writes `text` to `path` through a temporary file and a rename. Throws io::ImageIoError on failure.
void write_text_file(const std::filesystem::path& path, const std::string& text);

}  // namespace snell::cli
