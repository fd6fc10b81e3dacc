// Several noisy isosurfaces, the heavier scene of tools/bench-shapes.sh (render at 640x480):
// spheres and a torus displaced by noise3d, a twisted box and a rippled slab, each with its own
// max_gradient. Plain POV-Ray 3.7 syntax, so that povray renders it too.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.6, 0> angle 45 }
light_source { <-6, 10, -8> color rgb 1.2 }
light_source { <8, 6, -3> color rgb 0.4 }
background { color rgb <0.55, 0.65, 0.85> }

#declare Rough = function { f_sphere(x, y, z, 1) - f_noise3d(x * 3, y * 3, z * 3) * 0.45 }
#declare Knot = function { f_torus(x, y, z, 1.0, 0.35) - f_noise3d(x * 5, y * 5, z * 5) * 0.2 }
#declare Twist = function { f_rounded_box(x * cos(y) - z * sin(y), y, x * sin(y) + z * cos(y), 0.15, 0.7, 1, 0.7) }

isosurface {
  function { Rough(x, y, z) }
  contained_by { sphere { 0, 1.6 } }
  max_gradient 2.5
  translate <-2.6, 1, 0>
  pigment { color rgb <0.9, 0.55, 0.3> }
  finish { specular 0.4 roughness 0.02 }
}
isosurface {
  function { Knot(x, y, z) }
  contained_by { box { <-1.6, -0.8, -1.6>, <1.6, 0.8, 1.6> } }
  max_gradient 2.2
  rotate -60 * x
  translate <0, 1.2, 0.5>
  pigment { color rgb <0.35, 0.75, 0.45> }
  finish { specular 0.5 roughness 0.01 }
}
isosurface {
  function { Twist(x, y, z) }
  contained_by { box { <-1.3, -1.1, -1.3>, <1.3, 1.1, 1.3> } }
  max_gradient 1.4
  translate <2.6, 1.1, 0>
  pigment { color rgb <0.4, 0.5, 0.95> }
  finish { specular 0.6 roughness 0.01 }
}
isosurface {
  function { y - 0.15 * sin(x * 3) * cos(z * 3) - f_noise3d(x * 2, 0, z * 2) * 0.3 }
  contained_by { box { <-7, -0.6, -4>, <7, 0.6, 6> } }
  max_gradient 1.5
  translate -0.5 * y
  pigment { color rgb <0.8, 0.78, 0.7> }
  finish { diffuse 0.8 }
}
