#include <filesystem>
#include <system_error>

#include "cli/options.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/io/image_file.hpp"
#include "snell/memory/budget.hpp"
#include "snell/render/filter.hpp"
#include "snell/render/sampler.hpp"

namespace snell::cli {

namespace fs = std::filesystem;

void validate(CliOptions& o) {
  if (o.input.empty()) throw UsageError("no scene file given (snell render scene.pov, or +Iscene.pov)");
  if (o.width <= 0 || o.height <= 0)
    throw UsageError("image size must be positive, got " + std::to_string(o.width) + "x" +
                     std::to_string(o.height));
  if (o.width > 65536 || o.height > 65536) throw UsageError("image size must be at most 65536 pixels a side");
  if (o.aa_threshold < 0) throw UsageError("anti-aliasing threshold must not be negative");
  if (o.aa_depth < 1 || o.aa_depth > 9) throw UsageError("anti-aliasing depth must be between 1 and 9");
  if (o.jitter_amount < 0) throw UsageError("jitter amount must not be negative");
  if (o.threads < 0) throw UsageError("thread count must not be negative");
  if (o.aa_method != 1 && o.aa_method != 2) throw UsageError("anti-aliasing method must be 1 or 2");
  if (o.samples_per_pixel < 0 || o.samples_per_pixel > 1 << 20)
    throw UsageError("--spp must be between 0 and 1048576");
  if (!render::make_sampler(o.sampler))
    throw UsageError("unknown sampler '" + o.sampler + "' (expected " + std::string(render::kSamplerNames) +
                     ")");
  if (!render::Filter::parse(o.filter))
    throw UsageError(
        "bad filter '" + o.filter +
        "' (expected box, tent, gaussian or mitchell, optionally :RADIUS with 0 < RADIUS <= 16)");
  if (o.checkpoint_seconds < 0) throw UsageError("checkpoint interval must not be negative");
  if (!o.max_memory.empty() && !memory::parse_size(o.max_memory))
    throw UsageError("--max-memory needs a size such as 2G, 512M or 100000000 (bytes), got '" + o.max_memory +
                     "'");
  if (o.bits != 8 && o.bits != 16) throw UsageError("bit depth must be 8 or 16");
  if (o.accel != "auto" && !accel::is_accelerator_kind(o.accel))
    throw UsageError("unknown accelerator '" + o.accel + "' (expected " +
                     std::string(accel::kAcceleratorKinds) + ")");
  std::error_code ec;
  if (!fs::exists(o.input, ec)) throw UsageError("scene file '" + o.input.string() + "' does not exist");
  if (fs::is_directory(o.input, ec)) throw UsageError("scene file '" + o.input.string() + "' is a folder");
  if (o.output.empty()) {
    o.output = o.input.filename();
    o.output.replace_extension(o.extension);
  } else if (fs::is_directory(o.output, ec)) {
    o.output /= o.input.stem().string() + o.extension;
  } else if (!o.output.has_extension()) {
    o.output += o.extension;
  }
  if (!io::is_supported_output(o.output))
    throw UsageError("cannot write '" + o.output.string() +
                     "': unsupported image format (use .png, .exr or .hdr)");
}

}  // namespace snell::cli
