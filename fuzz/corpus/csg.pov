#version 3.7;
camera { location <0,1,-4> look_at 0 }
light_source { <5,5,-5> rgb 1 }
#declare Part = difference { box { -1, 1 } sphere { 0, 1.3 } rotate <0, 30, 0> }
union { object { Part } intersection { cylinder { -y, y, 0.5 } cone { -y, 1, y, 0 } } merge { torus { 1, 0.2 } }
  clipped_by { plane { y, 0.5 } } pigment { checker rgb 1, rgb <1,0,0> scale 0.2 } }
