// snell flock: boids (Reynolds 1987) with separation, alignment and cohesion, a limited field of view,
// flying around two pillars they avoid by looking ahead (docs/procedural.md). Each boid is a small
// dart pointing along its velocity (+z of the model).
// Animate with clock (0..1 = 4..12 s of flight): snell +Iscenes/flock.pov +Oflock.png +W320 +H240 +KI0.5
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Seconds = 4 + 8 * clock;

camera { location <0, 8, -15> look_at <0, 3.8, 0> right x*image_width/image_height angle 55 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.95, 0.8, 0.6>] [0.4 rgb <0.45, 0.6, 0.9>] } } }
light_source { <-20, 40, -20> rgb 1 }

#declare Pillar = cylinder { <0, 0, 0>, <0, 7, 0>, 0.8 }
#declare Pillars = union { object { Pillar translate <-3, 0, 1> } object { Pillar translate <3.5, 0, -1> } }

#declare Dart = union {
  cone { <0, 0, -0.25>, 0.09, <0, 0, 0.25>, 0 }
  triangle { <-0.28, 0, -0.2>, <0.28, 0, -0.2>, <0, 0, 0.15> }
  pigment { rgb <0.15, 0.12, 0.1> }
  scale 1.3
}

boids {
  count 60 seed 7 time Seconds step 1/30
  start <-6, 2, -6>, <6, 6, 6> start_speed 2
  separation 0.7, 2.5 alignment 1 cohesion 0.8
  neighbour_radius 2.5 field_of_view 270
  max_speed 3.5 min_speed 1.5 max_force 8
  avoid { object { Pillars } } distance 3 weight 8
  bounds <-8, 1.5, -6>, <8, 6.5, 6> weight 2
  boid { object { Dart } }
}

object { Pillars pigment { rgb <0.8, 0.75, 0.65> } }
plane { y, 0 pigment { checker rgb <0.55, 0.6, 0.45> rgb <0.45, 0.5, 0.38> scale 2 } }
