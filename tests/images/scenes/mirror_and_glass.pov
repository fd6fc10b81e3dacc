// Mirror reflection, Fresnel reflection and refraction through a glass sphere with an ior.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2, -6> look_at <0, 0.7, 0> right x*4/3 }
background { color rgb <0.5, 0.6, 0.9> }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, 0 pigment { color rgb <0.8, 0.6, 0.4> } finish { diffuse 0.7 } }
box { <-5, 0, 3>, <5, 3, 3.5> pigment { color rgb <0.2, 0.5, 0.3> } }
sphere { <-1.2, 1, 0.5>, 1 pigment { color rgb 0.9 } finish { diffuse 0.1 reflection 0.85 phong 0.5 } }
sphere { <1.2, 1, -0.5>, 1
  pigment { color rgbf <1, 1, 1, 0.95> }
  finish { diffuse 0 ambient 0 reflection { 0, 1 fresnel on } specular 0.8 roughness 0.001 }
  interior { ior 1.5 } }
