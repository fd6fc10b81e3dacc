#pragma once
// The order of two-pass anti-aliasing's work over a batch of tiles (first_sample_grid.hpp), handed out to
// the render's threads: first passes in tile order, and each tile's second pass (its supersampling) as soon
// as the first passes it reads are done, taken before any new first pass. Tiles so finish nearly in order
// and one by one, as a one-pass render's do (for checkpoints and progress), with no barrier between passes.
#include <atomic>
#include <cstddef>
#include <memory>
#include <vector>

namespace snell::render {

class TwoPassQueue {
 public:
  /// needs[i]: the tiles whose first passes tile i's second pass reads.
  explicit TwoPassQueue(std::vector<std::vector<size_t>> needs);

  struct Work {
    enum class Pass { first, second, none } pass = Pass::none;
    size_t tile = 0;
  };
  /// The next work, waiting (briefly, near the end) while the only work left is a second pass whose first
  /// passes other threads are doing. `none` once everything is handed out or the queue is abandoned.
  Work next();
  /// Publishes tile i's first samples to the threads that read them.
  void first_done(size_t i);
  /// Stops handing out work (an exception on some thread), so that no thread waits for a first pass
  /// that will never be done.
  void abandon() { abandoned_.store(true, std::memory_order_release); }

 private:
  bool ready(size_t i) const;

  std::vector<std::vector<size_t>> needs_;
  std::unique_ptr<std::atomic<bool>[]> first_done_;
  std::atomic<size_t> next_first_{0}, next_second_{0};
  std::atomic<bool> abandoned_{false};
};

}  // namespace snell::render
