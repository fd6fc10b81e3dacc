// The stand-ins of distributed.hpp for a build without MPI: one process, rank 0 of 1.
#ifndef SNELL_HAVE_MPI
#include "cli/distributed.hpp"

namespace snell::cli::distributed {

Session::Session(int&, char**&) {}
Session::~Session() = default;
int rank() {
  return 0;
}
int size() {
  return 1;
}
const char* support() {
  return "without MPI";
}

render::RenderStats render(const Job& job, io::Image& image) {
  render::RenderOptions options = job.options;
  options.tile_done = [&job](const render::Tile& t, const io::Image&) { job.tile_done(t); };
  std::vector<bool> queued(static_cast<size_t>(render::tiles_across(options.width)) *
                           render::tiles_down(options.height));
  for (const render::Tile& t : job.tiles) queued[static_cast<size_t>(t.index)] = true;
  options.skip_tile = [&queued](const render::Tile& t) { return !queued[static_cast<size_t>(t.index)]; };
  return render::Renderer(job.scene, job.accelerator, options).render_into(image);
}

}  // namespace snell::cli::distributed
#endif
