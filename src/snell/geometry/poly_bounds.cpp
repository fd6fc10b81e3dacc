#include "snell/geometry/poly_bounds.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

#include "snell/geometry/polynomial.hpp"

namespace snell::geometry {
namespace {

using Axes = std::array<double, 3>;

std::array<int, 3> exponents(const PolyTerm& t) {
  return {t.i, t.j, t.k};
}

bool all_even(const PolyTerm& t) {
  return t.i % 2 == 0 && t.j % 2 == 0 && t.k % 2 == 0;
}

/// The half-widths of a box about the origin outside which the sum is positive, from a weighted
/// AM-GM inequality. Each variable needs a pure power x^(2p) of positive coefficient a_x (its highest
/// pure power); with X = x^(2p), Y, Z alike, a term of weights (i/2p, j/2q, k/2s) summing to w obeys
///   |x^i y^j z^k| <= e (i/2p X + j/2q Y + k/2s Z) + (1 - w) e^(-w / (1 - w))   for any e > 0, w < 1,
/// and the same with e = 1 and no constant for w = 1. Terms that cannot be negative (all exponents even,
/// coefficient >= 0) are left out. Terms of weight 1 take their share of a_x, a_y, a_z at once; those of
/// weight below 1 take at most half of what remains, by the choice of e, leaving a constant C: the sum
/// is at least a'_x/2 X + a'_y/2 Y + a'_z/2 Z - C, positive where any a'_x/2 X exceeds C.
std::optional<Axes> dominance_box(std::span<const PolyTerm> terms) {
  std::array<int, 3> power{};    // exponent of each variable's highest pure power
  std::array<double, 3> lead{};  // its coefficient
  std::array<int, 3> lead_term{-1, -1, -1};
  for (size_t n = 0; n < terms.size(); ++n) {
    const auto e = exponents(terms[n]);
    for (int a = 0; a < 3; ++a) {
      const bool pure = e[a] > 0 && e[(a + 1) % 3] == 0 && e[(a + 2) % 3] == 0;
      if (pure && e[a] > power[a]) {
        power[a] = e[a];
        lead[a] = terms[n].c;
        lead_term[a] = static_cast<int>(n);
      }
    }
  }
  for (int a = 0; a < 3; ++a)
    if (power[a] == 0 || power[a] % 2 != 0 || !(lead[a] > 0)) return std::nullopt;

  // Weights with the common denominator P = 2p 2q 2s keep "w = 1" exact.
  const long denominator = static_cast<long>(power[0]) * power[1] * power[2];
  struct Lower {
    Axes weight;
    double w, c;
  };
  std::array<double, 3> remaining = lead;
  std::array<Lower, 128> lower{};
  size_t lower_count = 0;
  double constant = 0;
  for (size_t n = 0; n < terms.size(); ++n) {
    const PolyTerm& t = terms[n];
    if (static_cast<int>(n) == lead_term[0] || static_cast<int>(n) == lead_term[1] ||
        static_cast<int>(n) == lead_term[2])
      continue;
    if (all_even(t) && t.c >= 0) continue;
    const auto e = exponents(t);
    const long numerator = static_cast<long>(e[0]) * power[1] * power[2] +
                           static_cast<long>(e[1]) * power[0] * power[2] +
                           static_cast<long>(e[2]) * power[0] * power[1];
    if (numerator > denominator) return std::nullopt;  // outgrows the pure powers somewhere
    const Axes weight{static_cast<double>(e[0]) / power[0], static_cast<double>(e[1]) / power[1],
                      static_cast<double>(e[2]) / power[2]};
    if (numerator == denominator) {
      for (int a = 0; a < 3; ++a) remaining[a] -= std::fabs(t.c) * weight[a];
    } else if (numerator == 0) {
      constant += std::fabs(t.c);  // a negative constant
    } else {
      if (lower_count == lower.size()) return std::nullopt;
      lower[lower_count++] = {weight, static_cast<double>(numerator) / static_cast<double>(denominator),
                              std::fabs(t.c)};
    }
  }
  for (int a = 0; a < 3; ++a)
    if (!(remaining[a] > 0)) return std::nullopt;
  for (size_t n = 0; n < lower_count; ++n) {
    const Lower& l = lower[n];
    double e = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a)
      if (l.weight[a] > 0)
        e = std::min(e, remaining[a] / (2.0 * static_cast<double>(lower_count) * l.c * l.weight[a]));
    constant += l.c * (1 - l.w) * std::pow(e, -l.w / (1 - l.w));
  }
  Axes half_width{};
  for (int a = 0; a < 3; ++a) {
    half_width[a] = std::pow(2.0 * constant / remaining[a], 1.0 / power[a]);
    if (!std::isfinite(half_width[a])) return std::nullopt;
  }
  return half_width;
}

struct Range {
  double lo, hi;
};

/// The ranges of x^0 .. x^n over [lo, hi], by repeated products (exact for odd powers and for even
/// powers of an interval on one side of zero; an interval across zero gives an even power [0, max]).
template <size_t N>
void power_ranges(double lo, double hi, std::array<Range, N>& out) {
  double pl = 1, ph = 1;
  out[0] = {1, 1};
  for (size_t e = 1; e < N; ++e) {
    pl *= lo;
    ph *= hi;
    if (e % 2 != 0 || lo >= 0)
      out[e] = {pl, ph};
    else if (hi <= 0)
      out[e] = {ph, pl};
    else
      out[e] = {0, std::max(pl, ph)};
  }
}

Range product(Range a, Range b) {
  const double p0 = a.lo * b.lo, p1 = a.lo * b.hi, p2 = a.hi * b.lo, p3 = a.hi * b.hi;
  return {std::min(std::min(p0, p1), std::min(p2, p3)), std::max(std::max(p0, p1), std::max(p2, p3))};
}

/// Keeps the cells of a subdivision where the sum may reach zero, by the natural interval extension of
/// each term (an enclosure of its range over the cell). Cells inside the box found so far cannot change
/// it and are skipped; past the evaluation budget, cells are kept whole.
class Refinement {
 public:
  explicit Refinement(std::span<const PolyTerm> terms) : terms_(terms) {}

