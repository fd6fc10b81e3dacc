#include "snell/function/builtins.hpp"

#include <algorithm>
#include <cmath>

#include "snell/math/constants.hpp"

namespace snell::function {

namespace {

double f_abs(double a) {
  return std::fabs(a);
}
double f_sqr(double a) {
  return a * a;
}
double f_sqrt(double a) {
  return std::sqrt(a);
}
double f_sin(double a) {
  return std::sin(a);
}
double f_cos(double a) {
  return std::cos(a);
}
double f_atan2(double a, double b) {
  return std::atan2(a, b);
}

const Builtin kBuiltins[] = {
    {"abs", f_abs, nullptr},
    {"acos", [](double a) { return std::acos(a); }, nullptr},
    {"acosh", [](double a) { return std::acosh(a); }, nullptr},
    {"asin", [](double a) { return std::asin(a); }, nullptr},
    {"asinh", [](double a) { return std::asinh(a); }, nullptr},
    {"atan", [](double a) { return std::atan(a); }, nullptr},
    {"atanh", [](double a) { return std::atanh(a); }, nullptr},
    {"ceil", [](double a) { return std::ceil(a); }, nullptr},
    {"cos", f_cos, nullptr},
    {"cosh", [](double a) { return std::cosh(a); }, nullptr},
    {"degrees", [](double a) { return a * 180 / math::kPi; }, nullptr},
    {"exp", [](double a) { return std::exp(a); }, nullptr},
    {"floor", [](double a) { return std::floor(a); }, nullptr},
    {"int", [](double a) { return std::trunc(a); }, nullptr},
    {"ln", [](double a) { return std::log(a); }, nullptr},
    {"log", [](double a) { return std::log10(a); }, nullptr},
    {"radians", [](double a) { return a * math::kPi / 180; }, nullptr},
    {"sin", f_sin, nullptr},
    {"sinh", [](double a) { return std::sinh(a); }, nullptr},
    {"sqr", f_sqr, nullptr},
    {"sqrt", f_sqrt, nullptr},
    {"tan", [](double a) { return std::tan(a); }, nullptr},
    {"tanh", [](double a) { return std::tanh(a); }, nullptr},
    {"atan2", nullptr, f_atan2},
    {"pow", nullptr, [](double a, double b) { return std::pow(a, b); }},
    {"mod", nullptr, [](double a, double b) { return std::fmod(a, b); }},
    {"div", nullptr, [](double a, double b) { return std::trunc(a / b); }},
};

}  // namespace

std::span<const Builtin> builtins() {
  return kBuiltins;
}

double builtin_min(double a, double b) {
  return std::min(a, b);
}

double builtin_max(double a, double b) {
  return std::max(a, b);
}

LaneKernel lane_kernel(double (*unary)(double)) {
  if (unary == f_abs) return LaneKernel::abs;
  if (unary == f_sqr) return LaneKernel::sqr;
  if (unary == f_sqrt) return LaneKernel::sqrt;
  if (unary == f_sin) return LaneKernel::sin;
  if (unary == f_cos) return LaneKernel::cos;
  return LaneKernel::none;
}

LaneKernel lane_kernel(double (*binary)(double, double)) {
  if (binary == f_atan2) return LaneKernel::atan2;
  if (binary == builtin_min) return LaneKernel::min;
  if (binary == builtin_max) return LaneKernel::max;
  return LaneKernel::none;
}

}  // namespace snell::function
