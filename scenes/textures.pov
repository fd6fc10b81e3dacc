// snell texture gallery: every pattern on a labelled grid of tiles, pigments and patterned textures in the
// top rows, normals (on a plain white tile) in the bottom rows. Each label is a `text {}` under its tile.
// Render: snell render scenes/textures.pov -o textures.png -w 660 -h 678 --aa 0.3
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare Columns = 9;
#declare Rows = 9;
#declare RowHeight = 1.2;
camera {
  orthographic
  location <Columns / 2, -Rows * RowHeight / 2, -10>
  look_at  <Columns / 2, -Rows * RowHeight / 2, 0>
  right    x * Columns
  up       y * Rows * RowHeight
}

light_source { <-10, 15, -20> color rgb 1.1 }
light_source { <20, -5, -10> color rgb 0.35 shadowless }
background { color rgb 0.12 }

#declare Grey = color_map { [0 rgb <0.1, 0.1, 0.15>] [1 rgb <0.95, 0.9, 0.8>] }
// A tile's square covers [0.06, 0.94] in x and [-0.94, -0.06] in y before it moves to its cell; the label
// sits in the strip below it.
#macro Place(Column, Row) translate <Column, -Row * RowHeight, 0> #end
#macro Label(Column, Row, Name)
  text { ttf "timrom.ttf" Name 0.02, 0
    pigment { rgb 0.9 } finish { ambient 1 diffuse 0 }
    scale 0.135 translate <0.07, -1.08, 0> Place(Column, Row) }
#end
#macro TextureTile(Column, Row, Name, Tex)
  box { <0.06, -0.94, 0>, <0.94, -0.06, 0.2> texture { Tex } Place(Column, Row) }
  Label(Column, Row, Name)
#end
#macro Tile(Column, Row, Name, Pig)
  TextureTile(Column, Row, Name, texture { pigment { Pig } finish { ambient 0.15 diffuse 0.8 } })
#end
#macro BumpTile(Column, Row, Name, Nor)
  TextureTile(Column, Row, Name, texture { pigment { rgb <0.9, 0.88, 0.85> } normal { Nor }
    finish { ambient 0.1 diffuse 0.8 specular 0.4 roughness 0.02 } })
#end
#declare Centre = <0.5, -0.5, 0>;

// Row 1: geometric patterns.
Tile(0, 0, "gradient", pigment { gradient x color_map { Grey } scale 0.5 })
Tile(1, 0, "onion", pigment { onion color_map { Grey } scale 0.3 translate Centre })
Tile(2, 0, "spherical", pigment { spherical color_map { Grey } scale 0.45 translate Centre })
Tile(3, 0, "cylindrical", pigment { cylindrical color_map { Grey } rotate x*90 scale 0.45 translate Centre })
Tile(4, 0, "planar", pigment { planar color_map { Grey } scale 0.45 translate <0, -0.5, 0> })
Tile(5, 0, "boxed", pigment { boxed color_map { Grey } scale 0.45 translate Centre })
Tile(6, 0, "radial", pigment { radial frequency 6 color_map { Grey } rotate x*90 translate Centre })
Tile(7, 0, "leopard", pigment { leopard color_map { Grey } scale 0.06 })
Tile(8, 0, "spiral1", pigment { spiral1 3 color_map { Grey } scale 0.3 translate Centre })
// Row 2: noise patterns.
Tile(0, 1, "bozo", pigment { bozo color_map { Grey } scale 0.15 })
Tile(1, 1, "granite", pigment { granite color_map { Grey } scale 0.8 })
Tile(2, 1, "marble", pigment { marble turbulence 0.8 color_map { Grey } scale 0.4 })
Tile(3, 1, "wood", pigment { wood turbulence 0.1 rotate x*90 scale 0.08 translate Centre })
Tile(4, 1, "agate", pigment { agate scale 0.5 })
Tile(5, 1, "wrinkles", pigment { wrinkles color_map { Grey } scale 0.3 })
Tile(6, 1, "bumps", pigment { bumps color_map { Grey } scale 0.15 })
Tile(7, 1, "dents", pigment { dents color_map { Grey } scale 0.15 })
Tile(8, 1, "spiral2", pigment { spiral2 3 color_map { Grey } scale 0.3 translate Centre })
// Row 3: noise generators, cellular patterns.
Tile(0, 2, "noise_gen 1", pigment { bozo noise_generator 1 color_map { Grey } scale 0.15 })
Tile(1, 2, "noise_gen 3", pigment { bozo noise_generator 3 color_map { Grey } scale 0.15 })
Tile(2, 2, "crackle", pigment { crackle color_map { Grey } scale 0.2 })
Tile(3, 2, "crackle solid", pigment { crackle solid color_map { Grey } scale 0.2 })
Tile(4, 2, "metric 1", pigment { crackle metric 1 color_map { Grey } scale 0.2 })
Tile(5, 2, "form <1,0,0>", pigment { crackle form <1, 0, 0> color_map { Grey } scale 0.2 })
Tile(6, 2, "cells", pigment { cells color_map { Grey } scale 0.15 })
Tile(7, 2, "ripples", pigment { ripples color_map { Grey } frequency 6 translate Centre })
Tile(8, 2, "waves", pigment { waves color_map { Grey } frequency 6 translate Centre })
// Row 4: fractals, functions and made-of-pigments patterns.
Tile(0, 3, "quilted", pigment { quilted color_map { Grey } scale 0.25 })
Tile(1, 3, "mandel", pigment { mandel 40 color_map { Grey } scale 0.4 translate <0.75, -0.5, 0> })
Tile(2, 3, "julia", pigment { julia <0.353, 0.288>, 40 color_map { Grey } scale 0.35 translate Centre })
Tile(3, 3, "function", pigment { function { abs(sin(8 * x) * cos(8 * y)) } color_map { Grey } })
Tile(4, 3, "pigment_pattern", pigment { pigment_pattern { checker rgb 0.2, rgb 0.9 scale 0.25 }
  turbulence 0.3 color_map { Grey } })
