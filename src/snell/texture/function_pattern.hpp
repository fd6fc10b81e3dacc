#pragma once
// POV-Ray's `function { ... }` pattern (reference, "Function Pattern"): the value of a user function of
// x, y, z at the texture-space point; the wave function then folds values outside [0,1] as for any pattern.
#include <memory>

#include "snell/function/function.hpp"
#include "snell/texture/pattern.hpp"

namespace snell::texture {

class FunctionPattern final : public ValuePattern {
 public:
  /// `f` takes three arguments (x, y, z); the parser checks it can be evaluated.
  explicit FunctionPattern(std::shared_ptr<const function::Function> f) : f_(std::move(f)) {}
  double value(const Vec3& p) const override {
    const double args[3] = {p.x, p.y, p.z};
    return f_->call(args);
  }

 private:
  std::shared_ptr<const function::Function> f_;
};

}  // namespace snell::texture
