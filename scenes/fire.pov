// snell fire: a particle_system rendered as an emissive medium whose density is the particle cloud
// (docs/procedural.md). Particles rise from a disc with buoyancy (negative gravity), turbulence and a
// little drag; their colour goes from yellow-white to deep red and out, their size grows then shrinks.
// Animate with clock: snell +Iscenes/fire.pov +Ofire.png +W320 +H240 +KI0.5
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Seconds = 3 + 2 * clock;

camera { location <0, 1.4, -5> look_at <0, 1.1, 0> right x*image_width/image_height angle 45 }
background { rgb <0.01, 0.01, 0.015> }

particle_system {
  emitter { disc { <0, 0.05, 0>, y, 0.45 } rate 300 lifetime 1.1 +/- 0.3 speed 0.6 +/- 0.2 spread 15
            size 0.32 +/- 0.06 }
  gravity <0, 2.2, 0> drag 1.2 turbulence 3 size 0.35
  time Seconds step 1/30 seed 5
  color_map { [0 rgb <1, 0.85, 0.45>] [0.35 rgb <1, 0.45, 0.08>] [0.75 rgb <0.5, 0.06, 0.01>] [1 rgbt <0, 0, 0, 1>] }
  size_map { [0 0.7] [0.3 1] [1 0.5] }
  render { media emission 1.6 samples 24 }
}

// Logs under the flames, lit by a warm light where the fire is.
light_source { <0, 0.8, 0> rgb <1, 0.5, 0.15> * 1.5 fade_distance 1 fade_power 2 }
light_source { <-4, 5, -6> rgb 0.06 }
#declare Log = cylinder { <-0.7, 0, 0>, <0.7, 0, 0>, 0.09 pigment { rgb <0.18, 0.1, 0.05> } }
object { Log rotate y * 30 translate <0, 0.09, 0> }
object { Log rotate -y * 30 translate <0, 0.09, 0> }
object { Log rotate y * 90 translate <0, 0.2, 0> }
plane { y, 0 pigment { rgb <0.25, 0.22, 0.2> } }
