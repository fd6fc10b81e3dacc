// snell glossy reflection (a snell extension, docs/language.md "Glossy reflection and frosted glass"):
// four metal spheres whose reflection blur grows from a mirror (0) to rough brushed metal (0.3), on a
// glossy checkered floor. POV-Ray's `roughness` stays the size of the specular highlight; the GGX width of
// the reflection is `blur`, with `samples` rays where a camera ray hits (1 below).
// Render: snell render scenes/brushed_metal.pov -o brushed_metal.png -w 480 -h 360
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.2, -7.5> look_at <0, 0.8, 0> angle 50 }
light_source { <-6, 10, -8> color rgb 1.0 }
light_source { <8, 6, -3> color rgb 0.4 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.85, 0.8, 0.75>] [1 rgb <0.25, 0.4, 0.75>] } } }

plane { y, 0
  pigment { checker rgb <0.75, 0.72, 0.68> rgb <0.12, 0.12, 0.14> scale 1.2 }
  finish { diffuse 0.7 reflection { 0.25 blur 0.12 samples 8 } }
}

// Coloured posts behind the spheres, so that the blur shows in their reflections.
#declare Post = cylinder { <0, 0, 0>, <0, 3, 0>, 0.3 }
object { Post translate <-3.5, 0, 3> pigment { rgb <0.9, 0.2, 0.1> } }
object { Post translate <-1.2, 0, 3.5> pigment { rgb <0.1, 0.6, 0.2> } }
object { Post translate < 1.2, 0, 3.5> pigment { rgb <0.1, 0.3, 0.9> } }
object { Post translate < 3.5, 0, 3> pigment { rgb <0.95, 0.8, 0.1> } }

#macro Metal(X, Blur)
  sphere { <X, 0.8, 0>, 0.8
    pigment { rgb <0.95, 0.9, 0.85> }
    finish { ambient 0 diffuse 0.05 specular 0.6 roughness 0.02 metallic
             reflection { 0.85 metallic blur Blur samples 12 } }
  }
#end
Metal(-2.7, 0)
Metal(-0.9, 0.05)
Metal( 0.9, 0.15)
Metal( 2.7, 0.3)
