// A glass sphere (ior 1.5) over a checkered floor: reflection, refraction, total internal reflection and
// Fresnel for `snell explain` (docs/explain.md).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 6 }
camera { location <0, 0.6, -4> look_at <0, 0, 0> }
light_source { <3, 5, -4> color rgb 1 }
#declare Glass = sphere {
  <0, 0, 0>, 1
  pigment { rgbf <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 reflection { 0 1 fresnel on } phong 0.6 }
  interior { ior 1.5 }
}
object { Glass }
#declare Floor = plane { y, -1 pigment { checker rgb <0.9, 0.85, 0.7> rgb <0.2, 0.3, 0.5> } }
object { Floor }
background { rgb <0.3, 0.5, 0.8> }