Tile(5, 3, "image_pattern", pigment { image_pattern { png "povmap.png" } color_map { Grey } scale 0.88
  translate <0.06, -0.94, 0> })
Tile(6, 3, "average", pigment { average pigment_map { [1 gradient x color_map { Grey } scale 0.3]
  [1 gradient y color_map { Grey } scale 0.3] } })
Tile(7, 3, "object", pigment { object { sphere { Centre, 0.3 } rgb 0.2, rgb <0.9, 0.5, 0.2> } })
Tile(8, 3, "warp black_hole", pigment { checker rgb 0.2, rgb 0.9 scale 0.12
  warp { black_hole Centre, 0.4 strength 2 } })
// Row 5: block patterns.
Tile(0, 4, "checker", pigment { checker rgb <0.9, 0.3, 0.2>, rgb 0.9 scale 0.2 })
Tile(1, 4, "hexagon", pigment { hexagon rgb <0.2, 0.4, 0.8>, rgb 0.9, rgb <0.9, 0.7, 0.2> rotate x*90 scale 0.12 })
Tile(2, 4, "brick", pigment { brick rgb 0.8, rgb <0.6, 0.2, 0.15> scale 0.02 rotate x*90 })
Tile(3, 4, "square", pigment { square scale 0.2 rotate x*90 })
Tile(4, 4, "triangular", pigment { triangular scale 0.2 rotate x*90 })
Tile(5, 4, "cubic", pigment { cubic rotate <30, 40, 0> translate Centre })
Tile(6, 4, "slope", pigment { slope y color_map { Grey } })
// Row 6: patterned textures.
TextureTile(7, 4, "texture_map", texture { gradient x texture_map {
  [0.3 pigment { rgb <0.8, 0.2, 0.1> } finish { ambient 0.15 }]
  [0.7 pigment { rgb <0.1, 0.3, 0.8> } finish { ambient 0.15 specular 0.6 }] } scale 0.5 })
TextureTile(8, 4, "material_map", texture { material_map { png "povmap.png"
  texture { pigment { rgb <0.9, 0.8, 0.2> } finish { ambient 0.15 } }
  texture { pigment { rgb <0.2, 0.3, 0.8> } finish { ambient 0.15 } }
  texture { pigment { rgb <0.9, 0.2, 0.2> } finish { ambient 0.15 } }
  texture { pigment { rgb 0.9 } finish { ambient 0.15 } } } scale 0.88 translate <0.06, -0.94, 0> })
// Rows 6 and 7: normals.
BumpTile(0, 5, "bumps", normal { bumps 0.6 scale 0.08 })
BumpTile(1, 5, "dents", normal { dents 1 scale 0.08 })
BumpTile(2, 5, "wrinkles", normal { wrinkles 0.8 scale 0.2 })
BumpTile(3, 5, "ripples", normal { ripples 0.6 frequency 8 translate Centre })
BumpTile(4, 5, "waves", normal { waves 0.6 frequency 8 translate Centre })
BumpTile(5, 5, "quilted", normal { quilted 1 scale 0.2 })
BumpTile(6, 5, "crackle", normal { crackle 1 scale 0.2 })
BumpTile(7, 5, "slope_map", normal { gradient x 1 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } scale 0.25 })
BumpTile(8, 5, "granite", normal { granite 0.4 scale 0.8 })
BumpTile(0, 6, "leopard", normal { leopard 1 scale 0.06 })
BumpTile(1, 6, "onion", normal { onion 0.8 scale 0.15 translate Centre })
BumpTile(2, 6, "spiral1", normal { spiral1 3 0.8 scale 0.3 translate Centre })
BumpTile(3, 6, "average", normal { average normal_map { [1 gradient x 1 scale 0.2] [1 gradient y 1 scale 0.2] } })
BumpTile(4, 6, "marble", normal { marble 0.8 turbulence 0.5 scale 0.3 })
BumpTile(5, 6, "agate", normal { agate 0.6 scale 0.5 })
BumpTile(6, 6, "bozo", normal { bozo 0.8 scale 0.15 })
BumpTile(7, 6, "cells", normal { cells 0.5 scale 0.15 })
BumpTile(8, 6, "mandel", normal { mandel 40 0.5 scale 0.4 translate <0.75, -0.5, 0> })
// Row 8: fractal variants, potential, average of textures, facets and bump_map.
Tile(0, 7, "magnet 1", pigment { magnet 1 mandel 30 color_map { Grey } scale 0.3 translate <0.2, -0.5, 0> })
Tile(1, 7, "magnet 2 julia", pigment { magnet 2 julia <1.2, -0.3>, 30 interior 1, 0.2 color_map { Grey }
  scale 0.3 translate <0.1, -0.5, 0> })
