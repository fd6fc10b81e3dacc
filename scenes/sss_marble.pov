// A marble bust-like figure (a blob head on a CSG plinth) with Jensen et al. 2001's measured marble:
// subsurface scattering softens the shading and lets light bleed round the shadowed side.
// snell render scenes/sss_marble.pov -o docs/images/sss_marble.png -w 320 -h 240
#version 3.7;
global_settings { assumed_gamma 1.0 mm_per_unit 25 subsurface { samples 48, 1 } }
camera { location <0, 2.2, -5.2> look_at <0, 1.35, 0> angle 40 }
light_source { <-6, 7, -5> rgb 1.1 }
light_source { <5, 3, -2> rgb 0.35 shadowless }
background { rgb <0.05, 0.06, 0.09> }
#declare Marble = texture {
  pigment { rgb 1 }
  finish { ambient 0.02 specular 0.25 roughness 0.02 subsurface { material "marble" } }
}
blob {
  threshold 0.6
  sphere { <0, 2.05, 0>, 0.75, 1 }       // head
  sphere { <0, 1.75, -0.28>, 0.35, 0.5 } // chin and jaw
  sphere { <0, 2.05, -0.55>, 0.16, 0.7 } // nose
  cylinder { <0, 1.1, 0>, <0, 1.6, 0>, 0.38, 1 } // neck
  sphere { <-0.55, 0.95, 0>, 0.55, 1 }   // shoulders
  sphere { <0.55, 0.95, 0>, 0.55, 1 }
  texture { Marble }
  interior { ior 1.5 }
}
intersection {
  box { <-1.1, 0, -0.7>, <1.1, 0.7, 0.7> }
  cylinder { <0, -1, 0>, <0, 2, 0>, 1.25 }
  texture { Marble }
  interior { ior 1.5 }
}
plane { y, 0 pigment { rgb 0.25 } finish { ambient 0 diffuse 0.8 } }
