// Mariano's bush (Fractint lsystem library; ABoP Fig. 1.24c): F=FF-[-F+F+F]+[+F-F-F], 22.5 degrees, 4
// iterations, drawn as tapered round branches. The L-system grows in the xy plane from the origin up +y.
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
  scale 0.3 translate -2*x
}
