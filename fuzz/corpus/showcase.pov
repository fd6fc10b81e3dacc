// snell showcase: glass and mirror spheres on a plain floor, three lights.
// Uses only the foundation's features: spheres, a plane, a box, point lights, Phong and specular
// highlights, mirror reflection with Fresnel, refraction through glass, and filtered shadows.
// Render: snell render scenes/showcase.pov -o showcase.png -w 800 -h 600 --aa 0.3
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }

camera {
  location <0, 2.4, -7.5>
  look_at  <0, 0.9, 0>
  right    x*image_width/image_height
  angle    42
}

background { color rgb <0.52, 0.68, 0.95> }

light_source { <-6, 9, -6> color rgb <1.0, 0.95, 0.88> }
light_source { < 7, 6, -4> color rgb <0.30, 0.36, 0.48> }
light_source { < 0, 5,  8> color rgb 0.25 shadowless }

// The floor: a warm matte plane with a faint mirror term.
plane {
  y, 0
  pigment { color rgb <0.78, 0.74, 0.68> }
  finish { ambient 0.05 diffuse 0.75 reflection 0.08 }
}

// A back wall far behind, so reflections have something to show.
box {
  <-30, 0, 14>, <30, 20, 15>
  pigment { color rgb <0.85, 0.82, 0.78> }
  finish { ambient 0.1 diffuse 0.7 }
}

#declare Glass_Texture = texture {
  pigment { color rgbf <0.96, 0.98, 1.0, 0.92> }
  finish { ambient 0 diffuse 0.05 specular 0.9 roughness 0.002 reflection { 0.03, 1 fresnel on } }
}
#declare Glass_Interior = interior { ior 1.5 }

// Glass sphere in front.
sphere {
  <0, 1, 0>, 1
  texture { Glass_Texture }
  interior { Glass_Interior }
}

// A mirror sphere to the left.
sphere {
  <-2.3, 0.9, 1.3>, 0.9
  pigment { color rgb <0.9, 0.9, 0.92> }
  finish { ambient 0 diffuse 0.05 reflection { 0.8 metallic } phong 0.6 phong_size 120 }
}

// A gold sphere to the right, a metallic highlight.
sphere {
  <2.2, 0.8, 1.0>, 0.8
  pigment { color rgb <0.95, 0.68, 0.25> }
  finish { ambient 0.05 diffuse 0.35 reflection { 0.45 metallic } specular 0.8 roughness 0.01 metallic }
}

// Small coloured spheres behind, seen through the glass (refraction) and in the mirror.
#declare I = 0;
#while (I < 7)
  sphere {
    <-3 + I, 0.35, 3.5>, 0.35
    pigment { color rgb <0.5 + 0.5 * sin(I), 0.5 + 0.5 * sin(I + 2.1), 0.5 + 0.5 * sin(I + 4.2)> }
    finish { ambient 0.05 diffuse 0.8 phong 0.5 phong_size 60 }
  }
  #declare I = I + 1;
#end

// A tinted glass slab casting a coloured (filtered) shadow.
box {
  <-0.6, 0, -0.6>, <0.6, 0.08, 0.6>
  rotate y*25
  translate <1.2, 0, -1.8>
  pigment { color rgbf <1.0, 0.45, 0.2, 0.8> }
  finish { ambient 0 diffuse 0.1 specular 0.6 roughness 0.005 reflection 0.05 }
  interior { ior 1.45 }
}
