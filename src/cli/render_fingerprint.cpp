#include "cli/render_fingerprint.hpp"

#include <fstream>
#include <iterator>
#include <string>

#include "snell/render/resume_file.hpp"

namespace snell::cli {

uint64_t render_fingerprint(const CliOptions& o, const PixelBounds& region) {
  std::ifstream in(o.input, std::ios::binary);
  if (!in) throw UsageError("cannot read scene file '" + o.input.string() + "'");
  const std::string scene((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  render::Fnv1a h;
  h.add(std::string(SNELL_VERSION));
  h.add(scene);
  for (int v : {o.width, o.height, region.x0, region.y0, region.x1, region.y1, o.aa_depth, o.initial_frame,
                o.final_frame, o.frame, o.aa_method, o.samples_per_pixel})
    h.add_value(v);
  for (bool v : {o.antialias, o.jitter, o.cyclic}) h.add_value(v);
  for (double v : {o.aa_threshold, o.jitter_amount, o.initial_clock, o.final_clock}) h.add_value(v);
  h.add(o.sampler);
  h.add(o.filter);
  for (const auto& [name, value] : o.declares) {
    h.add(name);
    h.add_value(value);
  }
  for (const auto& dir : o.library_paths) h.add(dir.string());
  return h.value();
}

}  // namespace snell::cli
