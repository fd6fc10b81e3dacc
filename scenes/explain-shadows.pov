// Two lights, a ball and a glass pane: shadow rays reach a light, are blocked by the ball, or pass through
// the tinted glass (docs/explain.md).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 0, 0> }
light_source { <-4, 6, -2> color rgb 0.8 }
light_source { <4, 3, -3> color rgb 0.6 }
#declare Ball = sphere { <-0.8, 0, 0>, 0.7 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
object { Ball }
#declare Pane = box { <0.3, -1, -0.05>, <1.8, 1, 0.05> pigment { rgbf <0.3, 0.9, 0.4, 0.8> } }
object { Pane }
#declare Floor = plane { y, -0.7 pigment { rgb 0.8 } }
object { Floor }
background { rgb <0.2, 0.25, 0.35> }
