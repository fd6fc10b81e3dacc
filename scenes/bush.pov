// Left: Mariano's bush (Fractint lsystem library; ABoP Fig. 1.24c): F=FF-[-F+F+F]+[+F-F-F], 22.5 degrees,
// 4 iterations, drawn as tapered round branches; it grows in the xy plane from the origin up +y.
// Right: a stochastic 3D bush (after ABoP Fig. 1.27, with pitch and roll added): each F picks one of three
// rules with equal probability from the seed, so another seed grows another bush of the same kind.
// snell render scenes/bush.pov -w 320 -h 240
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 8, -30> look_at <0, 8, 0> angle 45 }
light_source { <-20, 40, -30> color rgb 1 }
light_source { <20, 10, -20> color rgb 0.3 }
background { color rgb <0.75, 0.85, 1.0> }
plane { y, 0 pigment { color rgb <0.45, 0.35, 0.25> } }

lsystem {
  axiom "++++F"
  rule "F" "FF-[-F+F+F]+[+F-F-F]"
  angle_divisions 16        // Fractint's "Angle 16": 360/16 = 22.5 degrees
  iterations 4
  width 1.2 taper 0.65
  pigment { color rgb <0.25, 0.45, 0.12> }
  scale 0.3 translate -4*x
}

lsystem {
  axiom "+(90)F"
  rule "F" "F[+F]F[-F]F" probability 1
  rule "F" "F[+F]F" probability 1
  rule "F" "F[-F]\\F" probability 1
  angle 28
  iterations 5
  seed 3
  width 0.12 taper 0.75
  step 0.1
  pigment { color rgb <0.45, 0.3, 0.15> }
  rotate 20*y translate 4.5*x
}
