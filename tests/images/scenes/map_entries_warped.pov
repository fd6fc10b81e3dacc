// Map entries evaluated where the outer pattern's warps take the point, as POV-Ray does (pigment.cpp
// Compute_Pigment, normal.cpp Perturb_Normal, trace.cpp ComputeOneTextureColour): a pigment_map, a
// normal_map, a block normal and a texture_map, each under an outer turbulence warp and scale.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,-5,4> look_at <0,0,0> angle 50 }
light_source { <-5, -3, 8> rgb 1 }
#declare F = finish { ambient 0.1 diffuse 0.8 specular 0.3 }
box { <-3,-2,-1>, <0,0,0>
  pigment { crackle pigment_map { [0.03 rgb 0] [0.055 granite color_map { [0 rgb 0.2] [1 rgb 1] } ] }
            warp { turbulence 0.55 } scale 0.4 } finish { F } }
box { <0,-2,-1>, <3,0,0> pigment { rgb 0.8 } finish { F }
  normal { gradient x normal_map { [0 bumps 0.5 scale 0.1] [1 granite 0.6] } warp { turbulence 0.5 } scale 0.7 } }
box { <-3,0,-1>, <0,2,0> pigment { rgb 0.8 } finish { F }
  normal { checker normal { bumps 0.5 scale 0.1 } normal { granite 0.6 } warp { turbulence 0.5 } scale 0.7 } }
box { <0,0,-1>, <3,2,0>
  texture { gradient x texture_map {
    [0 pigment { granite color_map { [0 rgb 0] [1 rgb 1] } scale 0.2 } finish { F }]
    [1 pigment { bozo color_map { [0 rgb 0] [1 rgb <1,0,0>] } scale 0.3 } finish { F }] }
    warp { turbulence 0.5 } scale 0.7 } }
