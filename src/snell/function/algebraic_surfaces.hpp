#pragma once
// The algebraic surfaces of functions.inc (POV-Ray 3.7 reference, "Internal Functions"): each is a
// polynomial P(x, y, z) that vanishes on the surface, returned as clamp(strength * S, -10, 10) where
// S = -P or P is signed so that the inside is positive, as POV-Ray's vm/fnintern.cpp returns them
// (an isosurface then draws them at threshold 0). Arguments: a[0..2] = x, y, z; a[3] = field strength;
// a[4..] = the surface's own parameters in documented order.

namespace snell::function::surfaces {

double bicorn(const double* a);                // 4: strength, scale
double bifolia(const double* a);               // 5: strength, scale
double crossed_trough(const double* a);        // 11
double cubic_saddle(const double* a);          // 12
double devils_curve(const double* a);          // 14
double glob(const double* a);                  // 22
double heart(const double* a);                 // 23
double hunt_surface(const double* a);          // 30
double klein_bottle(const double* a);          // 35
double kummer_surface_v1(const double* a);     // 36
double mitre(const double* a);                 // 41
double nodal_cubic(const double* a);           // 42
double paraboloid(const double* a);            // 45
double pillow(const double* a);                // 48
double piriform(const double* a);              // 49
double quartic_paraboloid(const double* a);    // 54
double quartic_saddle(const double* a);        // 55
double steiners_roman(const double* a);        // 65
double torus2(const double* a);                // 71: strength, major radius, minor radius
double torus_gumdrop(const double* a);         // 72
double umbrella(const double* a);              // 73
double witch_of_agnesi(const double* a);       // 74: strength, a
double cushion(const double* a);               // 13 (and f_odd, 43: the same quartic)
double folium_surface(const double* a);        // 20: strength, neck width, divergence
double hyperbolic_torus(const double* a);      // 31: strength, major radius, minor radius
double kampyle_of_eudoxus(const double* a);    // 33: strength, dimple, closeness
double kummer_surface_v2(const double* a);     // 37: strength, rod width, divergence, influence
double lemniscate_of_gerono(const double* a);  // 38
double ovals_of_cassini(const double* a);      // 44: strength, radius, filling, thickness
double parabolic_torus(const double* a);       // 46: strength, major radius, minor radius
double quartic_cylinder(const double* a);      // 56: strength, diameter, bulge
double strophoid(const double* a);             // 66: strength, size of bulb, sharpness, flatness
/// Not clamped fields: three Gaussian ellipsoids stretched along the axes, blended by their maximum
/// (cross, 10) or minimum (intersection, 32); parameters eccentricity, sharpness, flatness, threshold.
double cross_ellipsoids(const double* a);  // 10
double isect_ellipsoids(const double* a);  // 32

}  // namespace snell::function::surfaces
