#pragma once
// Deterministic scene mutations for the fuzz replay test: the kinds of damage libFuzzer does (byte flips,
// dictionary splices, cuts, duplicated ranges) plus deep nesting, driven by a seeded Pcg32 so that every
// run tries the same inputs.
#include <string>
#include <vector>

#include "snell/math/pcg32.hpp"

namespace snell::fuzz::test {

class Mutator {
 public:
  Mutator(std::vector<std::string> dictionary, uint64_t seed)
      : dictionary_(std::move(dictionary)), rng_(seed) {}

  /// `input` with 1 to 4 random mutations applied.
  std::string mutate(std::string input);
  size_t dictionary_size() const { return dictionary_.size(); }

 private:
  size_t below(size_t n) { return n == 0 ? 0 : rng_.next_uint() % n; }
  void flip_byte(std::string& s);
  void splice_token(std::string& s);
  void cut_range(std::string& s);
  void duplicate_range(std::string& s);
  void truncate(std::string& s);
  void nest_deeply(std::string& s);

  std::vector<std::string> dictionary_;
  math::Pcg32 rng_;
};

/// The quoted values of a libFuzzer dictionary file (`name="value"` lines, `\"` and `\\` escapes).
std::vector<std::string> read_dictionary(const std::string& path);

}  // namespace snell::fuzz::test
