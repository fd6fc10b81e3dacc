// 10,000 small spheres on a 100 x 100 grid: what a bounding hierarchy saves (`snell explain --heatmap cost`
// with --accel none and --accel bvh; docs/explain.md).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 14, -16> look_at <0, 0, 2> }
light_source { <10, 30, -20> color rgb 1 }
#for (I, 0, 99)
  #for (J, 0, 99)
    sphere { <(I - 49.5) * 0.3, 0, (J - 49.5) * 0.3>, 0.12
      pigment { rgb <0.3 + 0.7 * I / 99, 0.4, 1 - 0.7 * J / 99> } }
  #end
#end
background { rgb <0.05, 0.05, 0.1> }
