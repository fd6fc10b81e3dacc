#include "snell/scene/blur_confidence.hpp"

#include <cmath>
#include <stdexcept>

namespace snell::scene {

namespace {

/// Regularised lower incomplete gamma P(a, x): its power series below a + 1, else 1 - Q from Q's
/// continued fraction (Abramowitz & Stegun 6.5.29 and 6.5.31; Lentz's method).
double gamma_p(double a, double x) {
  if (x <= 0) return 0;
  const double log_prefix = a * std::log(x) - x - std::lgamma(a);
  if (x < a + 1) {
    double term = 1 / a, sum = term;
    for (int n = 1; n < 1000; ++n) {
      term *= x / (a + n);
      sum += term;
      if (std::fabs(term) < std::fabs(sum) * 1e-15) break;
    }
    return sum * std::exp(log_prefix);
  }
  constexpr double kTiny = 1e-300;
  double b = x + 1 - a, c = 1 / kTiny, d = 1 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    const double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1 / d;
    const double step = d * c;
    h *= step;
    if (std::fabs(step - 1) < 1e-15) break;
  }
  return 1 - std::exp(log_prefix) * h;
}

}  // namespace

double chi_square_upper_quantile(double dof, double tail) {
  if (!(dof > 0) || !(tail > 0 && tail < 1)) throw std::invalid_argument("chi-square quantile out of range");
  // P(X > x) = 1 - P(dof/2, x/2) falls monotonically in x: bisect.
  double lo = 0, hi = dof + 10 * std::sqrt(2 * dof) + 100;
  for (int i = 0; i < 200 && hi - lo > 1e-12 * (1 + hi); ++i) {
    const double mid = 0.5 * (lo + hi);
    if (1 - gamma_p(0.5 * dof, 0.5 * mid) > tail)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

std::vector<double> blur_variance_thresholds(int max_samples, double confidence, double variance) {
  std::vector<double> t(static_cast<size_t>(std::max(max_samples, 1)), 0.0);
  if (max_samples <= 1) return t;
  const double scale = variance / chi_square_upper_quantile(max_samples - 1, confidence);
  for (int n = 1; n <= max_samples; ++n) t[n - 1] = scale * chi_square_upper_quantile(n, confidence);
  return t;
}

int blur_batch_size(int batch, int max_samples) {
  // POV-Ray's hexagonal lens grids are traced ring by ring (7, 6, 6, 4, ... points), then 4 at a time.
  static constexpr int kLarge[] = {7, 6, 6, 4, 4, 4, 4, 2};
  static constexpr int kMedium[] = {7, 6, 6};
  if (max_samples >= 37 && batch < 8) return kLarge[batch];
  if (max_samples >= 19 && max_samples < 37 && batch < 3) return kMedium[batch];
  if (max_samples >= 7 && max_samples < 19 && batch < 1) return 7;
  return 4;
}

}  // namespace snell::scene
