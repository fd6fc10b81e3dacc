// Diffuse, brilliance, phong, specular and metallic highlights under two coloured point lights.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.6, 0> right x*4/3 }
background { color rgb <0.1, 0.12, 0.2> }
light_source { <-5, 6, -5> color rgb <1, 0.9, 0.8> }
light_source { <6, 3, -2> color rgb <0.3, 0.4, 0.8> }
plane { y, 0 pigment { color rgb 0.6 } finish { diffuse 0.8 ambient 0.1 } }
sphere { <-1.8, 0.8, 0>, 0.8 pigment { color rgb <0.9, 0.2, 0.2> } finish { phong 0.9 phong_size 40 } }
sphere { <0, 0.8, 0>, 0.8 pigment { color rgb <0.2, 0.8, 0.3> } finish { specular 0.7 roughness 0.02 brilliance 2 } }
sphere { <1.8, 0.8, 0>, 0.8 pigment { color rgb <0.9, 0.7, 0.2> } finish { phong 1 metallic diffuse 0.4 } }
