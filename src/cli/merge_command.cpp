// Partial renders are full-size images whose alpha marks the rendered pixels (renderer.hpp, "region"), so
// joining them is a per-pixel choice of the part that rendered it. EXR parts hold linear floats and merge
// losslessly; PNG parts are already encoded and are copied as stored, so PNG-to-PNG is lossless too.
#include "cli/merge_command.hpp"

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "cli/app.hpp"
#include "cli/options.hpp"
#include "snell/io/image_backend.hpp"
#include "snell/io/image_file.hpp"

namespace snell::cli {

namespace {

namespace fs = std::filesystem;

bool is_png(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".png";
}

}  // namespace

int run_merge(const std::vector<std::string>& args) {
  std::vector<fs::path> parts;
  fs::path output;
  double gamma = 1.0;
  bool quiet = false;
  CLI::App app("snell merge: joins partial renders by their alpha coverage", "snell merge");
  app.set_help_flag("--help", "print this help");
  app.add_option("parts", parts, "partial images (.exr for linear floats, or .png)")->required();
  app.add_option("-o,--output", output, "merged image (.png, .exr, .hdr)")->required();
  app.add_option("--assumed-gamma", gamma, "the scenes' assumed_gamma, for linear parts written as PNG");
  app.add_flag("--quiet", quiet, "no summary");
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return kOk;
  } catch (const CLI::ParseError& e) {
    throw UsageError(std::string("merge: ") + e.what());
  }
  if (!io::is_supported_output(output))
    throw UsageError("cannot write '" + output.string() +
                     "': unsupported image format (use .png, .exr or .hdr)");
  const bool encoded_parts = is_png(parts.front());
  for (const fs::path& p : parts)
    if (is_png(p) != encoded_parts)
      throw UsageError("merge: parts must all be PNG or all linear (EXR/HDR), not a mix");
  if (encoded_parts && !is_png(output))
    throw UsageError("merge: PNG parts hold encoded values; merge them into a PNG, or render EXR parts");

  io::preload_image_backend();
  io::Image merged;
  size_t overlaps = 0;
  for (const fs::path& p : parts) {
    const io::Image part = io::read_image(p);
    if (merged.width == 0) {
      merged = io::Image(part.width, part.height);
      merged.clear_alpha();
    } else if (part.width != merged.width || part.height != merged.height) {
      throw UsageError(fmt::format("merge: '{}' is {}x{}, the first part {}x{}", p.string(), part.width,
                                   part.height, merged.width, merged.height));
    }
    for (int y = 0; y < part.height; ++y)
      for (int x = 0; x < part.width; ++x) {
        if (part.alpha_at(x, y) <= 0) continue;
        if (merged.alpha_at(x, y) > 0) {
          ++overlaps;  // the same deterministic pixel twice: keep the first
          continue;
        }
        merged.set(x, y, part.at(x, y));
        merged.set_alpha(x, y, 1.0f);
      }
  }
  const auto missing = std::count(merged.alpha.begin(), merged.alpha.end(), 0.0f);
  merged.drop_alpha_if_covered();
  io::WriteOptions wo;
  wo.encoding.passthrough = encoded_parts;
  wo.encoding.assumed_gamma = gamma;
  io::write_image(output, merged, wo);
  if (!quiet)
    fmt::print(stderr,
               "snell: merged {} parts into {} ({}x{}; {} pixels in more than one part, {} in none)\n",
               parts.size(), output.string(), merged.width, merged.height, overlaps, missing);
  return kOk;
}

}  // namespace snell::cli
