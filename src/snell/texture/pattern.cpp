#include "snell/texture/pattern.hpp"

#include <cmath>

namespace snell::texture {

namespace {
// The tolerance POV-Ray's block patterns add before flooring (documented as avoiding "coincident surface"
// noise on planes through integer coordinates).
constexpr double kBlockTolerance = 1e-6;
}  // namespace

int CheckerPattern::block(const Vec3& p) const {
  const long long sum = static_cast<long long>(std::floor(p.x + kBlockTolerance)) +
                        static_cast<long long>(std::floor(p.y + kBlockTolerance)) +
                        static_cast<long long>(std::floor(p.z + kBlockTolerance));
  return static_cast<int>(sum & 1);
}

double GradientPattern::value(const Vec3& p) const {
  return dot(p, direction_);
}

}  // namespace snell::texture
