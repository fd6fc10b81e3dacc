// The foundation's shapes with transforms: box, cylinder (closed and open), cone, disc, torus,
// triangle, smooth_triangle and an inline mesh.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.5, 0> right x*4/3 angle 50 }
background { color rgb 0.15 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 4, -6> color rgb 0.4 }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.65> } }
box { <-0.6, 0, -0.6>, <0.6, 1, 0.6> rotate y*30 translate <-3, 0, 1.5> pigment { color rgb <0.8, 0.3, 0.3> } }
cylinder { <0, 0, 0>, <0, 1.4, 0>, 0.5 translate <-1, 0, 1.5> pigment { color rgb <0.3, 0.8, 0.3> } }
cylinder { <0, 0.2, 0>, <0, 1.2, 0>, 0.5 open rotate x*-30 translate <1, 0, 1.5> pigment { color rgb <0.3, 0.3, 0.8> } }
cone { <0, 0, 0>, 0.7, <0, 1.5, 0>, 0 translate <3, 0, 1.5> pigment { color rgb <0.8, 0.8, 0.3> } finish { phong 0.6 } }
disc { <0, 0.01, 0>, y, 0.7, 0.3 translate <-3, 0, -1.2> pigment { color rgb <0.8, 0.3, 0.8> } }
torus { 0.6, 0.2 rotate x*60 translate <-1, 0.8, -1.2> pigment { color rgb <0.3, 0.8, 0.8> } finish { phong 0.8 } }
triangle { <0, 0, 0>, <1.2, 0, 0>, <0.6, 1.4, 0> translate <0.4, 0, -1.2> pigment { color rgb <1, 0.6, 0.2> } }
smooth_triangle { <0, 0, 0>, <-1, 0, -1>, <1.2, 0, 0>, <1, 0, -1>, <0.6, 1.4, 0>, <0, 1, -1>
  translate <2.2, 0, -1.2> pigment { color rgb <0.6, 1, 0.2> } }
mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0.5, 0, 0.8> }
  triangle { <0, 0, 0>, <1, 0, 0>, <0.5, 0.9, 0.3> }
  triangle { <1, 0, 0>, <0.5, 0, 0.8>, <0.5, 0.9, 0.3> }
  triangle { <0.5, 0, 0.8>, <0, 0, 0>, <0.5, 0.9, 0.3> }
  scale 1.3 translate <-0.4, 0, -3.2>
  pigment { color rgb <0.9, 0.9, 0.9> }
}
