// Spotlight cone with falloff, light fading, a shadowless light and an orthographic camera.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 6, -6> look_at <0, 0, 0> right x*8 up y*6 }
light_source { <0, 6, 0> color rgb 1.5 spotlight point_at <1, 0, 1> radius 15 falloff 25 tightness 5 }
light_source { <-3, 2, -3> color rgb <0.4, 0.2, 0.1> fade_distance 2 fade_power 2 }
light_source { <3, 5, -3> color rgb 0.15 shadowless }
plane { y, 0 pigment { color rgb 0.8 } }
sphere { <1, 0.7, 1>, 0.7 pigment { color rgb <0.9, 0.9, 0.5> } }
union {
  sphere { <-1.5, 0.5, -0.5>, 0.5 }
  cylinder { <-1.5, 0, -0.5>, <-1.5, 1.5, -0.5>, 0.15 }
  pigment { color rgb <0.4, 0.7, 1> }
  finish { phong 0.7 }
}
