#declare Fin = finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 0.01 phong 1 reflection { 0.1, 0.9 fresnel } }
#declare Tex = texture { pigment { gradient y color_map { [0 rgb 0] [0.5 rgb <1,0,0>] [1 rgb 1] } turbulence 0.5 }
  finish { Fin } }
#declare Mat = material { texture { Tex } interior { ior 1.5 } }
#default { finish { ambient 0.2 } }
sphere { 0, 1 material { Mat } }
box { -1, 1 texture { pigment { granite scale 0.3 } } texture { pigment { rgbf <1,1,1,0.8> } } translate 3*x }
plane { y, -1 pigment { brick rgb 1, rgb 0.5 brick_size <1, 0.5, 1> mortar 0.1 } }
sphere { 0, 0.5 pigment { spherical pigment_map { [0 rgb 1] [1 bozo color_map { [0 rgb 0] [1 rgb 1] }] } } }
