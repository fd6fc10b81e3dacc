// The Koch snowflake in the seed notation of the reference: axiom FRRFRRF, rule F=FLFRRFLF with L a
// 60-degree left turn and R a right turn (the same as F=F+F--F+F, Fractint "Angle 6"), 4 iterations:
// 1792 modules, 768 segments. The curve lies in the xy plane.
// snell render scenes/koch_snowflake.pov -w 320 -h 240
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at 0 angle 40 }
light_source { <-10, 10, -20> color rgb 1 }
background { color rgb <0.05, 0.08, 0.2> }

lsystem {
  axiom "FRRFRRF"
  rule "F" "FLFRRFLF"
  interpret "L" "+"
  interpret "R" "-"
  angle 60
  iterations 4
  width 0.8
  pigment { color rgb <0.7, 0.85, 1.0> }
  finish { specular 0.6 }
  // The curve spans 3^4 = 81 steps; centre it and fit it to the view.
  translate <-40.5, 23.4, 0>
  scale 0.052
}
