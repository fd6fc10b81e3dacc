// A diamond-square landscape (Martz, "Generating Random Fractal Terrain"): 257 x 257 heights, roughness
// H = 0.9, seed 7; water at a fixed level, grass on gentle slopes, rock on steep ones, snow high up where
// the ground is flat enough to hold it (slope pattern inside a gradient texture_map).
// snell render scenes/terrain.pov -w 320 -h 240
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.15, 0.42, 0.05> look_at <0.55, 0.12, 0.6> angle 65 }
light_source { <-3, 4, -1> color rgb 1.2 }
sky_sphere { pigment { gradient y color_map { [0 color rgb <0.85, 0.9, 1>] [0.4 color rgb <0.4, 0.6, 0.95>] } } }

#declare Grass = texture { pigment { color rgb <0.25, 0.45, 0.12> } }
#declare Rock = texture { pigment { color rgb <0.4, 0.36, 0.32> } }
#declare Snow = texture { pigment { color rgb 0.95 } finish { diffuse 0.9 } }
// slope { y } is 1 where the ground is flat, 0.5 where it is vertical.
#declare Lowland = texture { slope { y } texture_map { [0 Rock] [0.82 Rock] [0.86 Grass] [1 Grass] } }
#declare Highland = texture { slope { y } texture_map { [0 Rock] [0.78 Rock] [0.82 Snow] [1 Snow] } }

height_field {
  diamond_square { size 257 roughness 0.9 seed 7 }
  smooth
  texture { gradient y texture_map { [0 Lowland] [0.68 Lowland] [0.72 Highland] [1 Highland] } }
  scale <1, 0.3, 1>
}
plane { y, 0.1 pigment { color rgbf <0.1, 0.3, 0.5, 0.3> } finish { reflection 0.25 specular 0.6 } }
