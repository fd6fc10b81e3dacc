// snell texture gallery: every pattern on a grid of tiles, pigments in the top rows and normals in the
// bottom row. Labels come once `text` lands; until then the order is (left to right, top to bottom):
//   row 1: gradient onion spherical cylindrical planar boxed radial leopard
//   row 2: bozo granite marble wood agate crackle cells wrinkles
//   row 3: bumps dents ripples waves quilted spiral1 spiral2 mandel
//   row 4: julia checker hexagon brick crackle-solid crackle-metric-1 crackle-form-<1,0,0> texture_map
//   row 5 (normals on white): bumps dents wrinkles ripples waves quilted crackle slope_map
// Render: snell render scenes/textures.pov -o textures.png -w 800 -h 500 --aa 0.3
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  orthographic
  location <4, -2.5, -10>
  look_at  <4, -2.5, 0>
  right    x*8.6
  up       y*5.4
}

light_source { <-10, 15, -20> color rgb 1.1 }
light_source { <20, -5, -10> color rgb 0.35 shadowless }
background { color rgb 0.12 }

#declare Grey = color_map { [0 rgb <0.1, 0.1, 0.15>] [1 rgb <0.95, 0.9, 0.8>] }
#macro Tile(Column, Row, Pig)
  box { <0.06, -0.94, 0>, <0.94, -0.06, 0.2>
    pigment { Pig }
    finish { ambient 0.15 diffuse 0.8 }
    translate <Column, -Row, 0> }
#end
#macro BumpTile(Column, Row, Nor)
  box { <0.06, -0.94, 0>, <0.94, -0.06, 0.2>
    pigment { rgb <0.9, 0.88, 0.85> }
    normal { Nor }
    finish { ambient 0.1 diffuse 0.8 specular 0.4 roughness 0.02 }
    translate <Column, -Row, 0> }
#end

// Row 1: geometric patterns.
Tile(0, 0, pigment { gradient x color_map { Grey } scale 0.5 })
Tile(1, 0, pigment { onion color_map { Grey } scale 0.3 translate <0.5, -0.5, 0> })
Tile(2, 0, pigment { spherical color_map { Grey } scale 0.45 translate <0.5, -0.5, 0> })
Tile(3, 0, pigment { cylindrical color_map { Grey } rotate x*90 scale 0.45 translate <0.5, -0.5, 0> })
Tile(4, 0, pigment { planar color_map { Grey } scale 0.45 translate <0, -0.5, 0> })
Tile(5, 0, pigment { boxed color_map { Grey } scale 0.45 translate <0.5, -0.5, 0> })
Tile(6, 0, pigment { radial frequency 6 color_map { Grey } rotate x*90 translate <0.5, -0.5, 0> })
Tile(7, 0, pigment { leopard color_map { Grey } scale 0.06 })
// Row 2: noise and cellular patterns.
Tile(0, 1, pigment { bozo color_map { Grey } scale 0.15 })
Tile(1, 1, pigment { granite color_map { Grey } scale 0.8 })
Tile(2, 1, pigment { marble turbulence 0.8 color_map { Grey } scale 0.4 })
Tile(3, 1, pigment { wood turbulence 0.1 rotate x*90 scale 0.08 translate <0.5, -0.5, 0> })
Tile(4, 1, pigment { agate scale 0.5 })
Tile(5, 1, pigment { crackle color_map { Grey } scale 0.2 })
Tile(6, 1, pigment { cells color_map { Grey } scale 0.15 })
Tile(7, 1, pigment { wrinkles color_map { Grey } scale 0.3 })
// Row 3.
Tile(0, 2, pigment { bumps color_map { Grey } scale 0.15 })
Tile(1, 2, pigment { dents color_map { Grey } scale 0.15 })
Tile(2, 2, pigment { ripples color_map { Grey } frequency 6 translate <0.5, -0.5, 0> })
Tile(3, 2, pigment { waves color_map { Grey } frequency 6 translate <0.5, -0.5, 0> })
Tile(4, 2, pigment { quilted color_map { Grey } scale 0.25 })
Tile(5, 2, pigment { spiral1 3 color_map { Grey } scale 0.3 translate <0.5, -0.5, 0> })
Tile(6, 2, pigment { spiral2 3 color_map { Grey } scale 0.3 translate <0.5, -0.5, 0> })
Tile(7, 2, pigment { mandel 40 color_map { Grey } scale 0.4 translate <0.75, -0.5, 0> })
// Row 4: fractals, block patterns, patterned textures.
Tile(0, 3, pigment { julia <0.353, 0.288>, 40 color_map { Grey } scale 0.35 translate <0.5, -0.5, 0> })
Tile(1, 3, pigment { checker rgb <0.9, 0.3, 0.2>, rgb 0.9 scale 0.2 })
Tile(2, 3, pigment { hexagon rgb <0.2, 0.4, 0.8>, rgb 0.9, rgb <0.9, 0.7, 0.2> rotate x*90 scale 0.12 })
Tile(3, 3, pigment { brick rgb 0.8, rgb <0.6, 0.2, 0.15> scale 0.02 rotate x*90 })
Tile(4, 3, pigment { crackle solid color_map { Grey } scale 0.2 })
Tile(5, 3, pigment { crackle metric 1 color_map { Grey } scale 0.2 })
Tile(6, 3, pigment { crackle form <1, 0, 0> color_map { Grey } scale 0.2 })
box { <0.06, -0.94, 0>, <0.94, -0.06, 0.2>
  texture { gradient x texture_map {
      [0.3 pigment { rgb <0.8, 0.2, 0.1> } finish { ambient 0.15 }]
      [0.7 pigment { rgb <0.1, 0.3, 0.8> } finish { ambient 0.15 specular 0.6 }] } scale 0.5 }
  translate <7, -3, 0> }
// Row 5: normals.
BumpTile(0, 4, normal { bumps 0.6 scale 0.08 })
BumpTile(1, 4, normal { dents 1 scale 0.08 })
BumpTile(2, 4, normal { wrinkles 0.8 scale 0.2 })
BumpTile(3, 4, normal { ripples 0.6 frequency 8 translate <0.5, -0.5, 0> })
BumpTile(4, 4, normal { waves 0.6 frequency 8 translate <0.5, -0.5, 0> })
BumpTile(5, 4, normal { quilted 1 scale 0.2 })
BumpTile(6, 4, normal { crackle 1 scale 0.2 })
BumpTile(7, 4, normal { gradient x 1 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } scale 0.25 })
