#pragma once
// Root finding along a ray for implicit surfaces g(t) = 0 whose slope is bounded, |dg/dt| <= L: sphere
// tracing (Hart 1996, "Sphere tracing: a geometric method for the antialiased ray tracing of implicit
// surfaces", The Visual Computer 12(10)) to bracket each sign change, then Illinois regula falsi (Dowell &
// Jarratt 1971) to refine it. Shared by isosurface and superellipsoid.
#include <algorithm>
#include <cmath>

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

/// march_roots with g evaluated at up to K points per call, `g_lanes(ts, n, out)` (out[i] = g(ts[i]),
/// n <= K), for functions whose multi-point evaluation costs much less than n single ones. Each pass
/// predicts the next K steps of the scalar march, assuming |g| keeps shrinking at the rate of the last step
/// taken, evaluates them at once, and walks them accepting a step as march_roots does: when it is no
/// longer than the safe step max(|g| / L, min_step) from its start, or when the Lipschitz balls of its
/// ends cover it. The first step refused ends the pass and the next pass starts there, so the march
/// proves exactly what march_roots proves; a wrong prediction only wastes lanes. Where the safe step is
/// the minimum step (a loose bound L), all K steps are taken in one pass. Roots are refined with g.
template <int K, typename G, typename GLanes, typename OnRoot, typename OnSlope>
double march_roots_lanes(const G& g, const GLanes& g_lanes, double t, double gt, double hi,
                         const MarchSettings& s, OnRoot&& on_root, OnSlope&& on_slope) {
  const double inverse_lipschitz = 1 / s.lipschitz;
  const auto covered = [&](double t0, double g0, double t1, double g1) {
    return std::fabs(g0) + std::fabs(g1) >= s.lipschitz * (t1 - t0);
  };
  double approach = 0;  // how fast |g| shrank per unit t over the last step taken
  while (t < hi) {
    // Predicted steps: over-relaxed as march_roots while the predicted |g| allows.
    double ts[K], gs[K];
    int n = 0;
    const double rate = std::isnan(approach) ? s.lipschitz : std::clamp(approach, -s.lipschitz, s.lipschitz);
    const double omega = std::clamp(1.9 / (1 + std::max(rate, 0.0) * inverse_lipschitz), 1.0, 1.9);
    for (double pt = t, pg = std::fabs(gt); n < K && pt < hi;) {
      const double reach = pg * inverse_lipschitz;
      const double step = reach > s.min_step ? omega * reach : s.min_step;
      pt = std::min(hi, pt + step);  // pt + step, rounded as the walk below rounds t0 + safe
      ts[n++] = pt;
      pg = std::max(0.0, pg - rate * step);
    }
    g_lanes(ts, n, gs);
    double t0 = t, g0 = gt;
    int taken = 0;
    for (; taken < n; ++taken) {
      const double t1 = ts[taken], g1 = gs[taken];
      // As the prediction computed it (min_step first: a NaN g gives the minimum step), so that a
      // predicted step no longer than the safe one passes this test exactly, however t rounds.
      const double safe = std::max(s.min_step, std::fabs(g0) * inverse_lipschitz);
      if (!(t1 <= t0 + safe || covered(t0, g0, t1, g1))) break;
      on_slope(std::fabs(g1 - g0) / (t1 - t0));
      approach = (std::fabs(g0) - std::fabs(g1)) / (t1 - t0);
      if ((g0 < 0) != (g1 < 0) && !on_root(refine_root(g, t0, g0, t1, g1, s.tolerance))) return g1;
      t0 = t1, g0 = g1;
    }
    // The first step refused (it was over-relaxed and not covered): predict no relaxation next time.
    if (taken == 0) approach = s.lipschitz;
    t = t0, gt = g0;
  }
  return gt;
}

}  // namespace snell::geometry
