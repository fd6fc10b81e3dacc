// Blob with sphere and cylinder components, one negative, threshold 0.5.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.3, 0> right x*4/3 }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-4, 6, -6> color rgb 1 }
light_source { <5, 2, -3> color rgb 0.4 }
blob {
  threshold 0.5
  sphere { <-0.8, 0.3, 0>, 1.1, 1 }
  sphere { <0.7, 0.4, 0>, 1.0, 1 }
  sphere { <0.2, 1.0, -0.3>, 0.6, -1 }
  cylinder { <-1.2, -0.4, 0>, <1.2, -0.4, 0>, 0.5, 1 }
  pigment { color rgb <0.3, 0.6, 0.9> }
  finish { phong 0.8 phong_size 60 }
}
