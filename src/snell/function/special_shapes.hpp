#pragma once
// The remaining shapes of functions.inc that are neither plain polynomials nor plane curves: Boy's and
// Enneper's surfaces, the comma, Dupin's cyclide, the hexagonal tilings, the second helix, the helical
// torus and the quantum orbital (POV-Ray 3.7 reference, "Internal Functions"; behaviour of vm/fnintern.cpp,
// including its quirks where they change the shape, each noted).

namespace snell::function::special {

double boy_surface(const double* a);    // 8: strength, scale
double comma(const double* a);          // 9: radius
double dupin_cyclid(const double* a);   // 16: strength, major, minor, 3 more shape parameters
double enneper(const double* a);        // 18: strength
double helical_torus(const double* a);  // 24: 10 parameters
double helix2(
    const double* a);           // 26: (unused), period, minor radius, major radius, (unused), shape, (unused)
double hex_x(const double* a);  // 27: (unused)
double hex_y(const double* a);  // 28: (unused)
double quantum(const double* a);  // 53: (unused)

}  // namespace snell::function::special
