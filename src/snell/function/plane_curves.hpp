#pragma once
// functions.inc's "_2d" functions: a plane curve f(x, y) = 0 either extruded along z or, when the sweep
// flag is positive, revolved round the y axis at a distance and tilted by an angle (POV-Ray 3.7
// reference, "Internal Functions", and vm/fnintern.cpp's ROT2D). Arguments a[0..2] = x, y, z; then the
// curve's own parameters, then sweep flag, distance, angle (degrees). Fields clamped to [-10, 10].
// Also the shapes built from Gaussian blobs and the y-polynomial cylinder of the same list.

namespace snell::function::curves {

double devils_curve_2d(const double* a);          // 15: strength, x factor, y factor, sweep, dist, angle
double folium_surface_2d(const double* a);        // 21: strength, neck, divergence, sweep, dist, angle
double kampyle_of_eudoxus_2d(const double* a);    // 34: strength, dimple, closeness, sweep, dist, angle
double lemniscate_of_gerono_2d(const double* a);  // 39: strength, size, width, sweep, dist, angle
double piriform_2d(const double* a);         // 50: strength, x^3 factor, x^4 factor, y^2 factor, sweep...
double strophoid_2d(const double* a);        // 67: strength, bulb, sharpness, flatness, sweep, dist, angle
double witch_of_agnesi_2d(const double* a);  // 75: strength, a, b, sweep, dist, angle
double spikes(const double* a);              // 62: spikiness, hollowness, size, roundness, fatness
double spikes_2d(const double* a);           // 63: height, x frequency, z frequency, rate
double blob(const double* a);                // 6: separation, inverse size 1, strength 1, inverse size 2...
double blob2(const double* a);               // 7: separation, inverse size, strength, threshold
double algbr_cyl1(const double* a);    // 0: strength, clamp, sweep, distance, angle (as the other three)
double algbr_cyl2(const double* a);    // 1
double algbr_cyl3(const double* a);    // 2
double algbr_cyl4(const double* a);    // 3
double flange_cover(const double* a);  // 19: spikiness, hollowness, size, threshold
double polytubes(const double* a);     // 52: tubes, c0 .. c4 (the tubes' distance from y as a quartic)
double spiral(const double* a);        // 64: step, thickness, outer radius, (unused), (unused), shape
double mesh1(const double* a);         // 40: x spacing, z spacing, thickness, amplitude, y scale
double poly4(const double* a);         // 51: the radius as a quartic in y: c0 .. c4

}  // namespace snell::function::curves
