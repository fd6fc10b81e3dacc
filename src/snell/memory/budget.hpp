#pragma once
// Memory accounting for the big consumers of a scene (issue 12, `--max-memory`): mesh and mesh2 lists,
// height fields, image-map images and the language's arrays today; photon maps, radiosity caches and
// particle systems are expected to charge the same budget (Scene::memory_budget) when they come.
//
// A consumer charges what it is about to allocate, before allocating it, with a short name of what it is
// ("mesh2 face_indices"); a charge past the limit throws BudgetExceeded naming that consumer, and the
// parser turns it into a `file:line:col: error:` at the item. The accounting is of the large arrays only,
// not of every byte the process holds: small objects, the accelerator and the libraries are not counted.
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace snell::memory {

class BudgetExceeded : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Budget {
 public:
  /// `limit` in bytes; kUnlimited accounts without ever refusing.
  explicit Budget(uint64_t limit) : limit_(limit) {}
  static constexpr uint64_t kUnlimited = UINT64_MAX;

  /// Counts `bytes` more for `consumer`, or throws BudgetExceeded (counting nothing) when that would pass
  /// the limit. Thread-safe.
  void charge(uint64_t bytes, std::string_view consumer);
  /// Gives back what an earlier charge counted (the consumer freed it).
  void release(uint64_t bytes);

  uint64_t limit() const { return limit_; }
  uint64_t used() const { return used_.load(std::memory_order_relaxed); }
  uint64_t peak() const { return peak_.load(std::memory_order_relaxed); }

 private:
  uint64_t limit_;
  std::atomic<uint64_t> used_{0};
  std::atomic<uint64_t> peak_{0};
};

/// A charge that is released when it is destroyed, for consumers that may be freed before the scene (the
/// language's arrays). Copying charges the same amount again, as the copy holds its own memory.
class Charge {
 public:
  Charge() = default;
  Charge(std::shared_ptr<Budget> budget, uint64_t bytes, std::string_view consumer);
  Charge(const Charge& other);
  Charge& operator=(const Charge& other);
  Charge(Charge&& other) noexcept;
  Charge& operator=(Charge&& other) noexcept;
  ~Charge();
  uint64_t bytes() const { return bytes_; }

 private:
  void reset() noexcept;
  std::shared_ptr<Budget> budget_;
  uint64_t bytes_ = 0;
  std::string consumer_;
};

/// Physical memory (sysconf's pages times page size), or 0 when the system does not say.
uint64_t physical_memory_bytes();
/// The limit when none is given: three quarters of physical memory, which leaves the rest of the machine
/// usable; unlimited when physical memory is unknown.
uint64_t default_limit();

/// "2G", "512M", "64k", "1.5GiB", "1000000" (bytes); units are powers of 1024, case-insensitive, with an
/// optional "B" or "iB". nullopt for anything else, zero or a size past 2^64.
std::optional<uint64_t> parse_size(std::string_view text);
/// "1.5 GiB", "512 MiB", "12 KiB", "100 bytes".
std::string format_size(uint64_t bytes);

}  // namespace snell::memory
