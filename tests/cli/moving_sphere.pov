// A small animation for the CLI tests (tests/cli/animation_test.cpp, mpi_test.cpp): a sphere travels along
// x with clock and changes colour with frame_number, so every frame differs.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -5> look_at <0, 0, 0> }
light_source { <3, 5, -4>, 1 }
plane { y, -1 pigment { checker rgb 1 rgb 0.3 } finish { reflection 0.2 } }
sphere { <-1.5 + 3 * clock, 0, 0>, 0.7
  pigment { rgb <0.2 + 0.1 * frame_number, 0.5, 0.9> } finish { phong 0.8 reflection 0.3 } }
