// ovus, lemon and parametric: an egg, two lemons (one open) and a parametric trefoil-like twisted torus.
// snell scenes/curved_shapes.pov -w 480 -h 360 -o docs/images/curved_shapes.png
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -10> look_at <0, 0.8, 0> angle 42 }
light_source { <-6, 10, -8> color rgb 1.1 }
light_source { <7, 5, -4> color rgb 0.35 }
background { color rgb <0.5, 0.6, 0.8> }
plane { y, 0 pigment { checker color rgb 0.85 color rgb 0.6 scale 1.5 } }

ovus { 1, 0.65 translate <-3.2, 1, 0> pigment { color rgb <0.95, 0.85, 0.7> } finish { specular 0.4 } }
lemon { <-0.9, 0.01, 0>, 0.35, <-0.9, 2.4, 0>, 0.15, 1.7
  pigment { color rgb <1, 0.85, 0.15> } finish { specular 0.5 roughness 0.02 } }
lemon { <0.6, 0.01, -0.6>, 0.4, <0.6, 1.6, -0.6>, 0.4, 1.2 open
  pigment { color rgb <0.4, 0.8, 0.3> } finish { specular 0.5 } }
parametric {
  function { cos(u) * (1.1 + 0.35 * cos(v + 3 * u)) }
  function { 0.35 * sin(v + 3 * u) }
  function { sin(u) * (1.1 + 0.35 * cos(v + 3 * u)) }
  <0, 0>, <2 * pi, 2 * pi>
  contained_by { box { -2, 2 } }
  accuracy 0.0005
  rotate -35 * x translate <3, 1.3, 0.3>
  pigment { uv_mapping checker color rgb <0.3, 0.45, 1> color rgb 0.95 scale <pi / 8, pi / 2, 1> }
  finish { specular 0.6 roughness 0.01 }
}
