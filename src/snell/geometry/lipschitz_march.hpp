#pragma once
// Root finding along a ray for implicit surfaces g(t) = 0 whose slope is bounded, |dg/dt| <= L: sphere
// tracing (Hart 1996, "Sphere tracing: a geometric method for the antialiased ray tracing of implicit
// surfaces", The Visual Computer 12(10)) to bracket each sign change, then Illinois regula falsi (Dowell &
// Jarratt 1971) to refine it. Shared by isosurface and superellipsoid.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "snell/math/simd.hpp"

namespace snell::geometry {

struct MarchSettings {
  /// Bound on |dg/dt| along this ray.
  double lipschitz = 1;
  /// Smallest step in t, so that grazing rays still progress; features thinner than this may be missed.
  double min_step = 1e-3;
  /// Roots are refined until their bracket is narrower than this.
  double tolerance = 1e-4;
};

/// Illinois regula falsi on g(t0), g(t1) of opposite signs; at most 60 steps bound the work when g jumps.
template <typename G>
double refine_root(const G& g, double t0, double g0, double t1, double g1, double tolerance) {
  int side = 0;
  for (int i = 0; i < 60 && std::fabs(t1 - t0) > tolerance; ++i) {
    double t = (t0 * g1 - t1 * g0) / (g1 - g0);
    if (!(t > std::min(t0, t1) && t < std::max(t0, t1))) t = 0.5 * (t0 + t1);  // round-off guard
    const double gt = g(t);
    if (gt == 0) return t;  // an exact root (analytic functions meet them): no bracket left to shrink
    if ((gt < 0) == (g1 < 0)) {
      t1 = t, g1 = gt;
      if (side == -1) g0 *= 0.5;  // the Illinois step: halve the stale end so both ends move
      side = -1;
    } else {
      t0 = t, g0 = gt;
      if (side == 1) g1 *= 0.5;
      side = 1;
    }
  }
  return g1 == g0 ? 0.5 * (t0 + t1) : (t0 * g1 - t1 * g0) / (g1 - g0);
}

/// Marches from t (where g = gt) to hi and calls on_root(t_root) at each sign change until it returns
/// false. on_slope(s) hears the secant slope |dg/dt| of every step. Returns g at the last point visited.
///
/// Over-relaxed sphere tracing (Keinert et al. 2014, "Enhanced sphere tracing", STAG): each step tries
/// omega times the safe step |g| / L and keeps it only when the Lipschitz balls |g(t0)| / L and
/// |g(t1)| / L cover it (so no root can hide in it), else it takes the safe step. omega follows the last
/// step's rate of approach a: a step of omega |g| / L stays covered while omega <= 2 / (1 + a / L) if g
/// keeps falling at that rate, so rays passing the surface stride nearly twice as far and rays closing in
/// fail seldom. A failed long step's point is kept: once the march covers the rest of the way to it, it
/// moves there without evaluating g again.
template <typename G, typename OnRoot, typename OnSlope>
double march_roots(const G& g, double t, double gt, double hi, const MarchSettings& s, OnRoot&& on_root,
                   OnSlope&& on_slope) {
  double approach = 0;  // how fast |g| shrank per unit t over the last step (> 0 while nearing a root)
  double ahead_t = 0, ahead_g = 0;  // the kept point, same sign as g(t), while `ahead`
  bool ahead = false;
  const auto covered = [&](double t0, double g0, double t1, double g1) {
    return std::fabs(g0) + std::fabs(g1) >= s.lipschitz * (t1 - t0);
  };
  const double inverse_lipschitz = 1 / s.lipschitz;  // divisions cost more than the march's other work
  while (t < hi) {
    const double reach = std::fabs(gt) * inverse_lipschitz;  // no root closer than this
    const double safe = std::max(reach, s.min_step);
    double t1, g1;
    if (ahead && covered(t, gt, ahead_t, ahead_g)) {
      t1 = ahead_t, g1 = ahead_g;
      ahead = false;
    } else {
      // At the minimum step the march is past proving anything: no over-relaxation there.
      const bool relax = !ahead && reach > s.min_step;
      const double omega =
          relax ? std::clamp(1.9 / (1 + std::max(approach, 0.0) * inverse_lipschitz), 1.0, 1.9) : 1;
      t1 = std::min(hi, t + omega * safe);
      if (ahead && t1 >= ahead_t) {
        t1 = ahead_t, g1 = ahead_g;  // the safe step reaches the kept point: no evaluation needed
        ahead = false;
      } else {
        g1 = g(t1);
      }
      if (t1 - t > safe && !covered(t, gt, t1, g1)) {
        // Not covered: a root (or a pair) might lie beyond the safe step. Take the safe step instead.
        ahead = (gt < 0) == (g1 < 0);
        ahead_t = t1, ahead_g = g1;
        t1 = std::min(hi, t + safe);
        g1 = g(t1);
      }
    }
    if (t1 > t) {
      on_slope(std::fabs(g1 - gt) / (t1 - t));
      approach = (std::fabs(gt) - std::fabs(g1)) / (t1 - t);
    }
    if ((gt < 0) != (g1 < 0)) {
      ahead = false;  // past a root the kept point no longer bounds anything
      if (!on_root(refine_root(g, t, gt, t1, g1, s.tolerance))) return g1;
    }
    t = t1, gt = g1;
  }
  return gt;
}

/// march_roots with g evaluated at K points per call, `g_lanes(ts, n, out)`: out[i] = g(ts[i]) for all
/// i < K, of which the first n (<= K) are distinct and the rest repeat ts[n - 1] (so that the evaluation
/// can run on whole registers), for functions whose multi-point evaluation costs much less than n single
/// ones. Each pass predicts the next K steps of the scalar march, assuming |g| keeps shrinking at the rate of
/// the last step taken, evaluates them at once, and walks them accepting a step as march_roots does: when it
/// is no longer than the safe step max(|g| / L, min_step) from its start, or when the Lipschitz balls of its
/// ends cover it. The first step refused ends the pass and the next pass starts there, so the march
/// proves exactly what march_roots proves; a wrong prediction only wastes lanes. Where the safe step is
/// the minimum step (a loose bound L), all K steps are taken in one pass. Roots are refined with g.
///
/// The first predicted step is the safe step itself, which the walk always accepts, so that no pass is
/// wasted (over-relaxed, a twelfth of the passes were refused at their first step); the others are
/// over-relaxed by at most 1.5, not march_roots' 1.9: here a refused step costs the rest of the pass, and
/// on isosurfaces.pov 1.5 takes the fewest passes (1.9: 6% more, 1.3 and 1.0: 0.3% and 3% more).
template <int K, typename G, typename GLanes, typename OnRoot, typename OnSlope>
requires(K % 2 == 0 && K <= 31) double march_roots_lanes(const G& g, const GLanes& g_lanes, double t,
                                                         double gt, double hi, const MarchSettings& s,
                                                         OnRoot&& on_root, OnSlope&& on_slope) {
  namespace simd = math::simd;
  using V = simd::Vec<2>::V;
  using M = simd::Vec<2>::M;
  const double inverse_lipschitz = 1 / s.lipschitz;
  double approach = 0;  // how fast |g| shrank per unit t over the last step taken
  double steepest = 0;  // the steepest step taken, |dg| / dt
  while (t < hi) {
    // Predicted steps: the safe step, then over-relaxed ones while the predicted |g| allows.
    double ts[K], gs[K];
    int n = 0;
    const double rate = std::isnan(approach) ? s.lipschitz : std::clamp(approach, -s.lipschitz, s.lipschitz);
    const double omega = std::clamp(1.5 / (1 + std::max(rate, 0.0) * inverse_lipschitz), 1.0, 1.5);
    for (double pt = t, pg = std::fabs(gt); n < K && pt < hi;) {
      const double reach = pg * inverse_lipschitz;
      const double step = reach > s.min_step ? (n == 0 ? reach : omega * reach) : s.min_step;
      pt = std::min(hi, pt + step);  // pt + step, rounded as the walk below rounds t0 + safe
      ts[n++] = pt;
      pg = std::max(0.0, pg - rate * step);
    }
    for (int i = n; i < K; ++i) ts[i] = ts[n - 1];
    g_lanes(ts, n, gs);
    // Every step of the pass at once, two at a time (SSE2 vectors, math/simd.hpp): its start, whether the
    // scalar march's test accepts it, whether g changes sign over it, its slope; the tests as bit masks
    // (bit i: step i), so the walk below needs no loop over the steps.
    alignas(16) double t0s[K], g0s[K], slope[K];
    t0s[0] = t, g0s[0] = gt;
    for (int i = 1; i < K; ++i) t0s[i] = ts[i - 1], g0s[i] = gs[i - 1];
    std::uint32_t taken = 0, crosses = 0;
    const V zero{}, min_step = zero + s.min_step, lipschitz = zero + s.lipschitz,
                    inverse = zero + inverse_lipschitz;
    for (int i = 0; i < K; i += 2) {
      const V t0 = simd::load<V>(t0s + i), g0 = simd::load<V>(g0s + i);
      const V t1 = simd::load<V>(ts + i), g1 = simd::load<V>(gs + i);
      const V size0 = simd::abs<V, M>(g0), size1 = simd::abs<V, M>(g1), dt = t1 - t0;
      // As the prediction computed it (std::max(min_step, reach): a NaN g gives the minimum step), so that
      // a predicted step no longer than the safe one passes this test exactly, however t rounds.
      const V reach = size0 * inverse;
      const V safe = simd::select((M)(min_step < reach), reach, min_step);
      const M accepted = (M)(t1 <= t0 + safe) | (M)(size0 + size1 >= lipschitz * dt);
      taken |= simd::mask_bits<2>(accepted) << i;
      crosses |= simd::mask_bits<2>((M)(g0 < zero) ^ (M)(g1 < zero)) << i;
      simd::store(slope + i, simd::abs<V, M>(g1 - g0) / dt);  // NaN past n (no step), never read there
    }
    // The steps taken: those before the first refused one, of the n predicted.
    const int walked = std::countr_one(taken & ((1u << n) - 1));
    const auto steepest_of = [&](int count) {  // the steepest of the first `count` steps and `steepest`
      double m = steepest;
      for (int i = 0; i < count; ++i) m = std::max(m, slope[i]);
      return m;
    };
    for (std::uint32_t roots = crosses & ((1u << walked) - 1); roots != 0; roots &= roots - 1) {
      const int i = std::countr_zero(roots);
      if (!on_root(refine_root(g, t0s[i], g0s[i], ts[i], gs[i], s.tolerance))) {
        on_slope(steepest_of(i + 1));
        return gs[i];
      }
    }
    steepest = steepest_of(walked);
    if (walked > 0) {
      approach =
          (std::fabs(g0s[walked - 1]) - std::fabs(gs[walked - 1])) / (ts[walked - 1] - t0s[walked - 1]);
      t = ts[walked - 1], gt = gs[walked - 1];
    } else {
      approach = s.lipschitz;  // the first step refused (over-relaxed, not covered): no relaxation next
    }
  }
  on_slope(steepest);
  return gt;
}

}  // namespace snell::geometry
