#pragma once
// One render over many processes with Open MPI (issue 11; docs/distributed.md). Rank 0 parses like every
// rank, hands out tiles from a queue, renders tiles itself on a second thread, gathers the others' pixels and
// writes the image; ranks 1..N-1 render the tiles they are given with all their cores. Tiles are
// self-contained and seeded by pixel, so the image is identical to a single-process render for any N.
// Built only where MPI is (SNELL_HAVE_MPI); elsewhere these are single-process stand-ins.
#include <atomic>
#include <functional>
#include <optional>
#include <vector>

#include "snell/accel/accelerator.hpp"
#include "snell/io/image.hpp"
#include "snell/render/renderer.hpp"
#include "snell/scene/scene.hpp"

namespace snell::cli::distributed {

/// Starts MPI when this process was launched by mpirun (and snell has MPI); finalises it at exit.
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

/// This process's rank and the number of ranks (0 and 1 outside mpirun).
int rank();
int size();
/// "with Open MPI" or "without MPI", for --version.
const char* support();

struct Job {
  const scene::Scene& scene;
  const accel::Accelerator& accelerator;
  /// The options of a single-process render; tile_source and tile_done are set here.
  render::RenderOptions options;
  /// The tiles still to render, in order (rank 0's queue).
  std::vector<render::Tile> tiles;
  /// Rank 0: called for every finished tile, local or remote, once its pixels are in the image.
  std::function<void(const render::Tile&)> tile_done;
};

/// Renders `job` over all ranks into `image` (meaningful on rank 0). Returns the statistics summed over
/// ranks on rank 0, this rank's own elsewhere.
render::RenderStats render(const Job& job, io::Image& image);

/// Whole frames over all ranks (frame_loop.hpp): rank 0 hands out frame indices 0..count-1 from a queue
/// to every rank, itself included; each rank calls render_frame(index) for the frames it gets and writes
/// them. A frame that does not return 0 (an interruption) stops that rank; `cancel` closes the queue.
/// Returns the highest exit code of all ranks on rank 0, this rank's own elsewhere.
int render_frames(int count, const std::atomic<bool>* cancel, const std::function<int(int)>& render_frame);

/// Rank 0's `value`, on every rank.
int broadcast_from_lead(int value);

/// Ends every rank of the job with `code` (after an error on one rank that the others cannot see).
[[noreturn]] void abort_all(int code);

/// Hands out the next tile to a render thread, or nothing when there is none left (calls may overlap).
using TileSource = std::function<std::optional<render::Tile>()>;
/// Renders the tiles `next_tile` gives on this process's cores, reporting each to job.tile_done.
render::RenderStats render_local(const Job& job, io::Image& image, const TileSource& next_tile);
/// The whole job in this process, tiles in order.
render::RenderStats render_alone(const Job& job, io::Image& image);

}  // namespace snell::cli::distributed
