// The algebraic surfaces of functions.inc against POV-Ray 3.7.0.10's own values: each number below was
// printed by POV-Ray's parser (`#debug str(f_name(x, y, z, params...), 0, 15)` with functions.inc), not
// computed by snell.
#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "snell/function/function.hpp"
#include "snell/function/internals.hpp"

namespace snell::function {
namespace {

struct Reference {
  const char* name;
  int number;  // internal(N) in functions.inc
  std::vector<double> arguments;
  double povray;
};

const Reference kReferences[] = {
    {"f_bicorn", 4, {0.3, -0.2, 0.5, 1, 0.8}, -0.372400000000000},
    {"f_bicorn", 4, {0.71, 0.43, -0.26, 1, 0.8}, -0.371399420000000},
    {"f_bifolia", 5, {0.3, -0.2, 0.5, 1, 3}, -0.348400000000000},
    {"f_bifolia", 5, {0.71, 0.43, -0.26, 1, 3}, 0.165049440000000},
    {"f_crossed_trough", 11, {0.3, -0.2, 0.5, 1}, 0.222500000000000},
    {"f_crossed_trough", 11, {0.71, 0.43, -0.26, 1}, -0.395922840000000},
    {"f_cubic_saddle", 12, {0.3, -0.2, 0.5, 1}, 0.465000000000000},
    {"f_cubic_saddle", 12, {0.71, 0.43, -0.26, 1}, -0.538404000000000},
    {"f_devils_curve", 14, {0.3, -0.2, 0.5, 1}, -0.091600000000000},
    {"f_devils_curve", 14, {0.71, 0.43, -0.26, 1}, -0.157401880000000},
    {"f_glob", 22, {0.3, -0.2, 0.5, 1}, -0.284735000000000},
    {"f_glob", 22, {0.71, 0.43, -0.26, 1}, -0.035230127450000},
    {"f_heart", 23, {0.3, -0.2, 0.5, 1}, 0.155002000000000},
    {"f_heart", 23, {0.71, 0.43, -0.26, 1}, -0.021854151103000},
    {"f_hunt_surface", 30, {0.3, -0.2, 0.5, 0.01}, 10.000000000000000},
    {"f_hunt_surface", 30, {0.71, 0.43, -0.26, 0.01}, 10.000000000000000},
    {"f_klein_bottle", 35, {0.3, -0.2, 0.5, 1}, -1.462632000000000},
    {"f_klein_bottle", 35, {0.71, 0.43, -0.26, 1}, -3.676250255896000},
    {"f_kummer_surface_v1", 36, {0.3, -0.2, 0.5, 1}, -0.656100000000000},
    {"f_kummer_surface_v1", 36, {0.71, 0.43, -0.26, 1}, -0.396490090000000},
    {"f_mitre", 41, {0.3, -0.2, 0.5, 1}, -0.108400000000000},
    {"f_mitre", 41, {0.71, 0.43, -0.26, 1}, -1.387395490000000},
    {"f_nodal_cubic", 42, {0.3, -0.2, 0.5, 1}, -0.717000000000000},
    {"f_nodal_cubic", 42, {0.71, 0.43, -0.26, 1}, -0.732731000000000},
    {"f_paraboloid", 45, {0.3, -0.2, 0.5, 1}, -0.540000000000000},
    {"f_paraboloid", 45, {0.71, 0.43, -0.26, 1}, -0.141700000000000},
    {"f_pillow", 48, {0.3, -0.2, 0.5, 1}, -0.307800000000000},
    {"f_pillow", 48, {0.71, 0.43, -0.26, 1}, -0.463725420000000},
    {"f_piriform", 49, {0.3, -0.2, 0.5, 1}, 0.271100000000000},
    {"f_piriform", 49, {0.71, 0.43, -0.26, 1}, 0.148705810000000},
    {"f_quartic_paraboloid", 54, {0.3, -0.2, 0.5, 1}, -0.270600000000000},
    {"f_quartic_paraboloid", 54, {0.71, 0.43, -0.26, 1}, 0.171313430000000},
    {"f_quartic_saddle", 55, {0.3, -0.2, 0.5, 1}, -0.145600000000000},
    {"f_quartic_saddle", 55, {0.71, 0.43, -0.26, 1}, 0.180452950000000},
    {"f_steiners_roman", 65, {0.3, -0.2, 0.5, 1}, -0.006100000000000},
    {"f_steiners_roman", 65, {0.71, 0.43, -0.26, 1}, -0.060406490000000},
    {"f_torus2", 71, {0.3, -0.2, 0.5, 1, 0.8, 0.3}, 0.005500000000000},
    {"f_torus2", 71, {0.71, 0.43, -0.26, 1, 0.8, 0.3}, -0.243651560000000},
    {"f_torus_gumdrop", 72, {0.3, -0.2, 0.5, 1}, -10.000000000000000},
    {"f_torus_gumdrop", 72, {0.71, 0.43, -0.26, 1}, -5.303341490000001},
    {"f_umbrella", 73, {0.3, -0.2, 0.5, 1}, -0.140000000000000},
    {"f_umbrella", 73, {0.71, 0.43, -0.26, 1}, -0.475032000000000},
    {"f_witch_of_agnesi", 74, {0.3, -0.2, 0.5, 1, 0.4}, 0.548000000000000},
    {"f_witch_of_agnesi", 74, {0.71, 0.43, -0.26, 1, 0.4}, -0.017831000000000},
    {"f_cushion", 13, {0.3, -0.2, 0.5, 1}, -0.146900000000000},
    {"f_cushion", 13, {0.71, 0.43, -0.26, 1}, -0.035212840000000},
    {"f_odd", 43, {0.3, -0.2, 0.5, 1}, -0.146900000000000},
    {"f_odd", 43, {0.71, 0.43, -0.26, 1}, -0.035212840000000},
    {"f_folium_surface", 20, {0.3, -0.2, 0.5, 1, 0.3, 0.5}, 0.364100000000000},
    {"f_folium_surface", 20, {0.71, 0.43, -0.26, 1, 0.3, 0.5}, 0.883157500000000},
    {"f_hyperbolic_torus", 31, {0.3, -0.2, 0.5, 1, 0.8, 0.3}, -0.594500000000000},
    {"f_hyperbolic_torus", 31, {0.71, 0.43, -0.26, 1, 0.8, 0.3}, -0.254737960000000},
    {"f_kampyle_of_eudoxus", 33, {0.3, -0.2, 0.5, 1, 0.4, 1.5}, -0.304175000000000},
    {"f_kampyle_of_eudoxus", 33, {0.71, 0.43, -0.26, 1, 0.4, 1.5}, 0.137786822500000},
    {"f_kummer_surface_v2", 37, {0.3, -0.2, 0.5, 1, -0.9, 0.4, 1.2}, 1.291360000000000},
    {"f_kummer_surface_v2", 37, {0.71, 0.43, -0.26, 1, -0.9, 0.4, 1.2}, 1.427405224000000},
    {"f_lemniscate_of_gerono", 38, {0.3, -0.2, 0.5, 1}, -0.208100000000000},
    {"f_lemniscate_of_gerono", 38, {0.71, 0.43, -0.26, 1}, -0.002516810000000},
    {"f_ovals_of_cassini", 44, {0.3, -0.2, 0.5, 1, 0.6, 0.3, 2}, -0.212800000000000},
    {"f_ovals_of_cassini", 44, {0.71, 0.43, -0.26, 1, 0.6, 0.3, 2}, -0.745171560000000},
    {"f_parabolic_torus", 46, {0.3, -0.2, 0.5, 1, 0.8, 0.3}, -0.760700000000000},
    {"f_parabolic_torus", 46, {0.71, 0.43, -0.26, 1, 0.8, 0.3}, -0.747003000000000},
    {"f_quartic_cylinder", 56, {0.3, -0.2, 0.5, 1, 0.7, 0.5}, 0.023900000000000},
    {"f_quartic_cylinder", 56, {0.71, 0.43, -0.26, 1, 0.7, 0.5}, -0.126132330000000},
    {"f_strophoid", 66, {0.3, -0.2, 0.5, 1, 0.5, 1.2, 0.8}, -0.214920000000000},
    {"f_strophoid", 66, {0.71, 0.43, -0.26, 1, 0.5, 1.2, 0.8}, 0.266650040000000},
    {"f_cross_ellipsoids", 10, {0.3, -0.2, 0.5, 2, 3, 1, 0.4}, 0.183464332683993},
    {"f_cross_ellipsoids", 10, {0.71, 0.43, -0.26, 2, 3, 1, 0.4}, 0.351553733381884},
    {"f_isect_ellipsoids", 32, {0.3, -0.2, 0.5, 2, 3, 1, 0.4}, 0.284674878961937},
    {"f_isect_ellipsoids", 32, {0.71, 0.43, -0.26, 2, 3, 1, 0.4}, 0.386921688088033},
};

TEST(AlgebraicSurfaces, EqualPovRaysValues) {
  for (const Reference& r : kReferences) {
    const auto f = internal_function(r.number);
    ASSERT_EQ(f->arity(), r.arguments.size()) << r.name;
    EXPECT_NEAR((*f)(std::span<const double>(r.arguments)), r.povray, 1e-12 * (1 + std::abs(r.povray)))
        << r.name;
  }
}

TEST(AlgebraicSurfaces, FieldIsClampedToTen) {
  // Far from the origin every polynomial is huge; POV-Ray clamps the field to [-10, 10].
  const auto torus2 = internal_function(71);
  EXPECT_DOUBLE_EQ((*torus2)(std::span<const double>(std::vector<double>{50, 0, 0, 1, 0.8, 0.3})), -10);
  const auto pillow = internal_function(48);
  EXPECT_DOUBLE_EQ((*pillow)(std::span<const double>(std::vector<double>{50, 0, 0, 1})), 10);
}

}  // namespace
}  // namespace snell::function
