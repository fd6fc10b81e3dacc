#pragma once
// L-systems (Lindenmayer 1968; Prusinkiewicz & Lindenmayer, The Algorithmic Beauty of Plants (ABoP), 1990):
// parallel rewriting of a string of modules, each a one-character symbol with optional numeric parameters.
// Rules may be bracketed (ABoP 1.6), stochastic (several rules for one predecessor, chosen by probability
// with a seeded generator, ABoP 1.7) and parametric with conditions (ABoP 1.10):
//   predecessor "A(l,w) : l > 1"   successor "F(l)[+A(l*0.5,w*0.7)]"
// Spaces are ignored. A module without parentheses has no parameters; a rule matches a module with the same
// symbol and the same number of parameters whose condition holds.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "snell/procedural/lsystem_expression.hpp"

namespace snell::procedural {

/// A string of modules stored compactly: one byte per symbol, and the parameters of module i in
/// params[offsets[i], offsets[i + 1]) (offsets stays empty while no module has parameters).
class ModuleString {
 public:
  std::size_t size() const { return symbols_.size(); }
  char symbol(std::size_t i) const { return symbols_[i]; }
  std::span<const double> parameters(std::size_t i) const;
  const std::string& symbols() const { return symbols_; }
  std::size_t parameter_count() const { return params_.size(); }
  void push_back(char symbol, std::span<const double> parameters = {});
  /// Bytes held, for memory checks.
  std::size_t bytes() const;

 private:
  std::string symbols_;
  std::vector<std::uint32_t> offsets_;
  std::vector<double> params_;
};

/// Parses a module string such as "F(1)[+A(2,3)]" (an axiom); arguments must be numbers.
ModuleString parse_modules(std::string_view text);

struct LSystemRule {
  /// "A(l,w) : l > 1" (condition optional).
  std::string predecessor;
  std::string successor;
  /// Relative weight among the rules that match the same module (stochastic L-systems).
  double probability = 1;
};

struct LSystemSettings {
  std::string axiom;
  std::vector<LSystemRule> rules;
  int iterations = 0;
  std::uint64_t seed = 0;
  /// The generated string may not grow past this many modules, nor twice as many parameters (bounded
  /// memory), and at most 10 times as many modules are rewritten over all iterations (bounded time).
  std::size_t max_length = 20'000'000;
};

/// Rewrites the axiom `iterations` times. Throws LSystemError for bad rules or a string past max_length.
ModuleString generate_lsystem(const LSystemSettings& settings);

}  // namespace snell::procedural
