// Filter and transmit colours: tinted transparent objects and the coloured shadows they cast.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -5> look_at <0, 0.5, 0> right x*4/3 }
light_source { <2, 8, -3> color rgb 1 }
plane { y, 0 pigment { color rgb 0.9 } }
sphere { <-1.3, 1, 0>, 0.8 pigment { color rgbf <1, 0.2, 0.2, 0.8> } }
sphere { <1.3, 1, 0>, 0.8 pigment { color rgbt <0.2, 0.3, 1, 0.6> } }
box { <-0.4, 0, 1>, <0.4, 1.5, 1.4> pigment { color rgbft <0.2, 1, 0.2, 0.5, 0.3> } }
