mesh {
  triangle { <0,0,0>, <1,0,0>, <0,1,0> }
  smooth_triangle { <0,0,0>, y, <1,0,0>, y, <0,0,1>, y }
  inside_vector y
  pigment { rgb 1 }
}
blob { threshold 0.5 sphere { 0, 1, 1 } cylinder { -x, x, 0.5, 1 } }
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
