// Caustics under glass by photon mapping (POV-Ray 3.7 photons syntax, docs/language.md "Photons"):
// a clear glass sphere focuses the light to a bright spot inside its shadow, an amber glass egg throws a
// tinted one, and a mirror ring reflects a bright arc onto the floor.
// Render: snell render scenes/caustics.pov -o caustics.png -w 480 -h 360 --stats
#version 3.7;
global_settings {
  assumed_gamma 1.0
  max_trace_level 10
  photons { spacing 0.01 autostop 0 jitter 0.4 }
}

camera { location <0, 4.2, -6.2> look_at <0, 0.4, 0.3> angle 44 }
light_source { <-3, 9, 5> color rgb 1.1 photons { refraction on reflection on } }
light_source { <6, 7, -7> color rgb 0.25 shadowless }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.6, 0.7, 0.9>] [1 rgb <0.2, 0.3, 0.6>] } } }

plane { y, 0
  pigment { checker rgb 0.85 rgb 0.7 scale 1.5 }
  finish { ambient 0.05 diffuse 0.8 }
}

#declare Glass = material {
  texture { pigment { rgbf <0.98, 0.99, 1, 1> }
            finish { ambient 0 diffuse 0 specular 0.6 roughness 0.005
                     reflection { 0, 1 fresnel on } conserve_energy } }
  interior { ior 1.5 }
}

sphere { <-1.1, 1, 0>, 1 material { Glass } photons { target refraction on reflection on collect off } }

sphere { 0, 1 scale <0.55, 0.8, 0.55> translate <1.2, 0.8, -0.4>
  material {
    texture { pigment { rgbf <1, 0.6, 0.15, 0.95> }
              finish { ambient 0 diffuse 0 specular 0.5 roughness 0.01 reflection { 0, 1 fresnel on } conserve_energy } }
    interior { ior 1.45 }
  }
  photons { target refraction on reflection on collect off }
}

// A polished ring: the light it reflects gathers into a bright arc (a cardioid-like caustic) on the floor.
difference {
  cylinder { <0, 0, 0>, <0, 0.5, 0>, 1.2 }
  cylinder { <0, -0.1, 0>, <0, 0.6, 0>, 1.12 }
  translate <1.3, 0, 2.1>
  pigment { rgb <0.9, 0.85, 0.7> }
  finish { ambient 0 diffuse 0.1 specular 0.6 roughness 0.01 reflection { 0.85 metallic } }
  photons { target reflection on collect off }
}
