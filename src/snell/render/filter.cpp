#include "snell/render/filter.hpp"

#include <charconv>
#include <cmath>

#include "snell/math/constants.hpp"

namespace snell::render {

namespace {

/// Mitchell & Netravali, "Reconstruction filters in computer graphics" (SIGGRAPH 1988), B = C = 1/3, on
/// [-2, 2]; its integral is 1.
double mitchell(double x) {
  constexpr double b = 1.0 / 3, c = 1.0 / 3;
  x = std::fabs(x);
  if (x >= 2) return 0;
  if (x < 1) return ((12 - 9 * b - 6 * c) * x * x * x + (-18 + 12 * b + 6 * c) * x * x + (6 - 2 * b)) / 6;
  return ((-b - 6 * c) * x * x * x + (6 * b + 30 * c) * x * x + (-12 * b - 48 * c) * x + (8 * b + 24 * c)) /
         6;
}

/// The Gaussian's standard deviation: a third of the radius, so the truncated tail is small.
double sigma(double radius) {
  return radius / 3;
}

}  // namespace

Filter::Filter(Kind kind, double radius) : kind_(kind), radius_(radius) {
  switch (kind) {
    case Kind::box:
      scale_ = 1 / (2 * radius);
      break;
    case Kind::tent:
      scale_ = 1 / radius;
      break;
    case Kind::gaussian: {
      // Shifted down so it reaches 0 at the radius: integral of exp(-x^2/2s^2) - exp(-r^2/2s^2) over [-r, r].
      const double s = sigma(radius);
      const double integral = s * std::sqrt(2 * math::kPi) * std::erf(radius / (s * std::sqrt(2.0))) -
                              2 * radius * std::exp(-radius * radius / (2 * s * s));
      scale_ = 1 / integral;
      break;
    }
    case Kind::mitchell:
      scale_ = 2 / radius;  // x is scaled by 2/radius onto Mitchell's [-2, 2]
      break;
  }
}

double Filter::value(double x) const {
  const double a = std::fabs(x);
  if (a > radius_) return 0;
  switch (kind_) {
    case Kind::box:
      return scale_;
    case Kind::tent:
      return scale_ * (1 - a / radius_);
    case Kind::gaussian: {
      const double s2 = 2 * sigma(radius_) * sigma(radius_);
      return scale_ * (std::exp(-a * a / s2) - std::exp(-radius_ * radius_ / s2));
    }
    case Kind::mitchell:
      return scale_ * mitchell(2 * a / radius_);
  }
  return 0;
}

std::optional<Filter> Filter::parse(std::string_view text) {
  const size_t colon = text.find(':');
  const std::string_view name = text.substr(0, colon);
  Kind kind;
  double radius;
  if (name == "box") {
    kind = Kind::box, radius = 0.5;
  } else if (name == "tent") {
    kind = Kind::tent, radius = 1;
  } else if (name == "gaussian") {
    kind = Kind::gaussian, radius = 1.5;
  } else if (name == "mitchell") {
    kind = Kind::mitchell, radius = 2;
  } else {
    return std::nullopt;
  }
  if (colon != std::string_view::npos) {
    const std::string_view r = text.substr(colon + 1);
    const auto [end, ec] = std::from_chars(r.data(), r.data() + r.size(), radius);
    if (ec != std::errc{} || end != r.data() + r.size() || !(radius > 0) || radius > 16) return std::nullopt;
  }
  return Filter(kind, radius);
}

}  // namespace snell::render
