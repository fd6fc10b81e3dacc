// snell depth of field: POV-Ray's focal blur (aperture, blur_samples, focal_point). A row of spheres
// recedes from the camera; only the one at the focal point is sharp.
// Render: snell render scenes/depth_of_field.pov -o depth_of_field.png -w 480 -h 360
//   (or with a fixed sample count: --spp 64 --sampler sobol --filter gaussian)
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.6, -6>
  look_at  <0, 0.6, 2>
  right    x*image_width/image_height
  angle    40
  aperture 0.4
  blur_samples 16, 96
  focal_point <-0.3, 0.5, 1>
  confidence 0.95
  variance 1/2000
}

background { color rgb <0.6, 0.72, 0.9> }
light_source { <-4, 7, -5> color rgb 1 }

plane { y, 0 pigment { checker color rgb 0.9, color rgb 0.35 } finish { diffuse 0.8 } }

#declare I = 0;
#while (I < 6)
  sphere {
    <-1.5 + I * 0.6, 0.5, -2 + I * 1.5>, 0.5
    pigment { color rgb <0.9 - I * 0.12, 0.3 + I * 0.1, 0.2 + I * 0.12> }
    finish { phong 0.7 reflection 0.12 }
  }
  #declare I = I + 1;
#end
