#include "snell/render/two_pass_queue.hpp"

#include <thread>

namespace snell::render {

TwoPassQueue::TwoPassQueue(std::vector<std::vector<size_t>> needs)
    : needs_(std::move(needs)), first_done_(std::make_unique<std::atomic<bool>[]>(needs_.size())) {
  for (size_t i = 0; i < needs_.size(); ++i) first_done_[i].store(false, std::memory_order_relaxed);
}

bool TwoPassQueue::ready(size_t i) const {
  for (const size_t j : needs_[i])
    if (!first_done_[j].load(std::memory_order_acquire)) return false;
  return true;
}

void TwoPassQueue::first_done(size_t i) {
  first_done_[i].store(true, std::memory_order_release);
}

TwoPassQueue::Work TwoPassQueue::next() {
  const size_t count = needs_.size();
  while (!abandoned_.load(std::memory_order_acquire)) {
    size_t second = next_second_.load(std::memory_order_relaxed);
    if (second >= count) break;
    if (ready(second)) {
      if (next_second_.compare_exchange_weak(second, second + 1, std::memory_order_relaxed))
        return {Work::Pass::second, second};
      continue;  // another thread took it
    }
    if (next_first_.load(std::memory_order_relaxed) < count) {
      const size_t first = next_first_.fetch_add(1, std::memory_order_relaxed);
      if (first < count) return {Work::Pass::first, first};
    }
    std::this_thread::yield();
  }
  return {};
}

}  // namespace snell::render
