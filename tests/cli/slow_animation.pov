// tests/cli/moving_sphere.pov seen through focal blur: slow enough at one thread that a signal sent while
// frame 2 renders lands mid-frame (tests/cli/animation_test.cpp).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -5> look_at <0, 0, 0> aperture 0.6 blur_samples 24 focal_point <0, 0, 0> }
light_source { <3, 5, -4>, 1 }
plane { y, -1 pigment { checker rgb 1 rgb 0.3 } finish { reflection 0.2 } }
#for (I, 0, 2)
  sphere { <-1.5 + 3 * clock, 0, I - 1>, 0.45 pigment { rgb <0.2 + 0.1 * frame_number, 0.5, 0.3 * I> }
    finish { phong 0.8 reflection 0.3 } }
#end
