#include "cli/progress.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>
#include <string>

namespace snell::cli {

Progress::Progress(bool enabled)
    : enabled_(enabled),
      tty_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      last_draw_() {}

void Progress::update(double fraction) {
  if (!enabled_ || !tty_) return;
  const auto now = std::chrono::steady_clock::now();
  if (fraction < 1 && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
  constexpr int kWidth = 40;
  const int filled = static_cast<int>(fraction * kWidth);
  fmt::print(stderr, "\r[{}{}] {:5.1f}%  ETA {:.0f}s ", std::string(filled, '#'),
             std::string(kWidth - filled, '.'), fraction * 100, eta);
  std::fflush(stderr);
}

void Progress::finish(double seconds) {
  if (!enabled_) return;
  if (tty_) fmt::print(stderr, "\r{:60}\r", "");
  fmt::print(stderr, "snell: rendered in {:.2f}s\n", seconds);
}

}  // namespace snell::cli