  void visit(const math::Bounds3& cell, int depth) {
    if (!found_.empty() && found_.contains(cell.lo) && found_.contains(cell.hi)) return;
    if (may_reach_zero(cell)) {
      if (depth == kMaxDepth || evaluations_ > kBudget) {
        found_.unite(cell);
        return;
      }
      const math::Vec3 mid = cell.center();
      for (int octant = 0; octant < 8; ++octant) {
        const math::Vec3 lo{octant & 1 ? mid.x : cell.lo.x, octant & 2 ? mid.y : cell.lo.y,
                            octant & 4 ? mid.z : cell.lo.z};
        const math::Vec3 hi{octant & 1 ? cell.hi.x : mid.x, octant & 2 ? cell.hi.y : mid.y,
                            octant & 4 ? cell.hi.z : mid.z};
        visit({lo, hi}, depth + 1);
      }
    }
  }
  const math::Bounds3& found() const { return found_; }

 private:
  // 64 cells a side at the finest; the budget caps the work for polynomials of many terms.
  static constexpr int kMaxDepth = 6;
  static constexpr long kBudget = 200000;

  bool may_reach_zero(const math::Bounds3& cell) {
    ++evaluations_;
    std::array<Range, kMaxPolynomialDegree + 1> x, y, z;
    power_ranges(cell.lo.x, cell.hi.x, x);
    power_ranges(cell.lo.y, cell.hi.y, y);
    power_ranges(cell.lo.z, cell.hi.z, z);
    double least = 0, magnitude = 0;
    for (const PolyTerm& t : terms_) {
      const Range r = product(product(x[static_cast<size_t>(t.i)], y[static_cast<size_t>(t.j)]),
                              z[static_cast<size_t>(t.k)]);
      least += t.c > 0 ? t.c * r.lo : t.c * r.hi;
      magnitude += std::fabs(t.c) * std::max(std::fabs(r.lo), std::fabs(r.hi));
    }
    // A margin far above the rounding of the sums keeps a cell whose enclosure only just clears zero.
    return least <= 1e-10 * magnitude;
  }

  std::span<const PolyTerm> terms_;
  math::Bounds3 found_;
  long evaluations_ = 0;
};

}  // namespace

std::optional<math::Bounds3> poly_negative_region_bounds(std::span<const PolyTerm> terms) {
  for (const PolyTerm& t : terms)
    if (std::min({t.i, t.j, t.k}) < 0 || std::max({t.i, t.j, t.k}) > kMaxPolynomialDegree ||
        !std::isfinite(t.c))
      return std::nullopt;
  const auto half_width = dominance_box(terms);
  if (!half_width) return std::nullopt;
  const math::Vec3 h{(*half_width)[0], (*half_width)[1], (*half_width)[2]};
  Refinement refinement(terms);
  refinement.visit({-h, h}, 0);
  math::Bounds3 box = refinement.found();
  if (box.empty()) box = {math::Vec3(0), math::Vec3(0)};  // positive everywhere: a token box
  const math::Vec3 pad = 1e-6 * box.extent() + math::Vec3(1e-9);
  return math::Bounds3(box.lo - pad, box.hi + pad);
}

}  // namespace snell::geometry
