// snell frosted glass (a snell extension, docs/language.md "Glossy reflection and frosted glass"):
// three glass panes in front of coloured stripes, refraction blur 0 (clear), 0.04 and 0.15, and a frosted
// sphere. `transmission { blur B samples N }` in the finish roughens the surface for the light going
// through it (GGX microfacets, Walter et al. 2007); the pigment's filter and the interior's ior still set
// how much light passes and how it bends, as in POV-Ray.
// Render: snell render scenes/frosted_glass.pov -o frosted_glass.png -w 480 -h 360
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }

camera { location <0, 1.6, -6.5> look_at <0, 1.2, 0> angle 52 }
light_source { <-5, 8, -6> color rgb 1.0 }
background { rgb 0.05 }

// The back wall: vertical stripes and a grid of dots to see the blur through the glass.
plane { z, 1.2
  pigment { gradient x color_map { [0.0 rgb <0.95, 0.2, 0.1>] [0.33 rgb <0.95, 0.2, 0.1>]
                                  [0.33 rgb <0.95, 0.9, 0.8>] [0.66 rgb <0.95, 0.9, 0.8>]
                                  [0.66 rgb <0.1, 0.3, 0.9>] [1.0 rgb <0.1, 0.3, 0.9>] } scale 0.6 }
  finish { ambient 0.3 diffuse 0.7 }
}
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } finish { ambient 0.2 diffuse 0.7 } }

#macro Glass(Blur)
  material {
    texture { pigment { rgbf <0.97, 0.99, 1.0, 0.95> }
      finish { ambient 0 diffuse 0 specular 0.4 roughness 0.01 reflection { 0.02, 0.6 fresnel } conserve_energy
               transmission { blur Blur samples 16 } } }
    interior { ior 1.5 }
  }
#end
#macro Pane(X, Blur)
  box { <-0.75, 0.2, -0.08>, <0.75, 2.6, 0.08> Glass(Blur) translate <X, 0, 0> }
#end
Pane(-2.0, 0)
Pane( 0.0, 0.04)
Pane( 2.0, 0.15)
sphere { <0, 0.45, -1.5>, 0.45 Glass(0.1) }
