// A 3D tree after The Algorithmic Beauty of Plants, Fig. 1.25 (bracketed, 22.5 degrees, 7 iterations):
// each apex A opens three branches rolled 112.5 and 157.5 degrees apart, internodes F grow by S/////F, and
// every S leaves a leaf L (drawn by `~`). `'` steps through the palette from bark to young twigs.
// snell render scenes/tree.pov -w 320 -h 240
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <-6, 10, -40> look_at <0, 9.5, 0> angle 45 }
light_source { <-30, 50, -40> color rgb 1.1 }
light_source { <30, 20, -30> color rgb 0.25 shadowless }
sky_sphere { pigment { gradient y color_map { [0 color rgb <0.85, 0.9, 1>] [1 color rgb <0.35, 0.55, 0.95>] } } }
plane { y, 0 pigment { color rgb <0.35, 0.5, 0.2> } }

#declare Leaf = sphere { 0, 1 scale <0.35, 0.7, 0.08> translate 0.7*y
                         pigment { color rgb <0.2, 0.55, 0.1> } }

lsystem {
  axiom "+(90)!(0.4)F(2)A"          // turn the start heading from +x to +y, a thick first trunk piece
  rule "A" "[&FL!A]/////'[&FL!A]///////'[&FL!A]"
  rule "F" "S/////F"
  rule "S" "FL"
  interpret "L" "~"
  angle 22.5
  iterations 7
  width 0.25 taper 0.707
  step 0.5
  palette {
    texture { pigment { color rgb <0.3, 0.2, 0.12> } }
    texture { pigment { color rgb <0.36, 0.25, 0.14> } }
    texture { pigment { color rgb <0.45, 0.33, 0.17> } }
    texture { pigment { color rgb <0.45, 0.45, 0.2> } }
  }
  leaf { object { Leaf } scale 0.5 }
}
