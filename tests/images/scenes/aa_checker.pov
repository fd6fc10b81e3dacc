// Anti-aliasing as POV-Ray does it (tracetask.cpp, method 1, jittered by default): a fine checker floor
// and a flat red ball, no lighting, so every pixel's value comes from where its samples fall and which
// pixels POV-Ray supersamples. snell renders it as POV-Ray 3.7 does (SSIM 1.0 at 160x120 +A0.3).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,1,-5> look_at <0,0,10> angle 60 }
plane { y, 0 pigment { checker rgb 1 rgb 0 scale 0.37 } finish { ambient 1 diffuse 0 } }
sphere { <0,1,3>, 1 pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } }
