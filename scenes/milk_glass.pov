// A glass of milk: a thin clear glass (a lathe-free CSG tumbler) holding whole milk, whose measured
// scattering (Jensen et al. 2001) gives its soft, bright body; next to it a skim-milk sphere, bluer and
// more translucent.
// snell render scenes/milk_glass.pov -o docs/images/milk_glass.png -w 320 -h 240
#version 3.7;
global_settings { assumed_gamma 1.0 mm_per_unit 30 subsurface { samples 48, 1 } max_trace_level 8 }
camera { location <0, 2.4, -5> look_at <0.2, 1.0, 0> angle 42 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.3 shadowless }
background { rgb <0.55, 0.6, 0.7> }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.45 scale 0.5 } finish { ambient 0.05 diffuse 0.8 } }
// The glass: a tube with a thick bottom.
difference {
  cylinder { <0, 0, 0>, <0, 2.1, 0>, 0.75 }
  cylinder { <0, 0.12, 0>, <0, 2.2, 0>, 0.69 }
  pigment { rgbf <0.97, 0.99, 1, 0.95> }
  finish { ambient 0 diffuse 0 specular 0.8 roughness 0.002 reflection { 0.05, 1 fresnel } conserve_energy }
  interior { ior 1.5 }
}
// The milk, just inside the glass.
cylinder {
  <0, 0.121, 0>, <0, 1.6, 0>, 0.689
  pigment { rgb 1 }
  finish { ambient 0.02 specular 0.3 roughness 0.01 subsurface { material "wholemilk" } }
  interior { ior 1.3 }
}
sphere {
  <1.55, 0.5, 0.3>, 0.5
  pigment { rgb 1 }
  finish { ambient 0.02 specular 0.3 roughness 0.01 subsurface { jensen "skimmilk" } }
  interior { ior 1.3 }
}
