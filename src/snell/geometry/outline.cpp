#include "snell/geometry/outline.hpp"

#include <algorithm>
#include <span>
#include <stdexcept>

#include "snell/geometry/polynomial.hpp"

namespace snell::geometry {

Outline::Outline(std::vector<CurveSegment> pieces) : pieces_(std::move(pieces)) {
  if (pieces_.empty()) throw std::invalid_argument("outline has no pieces");
  lo_ = pieces_[0].lo;
  hi_ = pieces_[0].hi;
  for (const CurveSegment& p : pieces_) {
    lo_ = {std::min(lo_.u, p.lo.u), std::min(lo_.v, p.lo.v)};
    hi_ = {std::max(hi_.u, p.hi.u), std::max(hi_.v, p.hi.v)};
  }
  tree_ = PieceTree(pieces_);
}

int Outline::crossings(const CurveSegment& piece, Vec2 n, double k, double* roots) {
  const std::array<double, 4> coeffs = piece.against_line(n, k);
  return real_roots(coeffs, -kJointSlack, 1.0 + kJointSlack, std::span<double>(roots, 3));
}

bool Outline::contains(Vec2 q) const {
  if (q.u < lo_.u || q.u > hi_.u || q.v < lo_.v || q.v > hi_.v) return false;
  // Count where the piece's height above the line v = q.v changes sign (a value of exactly zero counts
  // as above), to the right of q. Evaluating the sign between consecutive roots makes tangent touches
  // and shared end points count correctly, whatever the piece's degree.
  bool odd = false;
  const Vec2 n{0, 1};
  const double k = -q.v;
  // Only the pieces whose rectangles meet the half-line's stretch within the outline's rectangle.
  tree_.for_each_near(q, {hi_.u, q.v}, n, k, [&](uint32_t i) {
    const CurveSegment& piece = pieces_[i];
    if (piece.hi.u < q.u || !piece.line_may_cross(n, k)) return;
    const std::array<double, 4> coeffs = piece.against_line(n, k);
    double roots[3];
    const int count = real_roots(coeffs, 0.0, 1.0, std::span<double>(roots, 3));
    // Break points 0, roots..., 1 (a root at 1 adds an empty interval, which is harmless).
    double breaks[5];
    int nb = 0;
    breaks[nb++] = 0;
    for (int r = 0; r < count; ++r) breaks[nb++] = roots[r];
    if (breaks[nb - 1] < 1) breaks[nb++] = 1;
    const auto above = [&](double s) { return evaluate_polynomial(coeffs, s) >= 0; };
    bool side = above(0);
    for (int j = 0; j + 1 < nb; ++j) {
      const bool next = above(0.5 * (breaks[j] + breaks[j + 1]));
      if (next != side && piece.at(breaks[j]).u > q.u) odd = !odd;
      side = next;
    }
    if (above(1) != side && piece.at(breaks[nb - 1]).u > q.u) odd = !odd;
  });
  return odd;
}

}  // namespace snell::geometry
