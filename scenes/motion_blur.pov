// snell motion blur (an extension: POV-Ray 3.7 has none). The camera's shutter is open from time 0 to 1;
// each pixel takes 32 rays spread over the shutter (and over the pixel). A striped wheel spins about its
// axle, a ball flies along a keyed arc, and a cube slides while it turns; the floor and the post stand still.
// Render: snell render scenes/motion_blur.pov -o motion_blur.png -w 480 -h 360
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2.2, -7>
  look_at  <0, 1, 0>
  right    x*image_width/image_height
  angle    45
  shutter { open 0 close 1 samples 32 }
}

background { color rgb <0.55, 0.7, 0.95> }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 5, -3> color rgb 0.35 shadowless }

plane { y, 0 pigment { checker color rgb 0.85, color rgb 0.55 scale 0.75 } finish { diffuse 0.8 } }

// The wheel: a striped disc turning 30 degrees about its axle (z) while the shutter is open, so the rim
// smears more than the hub. Between two keys a rotation takes the shorter way round: to spin further,
// add a key every 90 degrees or so.
cylinder {
  <0, 0, -0.15>, <0, 0, 0.15>, 1
  pigment { radial frequency 8 color_map { [0.5 color rgb <0.9, 0.15, 0.1>] [0.5 color rgb 0.95] } rotate x*90 }
  finish { phong 0.5 }
  motion { key 0  key 0.5 rotate z*15  key 1 rotate z*30 }
  translate <-1.6, 1.2, 0.5>
}

// The ball: keyed positions along an arc, interpolated linearly between keys.
sphere {
  0, 0.45
  pigment { color rgb <0.2, 0.45, 0.95> }
  finish { phong 0.8 reflection 0.1 }
  motion { key 0 translate <-0.2, 0.5, -1.5>  key 0.5 translate <0.1, 0.9, -1.5>  key 1 translate <0.4, 0.7, -1.5> }
}

// The cube: a single-transform motion, from where it stands at time 0 to this transform at time 1.
box {
  -0.5, 0.5
  pigment { color rgb <0.95, 0.75, 0.2> }
  motion { rotate y*80 translate <1.2, 0, 0> }
  translate <1.3, 0.5, 1.2>
}

// Still: a post, sharp in every frame.
cylinder { <-3, 0, 2>, <-3, 2.5, 2>, 0.15 pigment { color rgb 0.3 } }
