#pragma once
// Render progress on stderr: a bar with percentage and ETA on a terminal, otherwise one summary line.
#include <chrono>

namespace snell::cli {

class Progress {
 public:
  explicit Progress(bool enabled);
  /// Fraction done in [0,1]; calls are serialised by the renderer.
  void update(double fraction);
  void finish(double seconds);

 private:
  bool enabled_;
  bool tty_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace snell::cli
