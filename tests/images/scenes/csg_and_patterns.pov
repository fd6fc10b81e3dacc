// CSG (glass merge, difference, intersection lens, clipped quadric) over checker and gradient pigments.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2.5, -6> look_at <0, 0.5, 0> right x*4/3 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 4, -3> color rgb 0.3 }
plane { y, -0.5 pigment { checker color rgb 0.9 color rgb 0.25 } }
box { <-6, -0.5, 4>, <6, 5, 4.2>
  pigment { gradient y color_map { [0 color rgb <0.9, 0.4, 0.2>] [1 color rgb <0.2, 0.4, 0.9>] } scale 2 } }
merge {
  sphere { <-0.4, 0, 0>, 0.6 }
  sphere { <0.4, 0, 0>, 0.6 }
  translate <-2, 0.3, 0>
  pigment { color rgbf <1, 1, 1, 0.9> }
  finish { ambient 0 diffuse 0.05 reflection { 0, 1 fresnel on } specular 0.6 roughness 0.01 }
  interior { ior 1.5 }
}
difference {
  box { <-0.6, -0.5, -0.6>, <0.6, 0.7, 0.6> }
  sphere { <0, 0.7, 0>, 0.55 pigment { color rgb <1, 0.9, 0.2> } }
  rotate y*30
  pigment { color rgb <0.3, 0.7, 0.4> }
  finish { phong 0.5 }
}
intersection {
  sphere { <0, 0, -0.7>, 1 }
  sphere { <0, 0, 0.7>, 1 }
  rotate y*60
  translate <2, 0.4, 0>
  pigment { color rgb <0.9, 0.5, 0.8> }
  finish { phong 0.8 }
}
quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.09
  clipped_by { box { <-1, -0.5, -1>, <1, 1.8, 1> } }
  translate <0, 0, 2.2>
  pigment { color rgb <0.4, 0.6, 1> }
}
