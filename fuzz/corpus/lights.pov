global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { orthographic location <0, 5, -5> look_at 0 right x * image_width / image_height angle 40 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.5, 0.6, 1>] [1 rgb 1] } } }
light_source { <0, 10, 0> rgb 1 spotlight point_at 0 radius 10 falloff 20 tightness 5 }
light_source { <3, 10, 0> rgb 1 area_light x, z, 3, 3 adaptive 1 jitter }
light_source { <0, 10, 3> rgb 0.5 parallel point_at 0 shadowless fade_distance 5 fade_power 2 }
disc { 0, y, 2 pigment { rgb 1 } no_shadow }
