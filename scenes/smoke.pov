// snell smoke: grey transparent spheres from a chimney, carried by wind through air drag, rising,
// swirling in turbulence and a vortex, growing and fading with age (docs/procedural.md).
// Animate with clock: snell +Iscenes/smoke.pov +Osmoke.png +W320 +H240 +KI0.5
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Seconds = 6 + 2 * clock;

camera { location <3, 2.5, -9> look_at <2.5, 2.4, 0> right x*image_width/image_height angle 50 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.75, 0.8, 0.9>] [1 rgb <0.35, 0.5, 0.8>] } } }
light_source { <-10, 20, -15> rgb 1 }

particle_system {
  emitter { disc { <0, 2.1, 0>, y, 0.15 } rate 60 lifetime 5 +/- 1 speed 1.2 +/- 0.3 spread 10 size 0.22 +/- 0.05 }
  gravity <0, 0.25, 0> wind <1.2, 0, 0.2> drag 0.6 turbulence 0.8 size 1.5
  vortex { <2, 0, 0>, y, 0.6 core 1 }
  time Seconds step 1/30 seed 11
  color_map { [0 rgbt <0.35, 0.33, 0.32, 0.3>] [0.5 rgbt <0.6, 0.6, 0.6, 0.7>] [1 rgbt <0.8, 0.8, 0.8, 1>] }
  size_map { [0 1] [1 4] }
  render { spheres }
  finish { ambient 0.3 diffuse 0.6 }
  no_shadow
}

// The chimney and the ground.
cylinder { <0, 0, 0>, <0, 2, 0>, 0.25 pigment { rgb <0.5, 0.25, 0.2> } }
plane { y, 0 pigment { rgb <0.35, 0.45, 0.3> } }
