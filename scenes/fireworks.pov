// snell fireworks: particle_system bursts drawn as fading streaks (docs/procedural.md).
// Three shells burst at different times; each spark falls under gravity with air drag, its colour cools
// and fades by a colour_map over its age, and its streak is the path of its last 0.25 s.
// Animate with clock (0..1 = 0..4 s): snell +Iscenes/fireworks.pov +Ofw.png +W320 +H240 +KI0.5
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Seconds = 4 * clock;

camera { location <0, 6, -22> look_at <0, 7, 0> right x*image_width/image_height angle 50 }
background { rgb <0.0005, 0.0008, 0.004> }

#macro Shell(Where, Burst, Color1, Color2, Seed)
  particle_system {
    emitter { point Where burst 400 at Burst lifetime 1.6 +/- 0.4 speed 6 +/- 1 spread 180 size 0.045 +/- 0.01 }
    gravity <0, -9.8, 0> drag 0.8 time Seconds step 1/60 seed Seed
    color_map { [0 rgb Color1 * 2.5] [0.4 rgb Color2 * 2] [1 rgbt <Color2.x, Color2.y, Color2.z, 1>] }
    size_map { [0 1] [1 0.4] }
    render { streaks length 0.25 }
    finish { ambient 0 diffuse 0 emission 1 }
    no_shadow
  }
#end

Shell(<-5, 10, 4>, 0.2, <1, 0.9, 0.6>, <1, 0.25, 0.1>, 1)
Shell(< 4, 12, 6>, 0.9, <0.7, 0.9, 1>, <0.2, 0.4, 1>, 2)
Shell(< 0, 8, 0>, 1.6, <1, 1, 0.7>, <0.3, 1, 0.3>, 3)

// The city below: dark blocks catching a little light.
light_source { <0, 30, -20> rgb 0.05 }
#declare Row = 0;
#while (Row < 12)
  box { <-14 + Row * 2.4, 0, 8>, <-12.4 + Row * 2.4, 1 + mod(Row * 7, 5), 10> pigment { rgb 0.05 } }
  #declare Row = Row + 1;
#end
plane { y, 0 pigment { rgb 0.02 } finish { reflection 0.3 } }
