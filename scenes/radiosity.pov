// snell radiosity (docs/language.md "Radiosity"): a room corner lit by one light and a blue sky. With
// `radiosity {}` the surfaces light each other: the red and green walls bleed their colour onto the white
// floor and the spheres, and the shadows fill with sky light instead of a flat `ambient`.
// Render: snell render scenes/radiosity.pov -o radiosity.png -w 400 -h 300
#version 3.7;
global_settings { assumed_gamma 1.0 radiosity { count 60 recursion_limit 1 brightness 1 } }

camera { location <0.5, 2.2, -5.5> look_at <0, 0.9, 0> angle 50 }
light_source { <-3, 7, -4> color rgb <1.0, 0.95, 0.85> }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.7, 0.8, 1.0>] [1 rgb <0.25, 0.4, 0.9>] } } }

#declare Matte = finish { diffuse 0.75 ambient 0.3 }  // ambient is ignored once radiosity is on
plane { y, 0 pigment { rgb 0.85 } finish { Matte } }
box { <-2.5, 0, 2>, <2.5, 3, 2.2> pigment { rgb 0.85 } finish { Matte } }
box { <-2.7, 0, -1>, <-2.5, 3, 2.2> pigment { rgb <0.85, 0.15, 0.1> } finish { Matte } }
box { <2.5, 0, -1>, <2.7, 3, 2.2> pigment { rgb <0.15, 0.7, 0.2> } finish { Matte } }
sphere { <-1.1, 0.8, 0.6>, 0.8 pigment { rgb 0.9 } finish { Matte } }
sphere { <1.2, 0.6, -0.1>, 0.6 pigment { rgb <1.0, 0.8, 0.3> } finish { Matte } }
