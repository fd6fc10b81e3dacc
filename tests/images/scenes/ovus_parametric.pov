// ovus and parametric (a torus written as a parametric surface), the middle ovus in spiral2 (its default
// triangle wave): rendered by POV-Ray 3.7 into ../reference/ovus_parametric.png.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 0.5, 0> angle 40 }
light_source { <-5, 8, -6> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
plane { y, -1.2 pigment { color rgb <0.7, 0.7, 0.65> } }
ovus { 1, 0.6 translate <-2.3, -0.2, 0> pigment { color rgb <1, 0.8, 0.6> } finish { specular 0.5 } }
ovus { 0.6, 1 translate <0, -0.6, 0> pigment { spiral2 3 color_map { [0.5 color rgb <0.6, 1, 0.6>] [0.5 color rgb 0.2] } scale 0.6 rotate 90 * x } finish { specular 0.5 } }
parametric {
  function { cos(u) * (1.3 + 0.45 * cos(v)) } function { 0.45 * sin(v) } function { sin(u) * (1.3 + 0.45 * cos(v)) }
  <0, 0>, <2 * pi, 2 * pi>
  contained_by { box { -2, 2 } }
  max_gradient 2 accuracy 0.0005 precompute 10, x, y, z
  rotate -50 * x translate <2.3, 0.6, 0>
  pigment { color rgb <0.6, 0.7, 1> } finish { specular 0.5 }
}
