// The tiles this process renders itself: the whole job in a single process, rank 0's share in a distributed
// render (distributed.hpp). Built with and without MPI.
#include <utility>

#include "cli/distributed.hpp"

namespace snell::cli::distributed {

namespace {

render::RenderStats render_job(const Job& job, io::Image& image, render::RenderOptions options) {
  options.tile_done = [&job](const render::Tile& t, const io::Image&) { job.tile_done(t); };
  return render::Renderer(job.scene, job.accelerator, options).render_into(image);
}

}  // namespace

render::RenderStats render_local(const Job& job, io::Image& image, const TileSource& next_tile) {
  render::RenderOptions options = job.options;
  options.tile_source = next_tile;
  return render_job(job, image, std::move(options));
}

// The whole list at once, so that the renderer can order its work (anti-aliasing's two passes).
render::RenderStats render_alone(const Job& job, io::Image& image) {
  render::RenderOptions options = job.options;
  options.tiles = job.tiles;
  return render_job(job, image, std::move(options));
}

}  // namespace snell::cli::distributed