Tile(2, 7, "mandel exp 3", pigment { mandel 40 exponent 3 color_map { Grey } scale 0.35 translate Centre })
Tile(3, 7, "julia exp 4", pigment { julia <0.6, 0.3>, 40 exponent 4 color_map { Grey } scale 0.35
  translate Centre })
Tile(4, 7, "potential", pigment { potential { blob { threshold 0.5 sphere { <-0.2, 0, 0>, 0.45, 1 }
  sphere { <0.2, 0.1, 0>, 0.4, 1 } } } color_map { Grey } translate Centre })
TextureTile(5, 7, "avg texture", texture { average texture_map {
  [1 pigment { gradient x color_map { Grey } scale 0.3 } finish { ambient 0.15 }]
  [1 pigment { rgb <0.8, 0.3, 0.1> } normal { bumps 0.8 scale 0.05 } finish { ambient 0.15 }] } })
BumpTile(6, 7, "facets coords", normal { facets coords 0.6 size 0.08 })
// facets without coords snaps the normal itself, so it shows on a curved surface.
sphere { Centre, 0.42 texture { pigment { rgb <0.9, 0.88, 0.85> } normal { facets size 0.15 }
  finish { ambient 0.1 diffuse 0.8 specular 0.4 roughness 0.02 } } Place(7, 7) }
Label(7, 7, "facets")
BumpTile(8, 7, "bump_map", normal { bump_map { png "povmap.png" bump_size 3 } scale 0.88 translate <0.06, -0.94, 0> })
// Row 9: the angle of incidence, tilings 1-5 and an average of textures with different finishes.
// aoi: 1 where the (orthographic) rays meet the sphere head-on, 0.5 at its rim.
sphere { Centre, 0.42 texture { pigment { aoi color_map { [0.5 rgb <0.1, 0.1, 0.15>] [1 rgb <0.95, 0.9, 0.8>] } }
  finish { ambient 0.6 diffuse 0.4 } } Place(0, 8) }
Label(0, 8, "aoi")
// Tilings lie in the x-z plane: turned to face the camera. Light caulk on each tile's outline.
#declare Caulked = color_map { [0 rgb <0.15, 0.2, 0.45>] [0.8 rgb <0.5, 0.6, 0.9>] [0.9 rgb 0.95] [1 rgb 0.95] }
#declare Caulked2 = color_map { [0 rgb <0.15, 0.2, 0.45>] [0.4 rgb <0.5, 0.6, 0.9>] [0.45 rgb 0.95]
  [0.5 rgb 0.95] [0.5 rgb <0.45, 0.15, 0.1>] [0.9 rgb <0.9, 0.5, 0.4>] [0.95 rgb 0.95] [1 rgb 0.95] }
Tile(1, 8, "tiling 1", pigment { tiling 1 color_map { Caulked } rotate x*90 scale 0.22 })
Tile(2, 8, "tiling 2", pigment { tiling 2 color_map { Caulked } rotate x*90 scale 0.15 })
Tile(3, 8, "tiling 3", pigment { tiling 3 color_map { Caulked2 } rotate x*90 scale 0.25 })
Tile(4, 8, "tiling 4", pigment { tiling 4 color_map { Caulked } rotate x*90 scale 0.25 })
#declare Caulked3 = color_map { [0 rgb <0.15, 0.2, 0.45>] [0.3 rgb <0.5, 0.6, 0.9>] [0.333 rgb 0.95]
  [0.333 rgb <0.45, 0.15, 0.1>] [0.633 rgb <0.9, 0.5, 0.4>] [0.666 rgb 0.95]
  [0.666 rgb <0.1, 0.35, 0.15>] [0.966 rgb <0.5, 0.85, 0.5>] [1 rgb 0.95] }
Tile(5, 8, "tiling 5", pigment { tiling 5 color_map { Caulked3 } rotate x*90 scale 0.2 })
// Each entry lit with its own finish, then averaged: a matte gradient and a shiny, bumpy red.
TextureTile(6, 8, "avg finishes", texture { average texture_map {
  [1 pigment { gradient x color_map { Grey } scale 0.3 } finish { ambient 0.15 diffuse 0.8 }]
  [1 pigment { rgb <0.8, 0.1, 0.05> } normal { bumps 0.5 scale 0.08 }
     finish { ambient 0.05 diffuse 0.4 phong 1 phong_size 60 }] } })
